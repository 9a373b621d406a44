// Project: open or create a .rockface project, list its visits, resume the
// last one or start a new one; a read-only project says why. The look
// (daylight or tunnel) is chosen here and remembered per tablet.
#include <algorithm>
#include <filesystem>

#include <imgui.h>

#include "ui/app/export_to_stick.h"
#include "ui/app/screens.h"
#include "ui/project/geologist_entry.h"
#include "ui/project/import_picker.h"
#include "ui/project/office_panel.h"
#include "ui/project/tunnel_panel.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"
#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> projects_in(const fs::path& folder) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().extension() == ".rockface") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void draw_theme_choice(AppState& app) {
  label_in_row("Screen:");
  for (const Theme t : {Theme::daylight, Theme::tunnel}) {
    const bool on = app.settings.theme == t;
    const std::string name = t == Theme::daylight ? "Daylight" : "Tunnel (dark)";
    if (toggle_button_in_row(app.targets, name, on) && !on) {
      app.settings.theme = t;
      app.theme_wanted = t;
      try {
        save_ui_settings(app.options.settings_file, app.settings);
      } catch (const std::exception& e) {
        app.fail(e.what());
      }
    }
  }
  if (app.options.settings_file.empty())
    note("Not remembered: this tablet has no settings folder.");
}

void draw_chooser(AppState& app) {
  heading("Open a project");
  for (const auto& file : projects_in(app.options.projects_folder))
    if (app.targets.button_in_row("Open " + file.stem().string(), !app.task.running()))
      app.open_project(file);
  ImGui::Separator();
  heading("New project");
  ImGui::SetNextItemWidth(std::min(320 * app.targets.scale(), ImGui::GetContentRegionAvail().x));
  text_field(app.targets, "project name", &app.project.new_project_name);
  if (app.targets.button_in_row("Create", !app.project.new_project_name.empty())) {
    const fs::path file =
        app.options.projects_folder / (app.project.new_project_name + ".rockface");
    try {
      app.session = ProjectSession::create(file, app.project.new_project_name);
      app.session->begin_visit(app.settings.geologist);
      app.say("Created " + file.filename().string() + " with its first visit");
    } catch (const std::exception& e) {
      app.fail(e.what());
    }
  }
}

std::string visit_line(const storage::Visit& v, bool current) {
  std::string text = (current ? "▸ " : "") + std::string("Visit ") + std::to_string(v.id) + ", " +
                     format::date_time(v.started_at);
  const std::string source = format::without_folders(v.source);
  if (!source.empty()) text += ", " + source;
  return text;
}

void draw_visit(const ProjectSession& s) {
  heading("This visit");
  const std::int64_t traces =
      std::count_if(s.measurements().begin(), s.measurements().end(),
                    [](const auto& m) { return m.kind == storage::Measurement::Kind::trace; });
  paragraph(
      format::count(static_cast<std::int64_t>(s.pairs().size()), "stereo pair", "stereo pairs") +
      ", " + format::count(static_cast<std::int64_t>(s.captures().size()), "capture", "captures") +
      ", " + format::count(traces, "trace", "traces") + ", " +
      format::count(static_cast<std::int64_t>(s.joints().size()), "joint", "joints") + ".");
  if (s.analysis())
    paragraph("Analysed: " +
              format::count(static_cast<std::int64_t>(s.blocks().size()), "block", "blocks") +
              " (" + format::date_time(s.analysis()->created_at) + ").");
  else
    paragraph("Not analysed yet (Blocks).");
  // The session falls back to an earlier visit's model for the screens;
  // this line is about this visit's own pairs.
  if (s.model() && !s.pairs().empty())
    paragraph("3D image: " + format::count(s.model()->vertex_count, "point", "points") + ", " +
              format::count(s.model()->face_count, "triangle", "triangles") + ", " +
              format::registered_by(s.model()->registration_kind) + ".");
  else
    paragraph("No 3D image of this visit yet (Capture).");
}

