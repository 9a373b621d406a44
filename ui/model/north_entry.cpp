#include "ui/model/north_entry.h"

#include <cmath>
#include <string>

#include "storage/project/model_registration.h"
#include "ui/app/screens.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

using NorthField = NorthEntryState::Field;

// The line's colour on the photograph: the pole targets' rings are orange.
constexpr ImU32 kLineColour = IM_COL32(80, 200, 255, 255);

// Why what was given is not yet a compass line; empty when it is one.
std::string problem(const NorthEntryState& e) {
  if (e.ends.size() < 2) return "Tap the line's two ends on the photograph.";
  if ((e.ends[0] - e.ends[1]).norm() < 20)
    return "The two ends are closer than 20 pixels: tap them further apart.";
  if (e.bearing.text().empty()) return "Type the bearing read from the first end to the second.";
  if (!(e.bearing.value() >= 0 && e.bearing.value() <= 360))
    return "Bearing " + format::text(format::Angle{e.bearing.value()}) +
           " is outside 0–360°: type it again.";
  if (!(e.declination.value() <= 30))
    return "Declination " + format::text(format::Angle{e.declination.value()}) +
           " is more than 30°: type it again.";
  return {};
}

void give_north(AppState& app) {
  NorthEntryState& e = app.model.north;
  NorthRunner* runner = app.services.north;
  const auto file = app.session->file();
  const storage::RecordId visit = *app.session->visit();
  const Eigen::Vector2d from = e.ends[0], to = e.ends[1];
  const double bearing = e.bearing.value();
  const double declination = (e.declination_west ? -1 : 1) * e.declination.value();
  app.task.start(
      "North",
      [runner, file, visit, from, to, bearing, declination](Progress& progress) {
        return runner->orient(file, visit, from, to, bearing, declination, progress);
      },
      [&app](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) return;  // the line stays to be mended
        app.model.north.clear();
        app.model.show_photograph = false;
        if (app.session) app.session->refresh();  // the turned 3D images, stored anew
      });
}

void draw_entry(AppState& app) {
  NorthEntryState& e = app.model.north;
  paragraph(
      "Tap the two ends of a line whose bearing you read with the compass (a painted line, a "
      "string) on the photograph, then type the bearing from the first end to the second.");
  label(e.ends.empty()       ? "Line: no end tapped yet"
        : e.ends.size() == 1 ? "Line: first end tapped"
                             : "Line: both ends tapped (a third tap starts it again)");
  if (toggle_button(app.targets, "Bearing", e.typing == NorthField::bearing)) {
    e.typing = NorthField::bearing;
    e.bearing.clear();
  }
  ImGui::SameLine();
  label_in_row(e.bearing.text().empty() ? std::string("not typed")
                                        : format::text(format::Angle{e.bearing.value()}));
  if (toggle_button(app.targets, "Declination", e.typing == NorthField::declination)) {
    e.typing = NorthField::declination;
    e.declination.clear();
  }
  ImGui::SameLine();
  if (app.targets.button_in_row(e.declination_west ? "West" : "East"))
    e.declination_west = !e.declination_west;
  ImGui::SameLine();
  label_in_row(format::text(format::Angle{e.declination.value()}));
  if (const auto k = draw_keypad(app.targets))
    (e.typing == NorthField::bearing ? e.bearing : e.declination).key(*k);
  const std::string why = problem(e);
  if (!why.empty()) paragraph(why);
  const bool can = why.empty() && !app.task.running();
  if (app.targets.button("Give north", 0, can)) give_north(app);
  ImGui::SameLine();
  if (app.targets.button_in_row("Cancel north")) {
    e.clear();
    app.model.show_photograph = false;
  }
}

}  // namespace

void NorthEntryState::clear() {
  open = false;
  ends.clear();
  bearing.clear();
  declination.clear();
  declination_west = false;
  typing = NorthField::bearing;
}

void draw_north_section(AppState& app) {
  const storage::Model& model = *app.model_view.model();
  const storage::ModelRegistration reg = storage::read_model_registration(model.registration);
  heading("North");
  if (reg.oriented()) {
    paragraph(reg.compass_azimuth_deg
                  ? "From the compass line at " +
                        format::text(format::Angle{*reg.compass_azimuth_deg}) + "."
                  : "Oriented (" + reg.north_source + ").");
    return;
  }
  paragraph(
      "Not known: the 3D image is turned as the camera stood, so dip directions and bearings "
      "are not true until north is given.");
  NorthEntryState& e = app.model.north;
  if (!app.services.north || !app.session || !app.session->visit()) return;
  if (app.session->pair() != 0) {
    paragraph("North is given on the photograph of pair 1: choose it first.");
    return;
  }
  if (!e.open) {
    const bool can = !app.session->read_only() && !app.task.running();
    if (app.targets.button("Give north from a compass line", -1, can)) {
      e.clear();
      e.open = true;
      app.model.show_photograph = true;
    }
    return;
  }
  draw_entry(app);
}

void north_photograph_taps(AppState& app, ImVec2 image_min, float px_per_photo_px,
                           ImVec2 image_max) {
  NorthEntryState& e = app.model.north;
  if (!e.open || px_per_photo_px <= 0) return;
  const ImVec2 m = ImGui::GetMousePos();
  const bool inside =
      m.x >= image_min.x && m.x < image_max.x && m.y >= image_min.y && m.y < image_max.y;
  if (inside && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    if (e.ends.size() == 2) e.ends.clear();
    e.ends.emplace_back((m.x - image_min.x) / px_per_photo_px - 0.5,
                        (m.y - image_min.y) / px_per_photo_px - 0.5);
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  auto at = [&](const Eigen::Vector2d& p) {
    return ImVec2(image_min.x + static_cast<float>(p.x() + 0.5) * px_per_photo_px,
                  image_min.y + static_cast<float>(p.y() + 0.5) * px_per_photo_px);
  };
  const float r = 0.25f * app.targets.target_px();
  for (const auto& p : e.ends) draw->AddCircle(at(p), r, kLineColour, 0, 2.5f);
  if (e.ends.size() == 2) draw->AddLine(at(e.ends[0]), at(e.ends[1]), kLineColour, 2.5f);
}

}  // namespace rockface::ui
