// Mapping: tap points on the 3D image to mark a trace, or tap its two ends
// for a semi-automatic trace; undo; assign it to a joint; the dip / dip
// direction and its uncertainty update with every tap, and the stereonet
// beside the model shows it with the visit's joints and stored traces.
// Saving a trace stores it at once (on the worker), with its joint when its
// plane is known (issue 27); the last saved trace can be taken back. "Outline
// the face" marks the mapped face's corners, stored as the visit's area.
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "core/common/error.h"
#include "core/common/units.h"
#include "storage/project/model_registration.h"
#include "storage/project/project_store.h"
#include "ui/app/screens.h"
#include "ui/blocks/stereonet_view.h"
#include "ui/mapping/mapping_compass.h"
#include "ui/mapping/proposals_view.h"
#include "ui/view3d/overlay_legend.h"
#include "ui/view3d/overlay_traces.h"
#include "ui/widgets/format.h"
#include "ui/widgets/toggle_button.h"

namespace rockface::ui {

namespace {

constexpr ImU32 kJointColour = IM_COL32(0, 90, 200, 255);
// The face outline stored for the visit (the mapped face the analysis takes).
constexpr ImU32 kOutlineColour = IM_COL32(255, 200, 0, 255);

TraceContext trace_context(const AppState& app) {
  TraceContext c;
  c.picker = app.model_view.picker();
  if (app.model_view.left_view()) c.photo_view = &*app.model_view.left_view();
  c.photo = &app.model_view.photo();
  // The precision of a picked point is the model's predicted depth
  // precision (stored with the registration by the reconstruction).
  if (const auto* m = app.model_view.model())
    if (const auto s = storage::read_model_registration(m->registration).predicted_depth_sigma_mm)
      c.settings.point_sigma = *s / 1000;
  return c;
}

// The taps of the trace being marked; the traces themselves are laid on
// the surface by the renderer (ui/view3d/overlay_traces.h).
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

}  // namespace

// Declared in mapping_compass.h (the compass panel saves the trace too).
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
  // Issue 27: the compass reading typed for it, if any (refused by name).
  if (!attach_compass_reading(app, m)) return;
  store_trace(app, std::move(m));
}

// Declared in mapping_compass.h: every edit of the map starts here.
MapEdit map_edit(const AppState& app) {
  MapEdit edit;
  edit.visit_id = app.session->visit().value_or(0);
  edit.picker = app.model_view.picker();
  edit.model_id = app.model_view.model_id();  // issue 27: each trace on its own pair
  edit.settings = trace_context(app).settings;
  return edit;
}

namespace {

// The visit's stored face outlines: its areas that are no free face and
// that no joint was measured from (as the runner replaces them).
std::vector<const storage::Measurement*> stored_outlines(const ProjectSession& session) {
  std::vector<const storage::Measurement*> out;
  for (const auto& m : session.measurements()) {
    if (m.kind != storage::Measurement::Kind::area || !m.rock_side.empty()) continue;
    const bool joint_face =
        std::any_of(session.joints().begin(), session.joints().end(),
                    [&](const storage::Joint& j) { return j.source == "area " + m.label; });
    if (!joint_face) out.push_back(&m);
  }
  return out;
}

// The last trace saved on the visit: the one "Undo" takes back.
const storage::Measurement* last_saved_trace(const ProjectSession& session) {
  const storage::Measurement* last = nullptr;
  for (const auto& m : session.measurements())
    if (m.kind == storage::Measurement::Kind::trace && (!last || m.id > last->id)) last = &m;
  return last;
}

// Issue 27 (touch): the stored outline and the corners tapped so far
// joined in order (closed once three), laid on the surface and depth-tested
// by the renderer like the traces (ui/mapping/face_outline.h).
void add_outlines_to_overlay(AppState& app) {
  const SurfaceDrape* drape = app.model_view.drape();
  if (!drape || !app.session) return;
  const float width = 3 * app.targets.scale();
  auto add = [&](const std::string& what, const std::vector<Eigen::Vector3d>& corners,
                 ImU32 colour) {
    for (auto& line :
         outline_on_surface(*drape, app.model_view.drape_cache(), what, corners, colour, width))
      app.model_view.overlay().lines.push_back(std::move(line));
  };
  for (const auto* m : stored_outlines(*app.session))
    add("face outline " + m->label, m->points, kOutlineColour);
  add("face outline being marked", app.mapping.outline.corners(), kPendingTraceColour);
}

// The corners tapped so far, over the model where each is in sight (one
// behind a ridge is not drawn).
void draw_outline(AppState& app) {
  const measure::MeshPicker* picker = app.model_view.picker();
  const SurfaceDrape* drape = app.model_view.drape();
  if (!picker || !drape) return;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const auto& p : app.mapping.outline.corners())
    if (const auto q = app.model_view.to_screen(p))
      if (corner_in_sight(*picker, app.model_view.ray_at(*q), p, drape->tolerance()))
        draw->AddCircleFilled(*q, 7 * app.targets.scale(), kPendingTraceColour, 16);
}

