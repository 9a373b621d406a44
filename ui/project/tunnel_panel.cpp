#include "ui/project/tunnel_panel.h"

#include <memory>

#include <imgui.h>

#include "core/common/number_format.h"
#include "storage/tunnel/visit_heading.h"
#include "ui/app/app_state.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

namespace {

const char* method_words(storage::VisitPlacement::Method m) {
  return m == storage::VisitPlacement::Method::ground_control
             ? "monitoring targets with survey coordinates"
             : "range pole position and compass line";
}

void reload_tunnel(AppState& app) {
  TunnelState& t = app.project.tunnel;
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
  t.drive.reset();
  t.drive_drawn = {};
  t.excavation.reset();
  t.excavation_drawn = {};
  t.picker = {};
  t.visit_heading.clear();
  try {
    t.record = s.store().load_tunnel();
    if (t.record && s.visit()) {
      t.placement = s.store().load_visit_placement(*s.visit());
      t.visit_heading = storage::load_visit_heading(s.store(), *s.visit());
    }
    t.typed_heading = t.visit_heading;
  } catch (const std::exception& e) {
    t.lines = {std::string("The tunnel could not be read: ") + e.what()};
  }
}

void show_excavation(AppState& app) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  const auto visit = app.session->visit();
  auto result = std::make_shared<ExcavationView>();
  app.task.start(
      "Excavation against the design",
      [runner, file, visit, result](Progress& progress) {
        *result = runner->profile(file, *visit, progress);
        return result->lines.empty() ? std::string("done") : result->lines.front();
      },
      [&app, result](const TaskOutcome& outcome) {
        TunnelState& t = app.project.tunnel;
        t.drive.reset();
        t.excavation.reset();
        t.excavation_drawn = {};
        t.lines.clear();
        if (outcome.kind != TaskOutcome::Kind::done) {
          t.view.clear();
          t.picture.clear();
          t.lines = {outcome.message};
          return;
        }
        t.view = "excavation";
        t.picture.set(result->cells);
        t.excavation = std::move(*result);
      });
}

void show_drive(AppState& app) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  auto result = std::make_shared<DriveJoints>();
  app.task.start(
      "Sets along the drive",
      [runner, file, result](Progress& progress) {
        *result = runner->drive(file, progress);
        return result->lines.empty() ? std::string("done") : result->lines.front();
      },
      [&app, result](const TaskOutcome& outcome) {
        TunnelState& t = app.project.tunnel;
        t.picture.clear();
        t.drive_drawn = {};
        t.excavation.reset();
        t.excavation_drawn = {};
        if (outcome.kind != TaskOutcome::Kind::done) {
          t.view.clear();
          t.drive.reset();
          t.lines = {outcome.message};
          return;
        }
        t.view = "drive";
        t.lines = result->lines;
        t.drive = std::move(*result);
      });
}

void place(AppState& app) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  const TunnelState& t = app.project.tunnel;
  const double chainage = t.typed_chainage, offset = t.typed_offset, height = t.typed_height;
  auto lines = std::make_shared<std::vector<std::string>>();
  app.task.start(
      "Place the visit",
      [runner, file, visit, chainage, offset, height, lines](Progress& progress) {
        *lines = runner->place(file, visit, chainage, offset, height, progress);
        return lines->empty() ? std::string("placed") : lines->front();
      },
      [&app, lines](const TaskOutcome& outcome) {
        app.project.tunnel.loaded = false;  // re-read the placement
        if (outcome.kind == TaskOutcome::Kind::done) {
          app.session->refresh();  // the moved 3D images are the visit's models now
          app.project.tunnel.lines = *lines;
        }
      });
}

// The face the visit was taken at, for a tunnel driven from more than one
// (issue 46): typed as the site names it ("North portal", "Bench") and kept
// on its own, placed or not (nothing moves); the office filters by it.
void name_heading(AppState& app) {
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  const std::string name = app.project.tunnel.typed_heading;
  app.task.start(
      "Name the heading",
      [file, visit, name](Progress&) {
        storage::ProjectStore store = storage::ProjectStore::open(file);
        storage::save_visit_heading(store, visit, name);
        const std::string kept = storage::load_visit_heading(store, visit);
        return kept.empty() ? std::string("no heading named") : "heading: " + kept;
      },
      [&app](const TaskOutcome&) { app.project.tunnel.loaded = false; });
}

