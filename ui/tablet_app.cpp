#include "ui/tablet_app.h"

#include <GLES3/gl3.h>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "ui/screens/screens.h"

namespace rockface::ui {

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

void AppState::open_project(const std::filesystem::path& file) {
  try {
    session = ProjectSession::open(file);
    model_view.clear();
    selected_block.reset();
    mapping = {};
    status = "opened " + file.string();
    if (session->read_only()) status += " (read-only: " + session->read_only_reason() + ")";
  } catch (const std::exception& e) {
    status = e.what();
  }
}

TabletApp::TabletApp(UiOptions options, FieldServices services) {
  state_.options = std::move(options);
  state_.services = services;
  state_.targets.set_scale(state_.options.scale);
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; nothing to remember
  io.ConfigFlags |= ImGuiConfigFlags_IsTouchScreen;
  apply_daylight_theme(state_.options.scale);
  ImGui_ImplOpenGL3_Init("#version 300 es");
  if (!state_.options.project.empty()) {
    state_.open_project(state_.options.project);
    if (state_.session) state_.screen = Screen::model;
  }
}

TabletApp::~TabletApp() {
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
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
  build();
  ImGui::Render();
}

void TabletApp::draw() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  glViewport(0, 0, static_cast<int>(size.x), static_cast<int>(size.y));
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void TabletApp::keep_model_loaded() {
  // Take what the worker finished (runs its `then` here, on the UI thread).
  if (const auto outcome = state_.task.take_outcome()) {
    state_.status = outcome->title + ": " + outcome->message;
  }
  if (!state_.session || state_.task.running()) return;
  const auto& wanted = state_.session->model();
  if (!wanted || wanted->id == state_.model_view.model_id()) return;
  const auto file = state_.session->file();
  const auto id = wanted->id;
  const std::size_t budget = state_.options.max_display_triangles;
  auto prepared = std::make_shared<PreparedModel>();
  state_.task.start(
      "Loading model",
      [file, id, budget, prepared](Progress& progress) {
        progress.step("reading the model", 0.1);
        *prepared = prepare_model(file, id, budget);
        return "model " + std::to_string(id) + " loaded";
      },
      [this, prepared](const TaskOutcome& outcome) {
        if (outcome.kind == TaskOutcome::Kind::done)
          state_.model_view.install(std::move(*prepared));
      });
}

void TabletApp::build() {
  state_.targets.begin_frame();
  keep_model_loaded();
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->Pos);
  ImGui::SetNextWindowSize(viewport->Size);
  ImGui::Begin("rockface", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings);
  draw_tabs();
  const float status_height =
      kTouchTargetPx * state_.options.scale + 2 * ImGui::GetStyle().ItemSpacing.y;
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
  draw_status_bar();
  ImGui::End();
}

void TabletApp::draw_tabs() {
  for (Screen s :
       {Screen::project, Screen::capture, Screen::model, Screen::mapping, Screen::blocks}) {
    const bool current = s == state_.screen;
    if (current)
      ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (state_.targets.button(screen_name(s), 150 * state_.options.scale)) state_.screen = s;
    if (current) ImGui::PopStyleColor();
    ImGui::SameLine();
  }
  if (state_.session)
    ImGui::Text("%s", state_.session->info().name.c_str());
  else
    ImGui::NewLine();
  ImGui::Separator();
}

void TabletApp::draw_status_bar() {
  ImGui::Separator();
  if (state_.session && state_.session->read_only()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(200, 0, 0, 255));
    ImGui::Text("Read-only: %s", state_.session->read_only_reason().c_str());
    ImGui::PopStyleColor();
    state_.targets.record("read-only notice", ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
    ImGui::SameLine();
  }
  const TaskStatus status = state_.task.status();
  if (status.running) {
    if (state_.targets.button("Cancel", 160 * state_.options.scale, !status.cancelling))
      state_.task.cancel();
    ImGui::SameLine();
    const std::string text =
        status.title + ": " + status.stage + (status.cancelling ? " (cancelling)" : "");
    ImGui::ProgressBar(static_cast<float>(status.fraction),
                       ImVec2(-1, kTouchTargetPx * state_.options.scale), text.c_str());
  } else {
    ImGui::TextWrapped("%s", state_.status.c_str());
  }
}

}  // namespace rockface::ui