void save_outline(AppState& app) {
  MapEdit edit = map_edit(app);
  try {
    edit.outline = app.mapping.outline.corner_pixels(trace_context(app));
  } catch (const InputError& e) {
    app.fail(e.what());  // refused by name; the corners stay to be mended
    return;
  }
  const storage::Model* model = app.model_view.model();
  edit.view = app.model_view.left_view() ? &*app.model_view.left_view() : nullptr;
  edit.outline_model_id = app.model_view.model_id();
  if (model) edit.outline_capture_id = model->texture_capture_id;
  store_map_edit(app, std::move(edit), "Saving the face outline", [](AppState& a) {
    a.mapping.outline.clear();
    a.mapping.outlining = false;
    // The errors said here were the map's without a face ("no surface
    // patches"): read, now that it has one.
    a.statuses.dismiss(static_cast<std::size_t>(Screen::mapping));
  });
}

// "Outline the face": Undo takes back the last corner, Clear all of them;
// Save outline closes the polygon (Replace outline, asked first, when the
// visit has one).
void draw_outline_controls(AppState& app) {
  FaceOutline& outline = app.mapping.outline;
  const bool idle = !app.task.running();
  if (app.targets.button("Undo", 0, !outline.corners().empty())) outline.undo();
  same_line_if_fits(button_width("Clear", app.targets.target_px()));
  if (app.targets.confirmed_button("Clear", "Clear every corner of this outline?",
                                   !outline.corners().empty()))
    outline.clear();
  const bool can_save =
      idle && outline.corners().size() >= 3 && app.session->visit() && !app.session->read_only();
  const auto stored = stored_outlines(*app.session);
  if (stored.empty()) {
    if (app.targets.button_in_row("Save outline", can_save)) save_outline(app);
  } else {
    same_line_if_fits(button_width("Replace outline", app.targets.target_px()));
    std::string names;
    for (const auto* m : stored) names += (names.empty() ? "" : ", ") + m->label;
    if (app.targets.confirmed_button(
            "Replace outline",
            "The visit's face (" + names + ") is replaced by this outline. Replace it?", can_save))
      save_outline(app);
  }
  if (!outline.problem().empty())
    paragraph(outline.problem());
  else if (outline.corners().size() < 3)
    paragraph(
        "Tap the corners of the mapped face on the image (3 or more), then Save outline. " +
        format::count(static_cast<std::int64_t>(outline.corners().size()), "corner", "corners") +
        " so far.");
  else
    paragraph(
        format::count(static_cast<std::int64_t>(outline.corners().size()), "corner", "corners") +
        ": the polygon closes from the last corner to the first.");
}

// Takes back the last saved trace (asked first: the trace and its joint
// are gone from the visit).
void draw_undo_saved_trace(AppState& app) {
  const storage::Measurement* last = last_saved_trace(*app.session);
  if (!last || app.session->read_only() || !app.services.trace_map) return;
  const std::string name = "Undo " + last->label;
  same_line_if_fits(button_width(name, app.targets.target_px()));
  if (app.targets.confirmed_button(
          name, "Take back trace " + last->label + "? The trace and its joint leave the visit.",
          !app.task.running())) {
    MapEdit edit = map_edit(app);
    edit.remove_trace = last->id;
    store_map_edit(app, std::move(edit), "Taking back trace " + last->label, {});
  }
}

// Issue 27: the face's outline and the undo of the last saved trace, in a
// row of their own below the proposals (whose Accept / Reject stay where
// the geologist had them). The runner measures and stores both: without
// one (a test's services) neither is offered.
void draw_face_and_undo(AppState& app) {
  if (!app.services.trace_map) return;
  ImGui::Separator();
  const bool outlining = app.mapping.outlining;
  if (toggle_button(app.targets, "Outline the face", outlining)) app.mapping.outlining = !outlining;
  draw_undo_saved_trace(app);
  draw_compass_button(app);  // issue 27
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
                              : toggle_button(app.targets, name, current, idle);
      if (chosen && !current) {
        marker.clear();
        app.session->choose_pair(k);
      }
    }
  }
  const bool outlining = app.mapping.outlining;
  if (toggle_button(app.targets, "Tap points",
                    !outlining && marker.mode() == TraceMarker::Mode::points)) {
    marker.set_mode(TraceMarker::Mode::points);
    app.mapping.outlining = false;
  }
  same_line_if_fits(button_width("Two taps", app.targets.target_px()));
  if (toggle_button(app.targets, "Two taps",
                    !outlining && marker.mode() == TraceMarker::Mode::two_taps)) {
    marker.set_mode(TraceMarker::Mode::two_taps);
    app.mapping.outlining = false;
  }
  // Issue 27: the face's outline, marked with the same taps as a trace.
  if (app.mapping.outlining) {
    draw_outline_controls(app);
    return;
  }
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
    if (toggle_button(app.targets, name, app.mapping.joint_label == joint))
      app.mapping.joint_label = joint;
  }
  draw_fit(marker);
}

}  // namespace

