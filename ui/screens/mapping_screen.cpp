// Mapping: tap points on the 3D image to mark a trace, or tap its two ends
// for a semi-automatic trace; undo; assign it to a joint; the dip / dip
// direction and its uncertainty update with every tap, and the stereonet
// beside the model shows it with the visit's joints and stored traces.
// Saving a trace stores it at once (on the worker).
#include <algorithm>
#include <cmath>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/common/units.h"
#include "storage/project_store.h"
#include "ui/overlay_legend.h"
#include "ui/overlay_traces.h"
#include "ui/proposals_view.h"
#include "ui/format.h"
#include "ui/screens/screens.h"
#include "ui/stereonet_view.h"

namespace rockface::ui {

namespace {

constexpr ImU32 kJointColour = IM_COL32(0, 90, 200, 255);

TraceContext trace_context(const AppState& app) {
  TraceContext c;
  c.picker = app.model_view.picker();
  if (app.model_view.left_view()) c.photo_view = &*app.model_view.left_view();
  c.photo = &app.model_view.photo();
  // The precision of a picked point is the model's predicted depth
  // precision (stored with the registration by the reconstruction).
  if (const auto* m = app.model_view.model()) {
    const auto p = nlohmann::json::parse(
        m->registration.parameters_json.empty() ? "{}" : m->registration.parameters_json, nullptr,
        false);
    if (p.is_object() && p.contains("predicted_depth_sigma_mm") &&
        p["predicted_depth_sigma_mm"].is_number())
      c.settings.point_sigma = p["predicted_depth_sigma_mm"].get<double>() / 1000;
  }
  return c;
}

// The taps of the trace being marked; the traces themselves are laid on
// the surface by the renderer (ui/overlay_traces.h).
void draw_traces(AppState& app) {
  const float s = app.targets.scale();
  for (const auto& t : app.mapping.marker.taps())
    if (const auto q = app.model_view.to_screen(t))
      ImGui::GetWindowDrawList()->AddCircleFilled(*q, 7 * s, kPendingTraceColour, 16);
}

std::string next_trace_label(const ProjectSession& session) {
  int n = 0;
  for (const auto& m : session.measurements())
    if (m.kind == storage::Measurement::Kind::trace && m.label.size() > 1 && m.label[0] == 'T')
      n = std::max(n, std::atoi(m.label.c_str() + 1));
  return "T" + std::to_string(n + 1);
}

void save_trace(AppState& app) {
  const TraceMarker& marker = app.mapping.marker;
  storage::Measurement m;
  m.visit_id = *app.session->visit();
  m.model_id = app.model_view.model_id();
  m.kind = storage::Measurement::Kind::trace;
  m.label = next_trace_label(*app.session);
  m.joint_label = app.mapping.joint_label;
  m.points = marker.points();
  // Where the taps are in the left photograph of the pair it was mapped on
  // (its model's texture), so that the record names that pair's capture.
  const storage::Model* model = app.model_view.model();
  if (model && model->texture_capture_id && model->texture_side == "left" &&
      app.model_view.left_view() && !marker.taps().empty()) {
    const auto pixels = measure::project_to_view(*app.model_view.left_view(), marker.taps());
    if (std::all_of(pixels.begin(), pixels.end(),
                    [](const Eigen::Vector2d& p) { return p.allFinite(); })) {
      m.photo = "left";
      m.photo_capture_id = model->texture_capture_id;
      m.pixels = pixels;
    }
  }
  if (marker.plane() && marker.plane()->known) {
    m.dip_deg = rad_to_deg(marker.plane()->orientation.dip);
    m.dipdir_deg = rad_to_deg(marker.plane()->orientation.dipdir);
    m.fit_rms_m = marker.plane()->fit.rms_off_plane();
  }
  store_trace(app, std::move(m));
}

void draw_fit(const TraceMarker& marker) {
  // A refused tap says why even when the trace so far has a plane.
  if (marker.plane() && !marker.problem().empty()) paragraph(marker.problem(), warning_colour());
  if (const auto& plane = marker.plane(); plane && plane->known) {
    heading("Dip / dip direction " +
            format::dip_and_direction(rad_to_deg(plane->orientation.dip),
                                      rad_to_deg(plane->orientation.dipdir)));
    paragraph("± " + format::text(format::Angle{rad_to_deg(plane->sigma)}) + " (1σ), from " +
              format::count(static_cast<std::int64_t>(marker.points().size()), "point", "points"));
    if (!plane->problem.empty()) paragraph(plane->problem);
  } else if (plane) {
    paragraph(plane->problem);
  } else if (!marker.problem().empty()) {
    paragraph(marker.problem());
  } else {
    paragraph(marker.mode() == TraceMarker::Mode::points
                  ? "Tap points along a trace (3 or more)."
                  : "Tap the two ends of a trace: the trace between them is found on the image.");
  }
}

void draw_controls(AppState& app) {
  TraceMarker& marker = app.mapping.marker;
  const TraceContext context = trace_context(app);
  const bool idle = !app.task.running();
  auto toggle = [&](const char* label, bool on, bool enabled = true) {
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    const bool pressed = app.targets.button(label, 0, enabled);
    if (on) ImGui::PopStyleColor();
    return pressed;
  };
  // A visit photographed as several pairs: its 3D images, all in the face
  // frame; traces mapped on any of them land in that frame.
  const auto& pairs = app.session->pairs();
  if (pairs.size() > 1) {
    label_in_row("3D image:");
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::string name = "Pair " + std::to_string(k + 1);
      same_line_if_fits(button_width(name, app.targets.target_px()));
      // The taps of an unsaved trace were on this pair's 3D image: another
      // pair loses them, so it asks first.
      const bool current = app.session->pair() == k;
      const bool chosen = !marker.taps().empty() && !current
                              ? app.targets.confirmed_button(
                                    name, "The trace being marked is not saved. Leave it?", idle)
                              : toggle(name.c_str(), current, idle);
      if (chosen && !current) {
        marker.clear();
        app.session->choose_pair(k);
      }
    }
  }
  if (toggle("Tap points", marker.mode() == TraceMarker::Mode::points))
    marker.set_mode(TraceMarker::Mode::points);
  same_line_if_fits(button_width("Two taps", app.targets.target_px()));
  if (toggle("Two taps", marker.mode() == TraceMarker::Mode::two_taps))
    marker.set_mode(TraceMarker::Mode::two_taps);
  if (app.targets.button("Undo", 0, !marker.taps().empty())) marker.undo(context);
  // Clear loses every tap of the trace: asked first (Undo takes one back).
  same_line_if_fits(button_width("Clear", app.targets.target_px()));
  if (app.targets.confirmed_button("Clear", "Clear every tap of this trace?",
                                   !marker.taps().empty()))
    marker.clear();
  const bool can_save =
      idle && marker.points().size() >= 2 && app.session->visit() && !app.session->read_only();
  if (app.targets.button_in_row("Save trace", can_save)) save_trace(app);
  label_in_row("Joint:");
  std::vector<std::string> labels{""};
  for (const auto& j : app.session->joints()) labels.push_back(j.label);
  for (const auto& joint : labels) {
    const std::string name = joint.empty() ? std::string("none") : joint;
    same_line_if_fits(button_width(name, app.targets.target_px()));
    if (toggle(name.c_str(), app.mapping.joint_label == joint)) app.mapping.joint_label = joint;
  }
  draw_fit(marker);
}

}  // namespace