// The project, its visits and the visit chosen; true when it was closed.
bool draw_project(AppState& app, ProjectSession& s) {
  heading(s.info().name);
  // The file's name, never its folder: a machine's path means nothing at
  // the face and must not end up in screenshots.
  note("File " + s.file().filename().string() +
       (s.info().created_at.empty() ? "" : ", created " + format::date_time(s.info().created_at)));
  if (s.read_only())
    paragraph("Read-only: " + s.read_only_reason() + ". Nothing can be added to this project.",
              warning_colour());
  const bool idle = !app.task.running();
  if (app.targets.button("Resume last visit", 0, idle && !s.visits().empty())) {
    s.choose_visit(s.visits().back().id);
    app.screen = Screen::model;
  }
  if (app.targets.button_in_row("New visit", idle && !s.read_only())) {
    s.begin_visit(app.settings.geologist);  // the tablet's geologist carried
    app.status_visit = s.visit();           // this message is about the new visit
    app.say("Visit " + std::to_string(*s.visit()) + " started: take its stereo pair (Capture).");
  }
  // Closing loses an unsaved trace's taps and unstored shots: asked then.
  const bool unsaved = !app.mapping.marker.taps().empty() ||
                       ((app.capture.left || app.capture.right) && !app.capture.stored);
  same_line_if_fits(button_width("Close project", app.targets.target_px()));
  if (unsaved
          ? app.targets.confirmed_button(
                "Close project", "A trace or shots are not saved yet. Close and lose them?", idle)
          : app.targets.button("Close project", 0, idle)) {
    app.session.reset();
    app.model_view.clear();
    app.blocks.selected_block.reset();
    app.mapping = {};
    app.capture.left.reset();
    app.capture.right.reset();
    return true;
  }
  ImGui::Separator();
  heading(format::count(static_cast<std::int64_t>(s.visits().size()), "visit", "visits"));
  ImGui::PushStyleVar(ImGuiStyleVar_ButtonTextAlign, ImVec2(0, 0.5f));
  for (auto it = s.visits().rbegin(); it != s.visits().rend(); ++it) {
    const bool current = s.visit() && *s.visit() == it->id;
    const std::string text = visit_line(*it, current);
    const std::string shown =
        shortened(text, ImGui::GetContentRegionAvail().x - 2 * ImGui::GetStyle().FramePadding.x);
    const bool tapped = app.targets.button(shown + "##visit" + std::to_string(it->id), -1, idle);
    // Scripts name a visit by its number, not by its date.
    app.targets.record("Visit " + std::to_string(it->id), ImGui::GetItemRectMin(),
                       ImGui::GetItemRectMax());
    if (tapped) {
      s.choose_visit(it->id);
      break;  // the list was re-read
    }
  }
  ImGui::PopStyleVar();
  if (s.visit()) {
    ImGui::Separator();
    draw_visit(s);
    // Issue 43: the visit's exports for the office, onto a USB stick.
    draw_export_to_stick(app);
  }
  return false;
}

}  // namespace

void draw_project_screen(AppState& app) {
  draw_theme_choice(app);
  ImGui::Separator();
  if (!app.session) {
    draw_chooser(app);
    return;
  }
  ProjectSession& s = *app.session;
  // The project and its visits; the tunnel and the office beside them
  // (below in portrait), so that a landscape tablet shows both unscrolled.
  const SplitLayout layout = split_for_side_panel(ImGui::GetContentRegionAvail().x * 0.45f, 0.45f);
  ImGui::BeginChild("project visits", layout.main);
  const bool closed = draw_project(app, s);
  ImGui::EndChild();
  if (closed) return;
  begin_side_panel("project tunnel and office", layout);
  // The visit's geologist beside the visits, not under them: under them it
  // left the visit's own line where no drag on the visits' panel brought it
  // into view (tests/ui/app/text_walk_test.cpp walks every text into view).
  if (s.visit()) draw_geologist_entry(app);
  draw_tunnel_panel(app);
  draw_office_panel(app);
  draw_import_picker(app);
  ImGui::EndChild();
}

}  // namespace rockface::ui
