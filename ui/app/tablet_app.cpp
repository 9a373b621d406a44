#include "ui/app/tablet_app.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cstdlib>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "ui/app/screens.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"

namespace rockface::ui {

namespace {
// The task that loads the visit's 3D image for display: said on the Model
// screen only.
constexpr const char* kLoadingTitle = "Loading the 3D image";
}  // namespace

const char* screen_name(Screen screen) {
  switch (screen) {
    case Screen::project:
      return "Project";
    case Screen::capture:
      return "Capture";
    case Screen::model:
      return "Model";
    case Screen::mapping:
      return "Mapping";
    case Screen::blocks:
      return "Blocks";
  }
  return "?";
}

void AppState::say(std::string text) {
  statuses.say(static_cast<std::size_t>(screen), std::move(text));
}

void AppState::fail(std::string text) {
  statuses.error(static_cast<std::size_t>(screen), std::move(text));
}

void AppState::open_project(const std::filesystem::path& file) {
  try {
    session = ProjectSession::open(file);
    model_view.clear();
    model_load_failed.reset();
    blocks.selected_block.reset();
    mapping = {};
    // The pole is the project's: its length as typed for the last pair.
    if (const auto pole = session->store().latest_capture_setting("range_pole_m")) {
      char* end = nullptr;
      const float v = std::strtof(pole->c_str(), &end);
      if (end != pole->c_str() && v > 0 && v <= 50) capture.range_pole_m = v;
    }
    // The file's name only: its folders are the machine's business.
    std::string text = "Opened " + format::file_name(file.string());
    if (session->read_only()) text += " (read-only: " + session->read_only_reason() + ")";
    say(text);
  } catch (const std::exception& e) {
    fail(e.what());
  }
}

TabletApp::TabletApp(UiOptions options, FieldServices services) {
  state_.options = std::move(options);
  state_.services = services;
  state_.targets.set_scale(state_.options.scale);
  state_.targets.set_dpi(state_.options.dpi > 0 ? state_.options.dpi
                                                : kScaleOneDpi * state_.options.scale);
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; nothing to remember
  io.ConfigFlags |= ImGuiConfigFlags_IsTouchScreen;
  try {
    state_.settings = load_ui_settings(state_.options.settings_file);
  } catch (const std::exception& e) {
    state_.statuses.error(static_cast<std::size_t>(Screen::project), e.what());
  }
  apply_theme(state_.settings.theme, state_.options.scale, state_.targets.target_px());
  ImGui_ImplOpenGL3_Init("#version 300 es");
  if (!state_.options.project.empty()) {
    state_.open_project(state_.options.project);
    if (state_.session) state_.screen = Screen::model;
  }
}

TabletApp::~TabletApp() {
  // Pairs waiting for their 3D image are stored before the app goes (each
  // job stores its pair before its first step); their 3D images are not made.
  state_.reconstructions.cancel();
  while (state_.reconstructions.busy()) {
    state_.reconstructions.wait();
    state_.reconstructions.poll();
  }
  state_.task.cancel();
  state_.task.wait();
  state_.model_view = ModelView();  // GL objects go while the context is current
  if (state_.capture.live_view_texture) glDeleteTextures(1, &state_.capture.live_view_texture);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void TabletApp::build_frame(TouchInput& input, int width, int height, float seconds_since_last) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = seconds_since_last > 0 ? seconds_since_last : 1.0f / 60;
  input.apply(io);
  state_.gesture = input.gesture();
  if (state_.theme_wanted) {
    // A new font atlas and its GL texture, between two frames.
    apply_theme(*state_.theme_wanted, state_.options.scale, state_.targets.target_px());
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    state_.theme_wanted.reset();
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  build();
  ImGui::Render();
}

bool TabletApp::draw() {
  const ImDrawData& data = *ImGui::GetDrawData();
  if (drawn_.same_as_last(data)) return false;
  drawn_.remember(data);
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  glViewport(0, 0, static_cast<int>(size.x), static_cast<int>(size.y));
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  glClearColor(bg.x, bg.y, bg.z, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return true;
}

void TabletApp::keep_model_loaded() {
  // A pair's 3D image made on the queue: said on the Capture screen, where
  // the pair was stored (its `then` has refreshed the project already, so
  // the newest model is loaded below).
  if (const auto outcome = state_.reconstructions.poll()) {
    const auto where = static_cast<std::size_t>(Screen::capture);
    const std::string text = outcome->title + ": " + outcome->message;
    if (outcome->kind == TaskOutcome::Kind::failed)
      state_.statuses.error(where, text);
    else
      state_.statuses.say(where, text);
  }
  // Take what the worker finished (runs its `then` here, on the UI thread).
  if (const auto outcome = state_.task.take_outcome()) {
    const auto where = static_cast<std::size_t>(state_.task_screen);
    const std::string text = outcome->title + ": " + outcome->message;
    if (outcome->kind == TaskOutcome::Kind::failed)
      state_.statuses.error(where, text);
    else if (outcome->title != kLoadingTitle || where == static_cast<std::size_t>(Screen::model))
      state_.statuses.say(where, text);
  }
  if (state_.session)
    if (auto problem = state_.session->take_file_problem())
      state_.statuses.error(static_cast<std::size_t>(Screen::project), std::move(*problem));
  if (!state_.session || state_.task.running()) return;
  const auto& wanted = state_.session->model();
  if (!wanted || wanted->id == state_.model_view.model_id()) return;
  if (state_.model_load_failed == wanted->id) return;
  const auto file = state_.session->file();
  const auto id = wanted->id;
  const std::size_t budget = state_.options.max_display_triangles;
  auto prepared = std::make_shared<PreparedModel>();
  state_.task.start(
      kLoadingTitle,
      [file, id, budget, prepared](Progress& progress) {
        progress.step("reading the model", 0.1);
        *prepared = prepare_model(file, id, budget);
        return "3D image " + std::to_string(id) + " loaded";
      },
      [this, prepared, id](const TaskOutcome& outcome) {
        if (outcome.kind == TaskOutcome::Kind::done)
          state_.model_view.install(std::move(*prepared));
        else if (outcome.kind == TaskOutcome::Kind::failed)
          state_.model_load_failed = id;
      });
  // The model is the Model screen's business, whichever screen is open.
  state_.task_screen = Screen::model;
  state_.tasks_noted = state_.task.started();
}

void TabletApp::build() {
  state_.targets.begin_frame();
  clear_drawn_text();
  keep_model_loaded();
  // Messages about another visit would mislead: they go with it.
  const auto visit = state_.session ? state_.session->visit() : std::nullopt;
  if (visit != state_.status_visit) {
    if (state_.status_visit) state_.statuses.clear_messages();
    state_.status_visit = visit;
  }
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->Pos);
  ImGui::SetNextWindowSize(viewport->Size);
  ImGui::Begin("rockface", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  draw_tabs();
  float status_height = state_.targets.target_px() + 2 * ImGui::GetStyle().ItemSpacing.y;
  if (state_.session && state_.session->read_only())
    status_height += ImGui::GetTextLineHeightWithSpacing();
  ImGui::BeginChild("screen", ImVec2(0, -status_height));
  switch (state_.screen) {
    case Screen::project:
      draw_project_screen(state_);
      break;
    case Screen::capture:
      draw_capture_screen(state_);
      break;
    case Screen::model:
      draw_model_screen(state_);
      break;
    case Screen::mapping:
      draw_mapping_screen(state_);
      break;
    case Screen::blocks:
      draw_blocks_screen(state_);
      break;
  }
  ImGui::EndChild();
  // A task started while drawing this screen: its outcome is said here.
  if (state_.task.started() != state_.tasks_noted) {
    state_.tasks_noted = state_.task.started();
    state_.task_screen = state_.screen;
  }
  draw_status_bar();
  ImGui::End();
}

void TabletApp::draw_tabs() {
  const ImGuiStyle& style = ImGui::GetStyle();
  // Five tabs share the width (portrait too), each at least a touch target.
  const float room = ImGui::GetContentRegionAvail().x;
  const float tab =
      std::max(state_.targets.target_px(),
               std::min(150 * state_.options.scale, (room - 4 * style.ItemSpacing.x) / 5));
  bool first = true;
  for (Screen s :
       {Screen::project, Screen::capture, Screen::model, Screen::mapping, Screen::blocks}) {
    if (!first) same_line_if_fits(tab);
    first = false;
    if (toggle_button(state_.targets, screen_name(s), s == state_.screen, true, tab))
      state_.screen = s;
  }
  // The project's name at the right of the tabs (below them when they fill
  // the line): shortened to its place, the whole name one tap away.
  if (state_.session) {
    const std::string name = state_.session->info().name;
    const float wanted = std::min(ImGui::CalcTextSize(name.c_str()).x, 12 * ImGui::GetFontSize());
    same_line_if_fits(wanted);
    label_in_row(name);
  }
  ImGui::Separator();
}

void TabletApp::draw_status_bar() {
  ImGui::Separator();
  const float s = state_.options.scale;
  if (state_.session && state_.session->read_only()) {
    const ImVec2 at = ImGui::GetCursorScreenPos();
    label("Read-only: " + state_.session->read_only_reason(), warning_colour());
    state_.targets.record_area("read-only notice", at, ImGui::GetItemRectMax());
  }
  const auto here = static_cast<std::size_t>(state_.screen);
  const auto& errors = state_.statuses.errors(here);
  if (!errors.empty()) {
    // The line is composed before "OK" is drawn: a tap on it empties
    // `errors`, and reading its back() after that was the crash of issue 42
    // (std::bad_alloc or a segmentation fault on the tap that dismissed a
    // camera's refusal).
    std::string text = errors.back();
    if (errors.size() > 1)
      text =
          format::count(static_cast<std::int64_t>(errors.size()), "error", "errors") + ": " + text;
    // An error stays until read: "OK" (a touch target) puts it away.
    if (state_.targets.button("OK##errors")) state_.statuses.dismiss(here);
    ImGui::SameLine();
    label_in_row(text, warning_colour());  // shortened: the whole one tap away
    return;
  }
  const TaskStatus status = state_.task.status();
  if (status.running) {
    if (state_.targets.button("Cancel", 160 * s, !status.cancelling)) state_.task.cancel();
    ImGui::SameLine();
    std::string text = status.title + ": " + status.stage + " (" +
                       format::text(format::Fraction{status.fraction}) + ", " +
                       format::text(format::Duration{status.seconds}) + ")";
    if (status.cancelling) text += ", cancelling";
    progress_bar(static_cast<float>(status.fraction), text, state_.targets.target_px());
  } else {
    label_in_row(state_.statuses.message(here));
  }
}

}  // namespace rockface::ui
