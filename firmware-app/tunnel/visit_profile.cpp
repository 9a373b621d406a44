#include "firmware-app/tunnel/visit_profile.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/tunnel/face_front.h"
#include "core/tunnel/surface_reach.h"
#include "firmware-app/tunnel/visit_placement.h"
#include "firmware-app/tunnel/visit_surface.h"

namespace rockface::app {

namespace {

// How far short of the face's nearest rock the round is measured (m). Near
// the face the wall and the face meet in a crease where the dense
// matching's window holds both, and the wall's texture, seen at a grazing
// angle, is streaked along the drive: on the D heading of
// tests/integration/tunnel/tunnel_break_truth_test.cpp the sections 0.15 m
// short of the face read 0.11 m of underbreak over a patch where the scene
// has none (issue 38). 0.4 m leaves them out; what the round loses by it is
// the last 0.25 m of its length, stated by its range.
constexpr double kFaceClearM = 0.4;

}  // namespace

VisitProfile visit_profile(storage::ProjectStore& store, storage::RecordId visit_id, Preset preset,
                           const DriveFaces* given) {
  VisitProfile out;
  auto tunnel = store.load_tunnel();
  if (!tunnel)
    throw InputError(store.file().string(),
                     "the project has no tunnel: add its alignment and design profile first");
  out.tunnel = std::move(*tunnel);
  auto placement = known_placement(store, out.tunnel, visit_id);
  if (!placement)
    throw InputError("visit " + std::to_string(visit_id),
                     "is not placed in the tunnel: type the chainage of its range pole, or "
                     "register it to monitoring targets");
  out.placement = *placement;
  tunnel::Alignment alignment = out.tunnel.alignment(store.project().datum);
  // The round is read in its heading's drive direction (round_start.h): a
  // heading driven from the far portal advances toward the other end.
  const DriveFaces read = given ? DriveFaces{} : drive_faces(store, out.tunnel.drive);
  const DriveFaces& drive = given ? *given : read;
  const double sense = drive.sense_of(drive.heading_of(visit_id));
  alignment.set_drive(sense > 0 ? tunnel::Drive::ascending : tunnel::Drive::descending);
  out.sense = sense;
  const VisitSurface surface = visit_surface(store, visit_id);
  out.pole_vertices = surface.pole_vertices;

  // The round: back to the nearest face of an earlier visit of the same
  // heading behind this one.
  // The round is measured up to kFaceClearM short of where the face reaches
  // farthest back (face_front.h): a cross-section through the face cuts the
  // face (its bulge, its roughness, the reconstruction's smear into the
  // corner), which would read as metres of underbreak, and the crease by it
  // reads as centimetres (kFaceClearM).
  const auto reach =
      tunnel::surface_reach(alignment, tunnel::rock_places(alignment, surface_input(surface)));
  const double rear = reach ? reach->rear : 0;
  const auto front =
      tunnel::face_front(alignment, out.tunnel.profile, surface_input(surface), rear);
  // Every cross-section the surface reaches is measured, from its rearmost
  // rock: sections that meet nothing there are left out by the measurement
  // and said (profile_deviation.h).
  const double start = reach ? reach->first : 0;
  out.round_to = (front ? front->nearest_chainage : out.placement.chainage) - sense * kFaceClearM;
  const auto previous = drive.previous_face(visit_id, out.round_to, sense);
  if (previous) out.previous_face = previous->chainage;
  if (previous && sense * previous->chainage >= sense * start) {
    out.round_from = previous->chainage;
    out.round_from_source = "face of visit " + std::to_string(previous->visit_id);
  } else {
    // No earlier face, or it lies behind what the cameras saw: the round is
    // measured where there is surface to measure.
    out.round_from = start;
    out.round_from_source = "start of the 3D image";
  }
  tunnel::DeviationOptions options = analysis::preset_options(preset).deviation;
  if (sense * (out.round_to - out.round_from) < options.section_spacing_m) {
    // The 3D image holds the face and nothing behind it: no wall, roof or
    // invert to hold against the design. Said so, never zero over- and
    // underbreak.
    out.deviation.status = tunnel::DeviationStatus::no_walls_in_view;
    out.deviation.message =
        "the 3D image holds only the face (its surface starts at chainage " +
        format_fixed(out.round_from, 2) + ", the face reaches back to " +
        format_fixed(out.round_to + sense * kFaceClearM, 2) +
        "): no walls, roof or invert in view to compare with the design profile";
    out.deviation.underbreak_tolerance_m = out.tunnel.underbreak_tolerance_m;
    return out;
  }
  options.chainage_from = out.round_from;
  options.chainage_to = out.round_to;
  options.underbreak_tolerance_m = out.tunnel.underbreak_tolerance_m;
  // The 3D images' own stated precision: deviations within it are noise.
  if (surface.depth_sigma_m) options.depth_sigma_m = *surface.depth_sigma_m;
  // Each cell's threshold from its own distance to the cameras and its
  // incidence (issue 38): the grazing walls are less precise than the face.
  tunnel::PreciseDeviation measured = tunnel::profile_deviation_per_cell(
      surface_input(surface), alignment, out.tunnel.profile, options, surface.precision);
  out.deviation = std::move(measured.deviation);
  // The volumes' stated uncertainty is the 3D image's; a round turned by
  // its compass line carries the line's heading error too, which it cannot
  // state (issue 38: a line read from the 3D image turned the test headings
  // by 0.14-0.22 deg, and a tenth of a degree moved their volumes by up to
  // 25 %). Said, with what places a round better.
  if (out.placement.method == tunnel::VisitPlacement::Method::chainage_compass &&
      (out.deviation.status == tunnel::DeviationStatus::ok ||
       out.deviation.status == tunnel::DeviationStatus::partly_seen))
    out.deviation.message +=
        "; placed by its chainage and compass line, whose heading error (0.1-0.5 deg) is not in "
        "the volumes' uncertainty: a tenth of a degree can move them by 5-25 %; the survey's "
        "monitoring targets (ground control) place a round to a few hundredths of a degree";
  out.cell_precision = std::move(measured.precision);
  out.cell_sigma_m = std::move(measured.cell_sigma_m);
  return out;
}

}  // namespace rockface::app
