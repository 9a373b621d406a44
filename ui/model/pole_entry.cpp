#include "ui/model/pole_entry.h"

#include <string>

#include "core/common/number_format.h"
#include "storage/project/model_registration.h"
#include "ui/app/screens.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// An imported 3D image in a local frame that nothing scaled yet.
bool unscaled_import(const storage::Model& model) {
  const storage::ModelRegistration reg = storage::read_model_registration(model.registration);
  return !reg.imported_from.empty() && model.registration.kind == "none";
}

// Why the taps are not yet a pole; empty when they are one.
std::string pole_taps_problem(const PoleEntryState& e) {
  if (e.targets.empty()) return "Tap the pole's lower target on the 3D image.";
  if (e.targets.size() == 1) return "Now tap its upper target.";
  // 1e-9: the same point twice (a double tap).
  if ((e.targets[0] - e.targets[1]).norm() < 1e-9)
    return "Both taps found the same point: tap the upper target again.";
  return {};
}

void scale_by_pole(AppState& app) {
  PoleRunner* runner = app.services.pole;
  const auto file = app.session->file();
  const storage::RecordId visit = *app.session->visit();
  const Eigen::Vector3d lower = app.model.pole.targets[0], upper = app.model.pole.targets[1];
  const double length = app.capture.range_pole_m;
  app.task.start(
      "Range pole",
      [runner, file, visit, lower, upper, length](Progress& progress) {
        return runner->scale(file, visit, lower, upper, length, progress);
      },
      [&app](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) return;  // the taps stay to be mended
        app.model.pole.clear();
        if (app.session) app.session->refresh();  // the scaled 3D images, stored anew
      });
}

}  // namespace

void PoleEntryState::clear() {
  open = false;
  targets.clear();
}

void draw_pole_section(AppState& app) {
  if (!unscaled_import(*app.model_view.model())) return;
  heading("Scale");
  paragraph(
      "Not to scale: this 3D image came in its own frame, so lengths, dips and volumes are "
      "not true until it is scaled and levelled.");
  PoleEntryState& e = app.model.pole;
  if (!app.services.pole || !app.session || !app.session->visit()) return;
  if (!e.open) {
    const bool can = !app.session->read_only() && !app.task.running();
    if (app.targets.button("Scale from the range pole", -1, can)) {
      e.clear();
      e.open = true;
    }
    return;
  }
  paragraph(
      "Tap the centre of the pole's lower target on the 3D image, then its upper one. The "
      "pole is " +
      format::text(format::Length{app.capture.range_pole_m}) +
      " between its targets (typed on the Capture screen).");
  label(e.targets.empty()       ? "Targets: none tapped yet"
        : e.targets.size() == 1 ? "Targets: the lower tapped"
                                : "Targets: both tapped (a third tap starts again)");
  const std::string why = pole_taps_problem(e);
  if (!why.empty()) paragraph(why);
  const bool can = why.empty() && !app.task.running();
  if (app.targets.button("Scale by the pole", 0, can)) scale_by_pole(app);
  ImGui::SameLine();
  if (app.targets.button_in_row("Cancel pole")) e.clear();
}

void pole_model_taps(AppState& app, const ModelView::Interaction& touch) {
  PoleEntryState& e = app.model.pole;
  if (!e.open) return;
  if (touch.tap && app.model_view.picker()) {
    const ScreenRay ray = app.model_view.ray_at(*touch.tap);
    if (const auto hit = app.model_view.picker()->pick({ray.origin, ray.direction})) {
      if (e.targets.size() == 2) e.targets.clear();
      e.targets.push_back(hit->point);
    }
  }
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float r = 0.25f * app.targets.target_px();
  for (const auto& p : e.targets)
    if (const auto at = app.model_view.to_screen(p))
      draw->AddCircle(*at, r, kTargetColour, 0, 2.5f);
}

}  // namespace rockface::ui
