#include "ui/tunnel_panel.h"

#include <cstdio>
#include <memory>

#include <imgui.h>

#include "ui/app_state.h"

namespace rockface::ui {

namespace {

std::string fixed(double v, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

const char* method_words(storage::VisitPlacement::Method m) {
  return m == storage::VisitPlacement::Method::ground_control
             ? "monitoring targets with survey coordinates"
             : "range pole position and compass line";
}

void reload(AppState& app) {
  TunnelState& t = app.tunnel;
  ProjectSession& s = *app.session;
  if (t.loaded && t.file == s.file() && t.visit == s.visit()) return;
  t.file = s.file();
  t.visit = s.visit();
  t.loaded = true;
  t.record.reset();
  t.placement.reset();
  t.view.clear();
  t.lines.clear();
  t.picture.clear();
  try {
    t.record = s.store().load_tunnel();
    if (t.record && s.visit()) t.placement = s.store().load_visit_placement(*s.visit());
  } catch (const std::exception& e) {
    t.lines = {std::string("The tunnel could not be read: ") + e.what()};
  }
}

void show(AppState& app, const std::string& view) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  const auto visit = app.session->visit();
  auto result = std::make_shared<TunnelPicture>();
  app.task.start(
      view == "excavation" ? "Excavation against the design" : "Sets along the drive",
      [runner, file, visit, view, result](Progress& progress) {
        *result = view == "excavation" ? runner->profile(file, *visit, progress)
                                       : runner->drive(file, progress);
        return result->lines.empty() ? std::string("done") : result->lines.front();
      },
      [&app, view, result](const TaskOutcome& outcome) {
        TunnelState& t = app.tunnel;
        if (outcome.kind != TaskOutcome::Kind::done) {
          t.view.clear();
          t.picture.clear();
          t.lines = {outcome.message};
          return;
        }
        t.view = view;
        t.lines = result->lines;
        t.picture.set(result->bgr);
      });
}

void place(AppState& app) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  const TunnelState& t = app.tunnel;
  const double chainage = t.typed_chainage, offset = t.typed_offset, height = t.typed_height;
  auto lines = std::make_shared<std::vector<std::string>>();
  app.task.start(
      "Place the visit",
      [runner, file, visit, chainage, offset, height, lines](Progress& progress) {
        *lines = runner->place(file, visit, chainage, offset, height, progress);
        return lines->empty() ? std::string("placed") : lines->front();
      },
      [&app, lines](const TaskOutcome& outcome) {
        app.tunnel.loaded = false;  // re-read the placement
        if (outcome.kind == TaskOutcome::Kind::done) {
          app.session->refresh();  // the moved 3D images are the visit's models now
          app.tunnel.lines = *lines;
        }
      });
}

// The form for a visit with no survey target in view: where the range
// pole's lower target stood.
void draw_typed_placement(AppState& app) {
  TunnelState& t = app.tunnel;
  if (t.record && !t.record->stations.empty() && t.typed_chainage == 0)
    t.typed_chainage = t.record->stations.front().chainage;
  const float w = 150 * app.targets.scale();
  ImGui::TextWrapped("Range pole's lower target (m):");
  ImGui::SetNextItemWidth(w);
  ImGui::InputDouble("chainage", &t.typed_chainage, 0.1, 1.0, "%.2f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(w);
  ImGui::InputDouble("offset right", &t.typed_offset, 0.1, 1.0, "%.2f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(w);
  ImGui::InputDouble("height above axis", &t.typed_height, 0.1, 1.0, "%.2f");
  const bool can = !app.task.running() && app.services.tunnel && !app.session->read_only() &&
                   !app.session->pairs().empty() && app.session->measurements().empty();
  if (app.targets.button("Place this visit", 0, can)) place(app);
  if (!app.session->measurements().empty())
    ImGui::TextDisabled("(placing moves the 3D image: only before mapping on it)");
}

}  // namespace

void draw_tunnel_panel(AppState& app) {
  if (!app.session) return;
  reload(app);
  TunnelState& t = app.tunnel;
  ImGui::Separator();
  if (!t.record) {
    ImGui::TextDisabled("No tunnel in this project (a replay of a scene with a tunnel adds one).");
    for (const auto& line : t.lines) ImGui::TextWrapped("%s", line.c_str());
    return;
  }
  const auto& r = *t.record;
  const std::string from = r.stations.empty() ? "?" : fixed(r.stations.front().chainage, 1);
  const std::string to = r.stations.empty() ? "?" : fixed(r.stations.back().chainage, 1);
  ImGui::TextWrapped("Tunnel %s: chainage %s to %s m, drive %s", r.name.c_str(), from.c_str(),
                     to.c_str(), tunnel::drive_name(r.drive));
  ImGui::TextWrapped("Design profile %s m around, %s m2; underbreak tolerance %s cm",
                     fixed(r.profile.perimeter(), 2).c_str(), fixed(r.profile.area(), 1).c_str(),
                     fixed(r.underbreak_tolerance_m * 100, 0).c_str());
  if (t.placement) {
    const auto& p = *t.placement;
    ImGui::TextWrapped("This visit: face at chainage %s, %s m %s of the axis; placed by %s.",
                       fixed(p.chainage, 2).c_str(), fixed(std::abs(p.offset_m), 2).c_str(),
                       p.offset_m >= 0 ? "right" : "left", method_words(p.method));
    if (p.rms_m) ImGui::TextWrapped("Target residual rms %s mm", fixed(*p.rms_m * 1000, 1).c_str());
  } else if (app.session->visit()) {
    ImGui::TextWrapped("This visit is not placed in the tunnel yet.");
    draw_typed_placement(app);
  }
  const bool idle = !app.task.running() && app.services.tunnel;
  if (app.targets.button("Excavation of this round", 0, idle && t.placement.has_value()))
    show(app, "excavation");
  ImGui::SameLine();
  if (app.targets.button("Sets along the drive", 0, idle)) show(app, "drive");
  for (const auto& line : t.lines) ImGui::TextWrapped("%s", line.c_str());
  t.picture.draw(ImGui::GetContentRegionAvail().x);
}

}  // namespace rockface::ui
