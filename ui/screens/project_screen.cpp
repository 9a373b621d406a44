// Project: open or create a .rockface project, list its visits, resume the
// last one or start a new one; a read-only project says why.
#include <algorithm>
#include <filesystem>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/office_panel.h"
#include "ui/screens/screens.h"
#include "ui/tunnel_panel.h"

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

void draw_chooser(AppState& app) {
  ImGui::TextUnformatted("Open a project");
  for (const auto& file : projects_in(app.options.projects_folder))
    if (app.targets.button("Open " + file.stem().string(), 0, !app.task.running()))
      app.open_project(file);
  ImGui::Separator();
  ImGui::TextUnformatted("New project");
  ImGui::SetNextItemWidth(320 * app.targets.scale());
  ImGui::InputText("##name", &app.new_project_name);
  ImGui::SameLine();
  if (app.targets.button("Create", 0, !app.new_project_name.empty())) {
    const fs::path file = app.options.projects_folder / (app.new_project_name + ".rockface");
    try {
      app.session = ProjectSession::create(file, app.new_project_name);
      app.session->begin_visit();
      app.status = "created " + file.string();
    } catch (const std::exception& e) {
      app.status = e.what();
    }
  }
}

}  // namespace

void draw_project_screen(AppState& app) {
  if (!app.session) {
    draw_chooser(app);
    return;
  }
  ProjectSession& s = *app.session;
  ImGui::Text("%s", s.info().name.c_str());
  ImGui::TextDisabled("%s", s.file().string().c_str());
  if (s.read_only()) {
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(200, 0, 0, 255));
    ImGui::TextWrapped("Read-only: %s. Nothing can be added to this project.",
                       s.read_only_reason().c_str());
    ImGui::PopStyleColor();
  }
  const bool idle = !app.task.running();
  if (app.targets.button("Resume last visit", 0, idle && !s.visits().empty())) {
    s.choose_visit(s.visits().back().id);
    app.screen = Screen::model;
  }
  ImGui::SameLine();
  if (app.targets.button("New visit", 0, idle && !s.read_only())) s.begin_visit();
  ImGui::SameLine();
  if (app.targets.button("Close project", 0, idle)) {
    app.session.reset();
    app.model_view.clear();
    app.selected_block.reset();
    return;
  }
  ImGui::Separator();
  ImGui::Text("Visits (%zu)", s.visits().size());
  for (auto it = s.visits().rbegin(); it != s.visits().rend(); ++it) {
    const bool current = s.visit() && *s.visit() == it->id;
    const std::string label = (current ? "> " : "  ") + std::string("Visit ") +
                              std::to_string(it->id) + "  " + it->started_at.substr(0, 16) + "  " +
                              it->source + "##visit" + std::to_string(it->id);
    if (app.targets.button(label, -1, idle)) {
      s.choose_visit(it->id);
      break;  // the list was re-read
    }
  }
  if (s.visit()) {
    ImGui::Separator();
    ImGui::Text("This visit: %zu captures, %zu measurements, %zu joints, %s", s.captures().size(),
                s.measurements().size(), s.joints().size(),
                s.analysis()
                    ? ("analysis with " + std::to_string(s.blocks().size()) + " blocks").c_str()
                    : "no analysis");
    if (s.model())
      ImGui::Text(
          "Model %lld: %lld vertices, %lld triangles, %s", static_cast<long long>(s.model()->id),
          static_cast<long long>(s.model()->vertex_count),
          static_cast<long long>(s.model()->face_count), s.model()->registration_kind.c_str());
  }
  draw_tunnel_panel(app);
  draw_office_panel(app);
}

}  // namespace rockface::ui