void draw_heading_entry(AppState& app) {
  TunnelState& t = app.project.tunnel;
  paragraph("Heading (the face this visit was taken at): " +
            (t.visit_heading.empty() ? std::string("none named") : t.visit_heading));
  text_field(app.targets, "heading", &t.typed_heading);
  const bool can = !app.task.running() && !app.session->read_only() &&
                   app.session->visit().has_value() && t.typed_heading != t.visit_heading;
  if (app.targets.button_in_row("Name the heading", can)) name_heading(app);
}

// The form for a visit with no survey target in view: where the range
// pole's lower target stood.
void draw_typed_placement(AppState& app) {
  TunnelState& t = app.project.tunnel;
  if (t.record && !t.record->stations.empty() && t.typed_chainage == 0)
    t.typed_chainage = t.record->stations.front().chainage;
  const float w = std::min(220 * app.targets.scale(), ImGui::GetContentRegionAvail().x * 0.5f);
  paragraph("Where the range pole's lower target stands:");
  for (auto [name, value] : {std::pair{"Chainage (m)", &t.typed_chainage},
                             std::pair{"Offset right of the axis (m)", &t.typed_offset},
                             std::pair{"Height above the axis (m)", &t.typed_height}}) {
    number_field(app.targets, name, value, "%.2f", w, 0.1);
    ImGui::SameLine();
    label(name);
  }
  const bool can = !app.task.running() && app.services.tunnel && !app.session->read_only() &&
                   !app.session->pairs().empty() && app.session->measurements().empty();
  if (app.targets.button("Place this visit", 0, can)) place(app);
  if (!app.session->measurements().empty())
    note("(placing moves the 3D image: only before mapping on it)");
}

}  // namespace

void draw_tunnel_panel(AppState& app) {
  if (!app.session) return;
  reload_tunnel(app);
  TunnelState& t = app.project.tunnel;
  ImGui::Separator();
  if (!t.record) {
    note(
        "No tunnel in this project: give it its alignment and design profile from their files "
        "(or replay a scene with a tunnel).");
    for (const auto& line : t.lines) paragraph(line);
    if (t.picker.open) {
      draw_tunnel_files_picker(app);
      return;
    }
    const bool can = !app.task.running() && app.services.tunnel && !app.session->read_only();
    if (app.targets.button("Tunnel from files", 0, can)) open_tunnel_files_picker(app);
    return;
  }
  const auto& r = *t.record;
  const std::string from = r.stations.empty() ? "?" : format_fixed(r.stations.front().chainage, 1);
  const std::string to = r.stations.empty() ? "?" : format_fixed(r.stations.back().chainage, 1);
  heading("Tunnel " + r.name);
  paragraph("Chainage " + from + " to " + to + " m, drive " + tunnel::drive_name(r.drive));
  paragraph("Design profile " + format::text(format::Length{r.profile.perimeter()}) + " around, " +
            format::text(format::Area{r.profile.area()}) + "; underbreak tolerance " +
            format::text(format::Length{r.underbreak_tolerance_m}));
  if (t.placement) {
    const auto& p = *t.placement;
    paragraph("This visit: face at chainage " + format_fixed(p.chainage, 2) + " m, " +
              format::text(format::Length{std::abs(p.offset_m)}) + " " +
              (p.offset_m >= 0 ? "right" : "left") + " of the axis; placed by " +
              method_words(p.method) + ".");
    if (p.rms_m) paragraph("Target residual: " + format::text(format::Length{*p.rms_m}) + " rms");
  } else if (app.session->visit()) {
    paragraph("This visit is not placed in the tunnel yet.");
    draw_typed_placement(app);
  }
  if (app.session->visit()) draw_heading_entry(app);
  const bool idle = !app.task.running() && app.services.tunnel;
  if (app.targets.button("Excavation of this round", 0, idle && t.placement.has_value()))
    show_excavation(app);
  if (app.targets.button_in_row("Sets along the drive", idle)) show_drive(app);
  if (t.view == "drive" && t.drive) {
    t.drive_drawn = draw_drive_chart(*t.drive, ImGui::GetContentRegionAvail().x);
    for (const auto& line : t.lines) paragraph(line);
    return;
  }
  if (t.view == "excavation" && t.excavation) {
    t.excavation_drawn =
        draw_excavation_view(*t.excavation, t.picture, ImGui::GetContentRegionAvail().x);
    return;
  }
  for (const auto& line : t.lines) paragraph(line);
}

}  // namespace rockface::ui