// Stores a trace as the Save trace button does (a hand trace, an accepted or
// a corrected proposal: proposals_view.h), then updates the map's blocks.
bool store_trace(AppState& app, storage::Measurement m) {
  if (m.label.empty()) m.label = next_trace_label(*app.session);
  const auto file = app.session->file();
  const FieldServices services = app.services;
  // The blocks are updated in the same task, right after the trace is
  // stored: the geologist sees what the trace closed before the next tap.
  auto blocks = std::make_shared<std::shared_ptr<const MapVerdicts>>();
  auto problem = std::make_shared<std::string>();
  return app.task.start(
      "Saving trace",
      [file, m, services, blocks, problem](Progress& progress) {
        storage::ProjectStore store = storage::ProjectStore::open(file);
        store.save_measurements(m.visit_id, {m});
        std::string done = "trace " + m.label + " saved";
        try {
          *blocks = update_map_blocks(services, file, m.visit_id, progress);
        } catch (const std::exception& e) {
          *problem = e.what();  // the trace is stored; the map says why it has no blocks
        }
        if (*blocks) done += "; " + map_blocks_summary(**blocks);
        return done;
      },
      [&app, visit = m.visit_id, blocks, problem](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) return;
        app.mapping.marker.clear();
        if (app.session) app.session->refresh();
        MapBlocksState& state = app.mapping.blocks;
        if (state.visit != visit) return;
        state.verdicts = *blocks;
        state.problem = *problem;
        state.stale = !*blocks && problem->empty();
      });
}

void draw_mapping_screen(AppState& app) {
  if (!require_model(app)) return;
  const SplitLayout layout = split_for_side_panel(400 * app.targets.scale());
  ImGui::BeginGroup();
  add_traces_to_overlay(app);
  add_map_blocks_to_overlay(app);
  drag_proposal_ends(app);  // before the model: a dragged handle does not turn it
  const auto interaction = app.model_view.draw(layout.main, app.gesture);
  if (interaction.tap && !tap_proposal(app, *interaction.tap)) {
    const ScreenRay r = app.model_view.ray_at(*interaction.tap);
    app.mapping.marker.tap({r.origin, r.direction}, trace_context(app));
  }
  refresh_map_blocks(app);
  ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
  draw_map_blocks_on_model(app);
  draw_traces(app);
  draw_model_overlays(app, ModelScreen::mapping);  // ui/overlay_legend.h
  draw_proposals_on_model(app);
  ImGui::PopClipRect();
  ImGui::EndGroup();
  begin_side_panel("mapping side", layout);
  draw_controls(app);
  draw_proposal_panel(app);
  draw_map_blocks_panel(app);
  std::vector<StereonetPlane> planes;
  for (const auto& j : app.session->joints())
    planes.push_back({j.dip_deg, j.dipdir_deg, kJointColour, true});
  for (const auto& m : app.session->measurements())
    if (m.kind == storage::Measurement::Kind::trace && m.dip_deg)
      planes.push_back({*m.dip_deg, *m.dipdir_deg, kTraceColour, false});
  if (const auto& plane = app.mapping.marker.plane(); plane && plane->known)
    planes.push_back({rad_to_deg(plane->orientation.dip), rad_to_deg(plane->orientation.dipdir),
                      kPendingTraceColour, true});
  draw_stereonet(planes,
                 std::min(ImGui::GetContentRegionAvail().x, ImGui::GetContentRegionAvail().y));
  ImGui::EndChild();
}

}  // namespace rockface::ui