// Stores an edit of the map on the worker (the runner measures and stores
// it as `rockface measure` would, with the visit's joints), then updates the
// map's blocks in the same task: the geologist sees what the edit closed or
// opened before the next tap. `then` runs once it is stored.
bool store_map_edit(AppState& app, MapEdit edit, const std::string& title,
                    std::function<void(AppState&)> then) {
  const auto file = app.session->file();
  const FieldServices services = app.services;
  auto blocks = std::make_shared<std::shared_ptr<const MapVerdicts>>();
  auto problem = std::make_shared<std::string>();
  const storage::RecordId visit = edit.visit_id;
  return app.task.start(
      title,
      [file, edit = std::move(edit), services, blocks, problem](Progress& progress) {
        std::string done;
        if (services.trace_map) {
          done = services.trace_map->store(file, edit, progress);
        } else if (edit.trace) {
          // No runner (a test's services): the trace alone, as tapped.
          storage::ProjectStore store = storage::ProjectStore::open(file);
          store.save_measurements(edit.visit_id, {*edit.trace});
          done = "trace " + edit.trace->label + " saved";
        }
        try {
          *blocks = update_map_blocks(services, file, edit.visit_id, progress);
        } catch (const std::exception& e) {
          *problem = e.what();  // the edit is stored; the map says why it has no blocks
        }
        if (*blocks) done += "; " + map_blocks_summary(**blocks);
        return done;
      },
      [&app, visit, blocks, problem, then = std::move(then)](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) return;
        if (then) then(app);
        if (app.session) app.session->refresh();
        MapBlocksState& state = app.mapping.blocks;
        if (state.visit != visit) return;
        state.verdicts = *blocks;
        state.problem = *problem;
        state.stale = !*blocks && problem->empty();
      });
}

// Stores a trace as the Save trace button does (a hand trace, an accepted or
// a corrected proposal: proposals_view.h), then updates the map's blocks.
bool store_trace(AppState& app, storage::Measurement m) {
  if (m.label.empty()) m.label = next_trace_label(*app.session);
  MapEdit edit = map_edit(app);
  edit.visit_id = m.visit_id;
  edit.trace = std::move(m);
  return store_map_edit(app, std::move(edit), "Saving trace", [](AppState& a) {
    a.mapping.marker.clear();
    // Issue 27: the reading went with the trace (one for a saved trace stays).
    if (!a.mapping.compass.trace) {
      a.mapping.compass.clear();
      a.mapping.compass.open = false;
    }
  });
}

void draw_mapping_screen(AppState& app) {
  if (!require_model(app)) return;
  const SplitLayout layout = split_for_side_panel(400 * app.targets.scale());
  ImGui::BeginGroup();
  add_traces_to_overlay(app);
  add_map_blocks_to_overlay(app);
  add_outlines_to_overlay(app);  // issue 27 (touch): on the surface
  drag_proposal_ends(app);       // before the model: a dragged handle does not turn it
  auto interaction = app.model_view.draw(layout.main, app.gesture);
  // Issue 27 (touch): a tap on a block's marker selects the block.
  if (interaction.tap && tap_map_block(app, *interaction.tap)) interaction.tap.reset();
  if (interaction.tap && app.mapping.outlining) {
    const ScreenRay r = app.model_view.ray_at(*interaction.tap);
    app.mapping.outline.tap({r.origin, r.direction}, app.model_view.picker());
  } else if (interaction.tap && !tap_proposal(app, *interaction.tap)) {
    const ScreenRay r = app.model_view.ray_at(*interaction.tap);
    app.mapping.marker.tap({r.origin, r.direction}, trace_context(app));
  }
  refresh_map_blocks(app);
  ImGui::PushClipRect(app.model_view.panel_min(), app.model_view.panel_max(), true);
  draw_map_blocks_on_model(app);
  draw_outline(app);  // under the trace's taps
  draw_traces(app);
  draw_model_overlays(app, ModelScreen::mapping);  // ui/view3d/overlay_legend.h
  draw_proposals_on_model(app);
  ImGui::PopClipRect();
  ImGui::EndGroup();
  begin_side_panel("mapping side", layout);
  // Issue 27: the compass panel, while open, in place of the controls.
  if (draw_compass_panel(app)) {
    ImGui::EndChild();
    return;
  }
  draw_controls(app);
  draw_proposal_panel(app);
  draw_face_and_undo(app);
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
