#pragma once
// What a wedge analysis runs on, gathered from where the geologist has it:
// a scene's `wedges` section (sets, profile, axis, trace-length limit,
// support; water and seismic from the scene's `effects`), or a project's
// tunnel (its design profile, and the drive's axis and the face at the
// visit's chainage) with the visit's measured joint sets, or its joints
// one by one when they form fewer than three sets (as UnWedge takes three
// orientations).
#include <optional>
#include <string>
#include <vector>

#include "core/common/preset.h"
#include "core/tunnel/alignment.h"
#include "core/tunnel/design_profile.h"
#include "core/tunnel/wedge_analysis.h"
#include "storage/project/project_store.h"
#include "storage/scene/scene.h"

namespace rockface::app {

struct WedgeSetInput {
  std::string id;
  double dip_deg = 0, dipdir_deg = 0;
  std::optional<double> friction_deg;
  double cohesion_pa = 0;
  std::string source;  // "scene", "measured" (a set), "joint" (a joint taken as a set)
};

struct WedgeRun {
  std::string source;                      // the scene file or "project P, visit N"
  std::optional<storage::RecordId> visit;  // project runs
  tunnel::DesignProfile profile;
  std::string profile_source;
  double trend_deg = 0, plunge_deg = 0;  // the drive's axis
  tunnel::TunnelFrame frame;             // datum-relative
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();
  std::optional<double> chainage;  // of the section / face, with a tunnel
  std::vector<WedgeSetInput> sets;
  tunnel::WedgeOptions options;
  Preset preset = Preset::standard;
  std::vector<std::string> notes;
};

// An axis typed as "TREND/PLUNGE" (degrees); InputError(where) otherwise.
std::pair<double, double> parse_axis(const std::string& text, const std::string& where);

// Throws InputError naming the scene and field: no `wedges` section, fewer
// than three sets, no profile (neither given nor a scene tunnel), no axis.
WedgeRun wedge_run_from_scene(const storage::Scene& scene,
                              std::optional<std::pair<double, double>> axis = std::nullopt);

struct ProjectWedgeSettings {
  std::optional<std::pair<double, double>> axis;  // degrees; none: the drive at the visit
  // The friction angle of every set or joint when given; when not, a joint's
  // own (stored with the visit) or this default, said to be assumed.
  double friction_deg = 30;
  bool friction_given = false;
  double cohesion_pa = 0;
  std::optional<double> trace_length;
  std::optional<tunnel::PatternBolts> bolts;
  std::optional<tunnel::Shotcrete> shotcrete;
  Preset preset = Preset::standard;
};

// Throws InputError naming the project and visit: no tunnel, a visit not
// placed in it (without --axis and an origin there is no section), fewer
// than three sets and fewer than three joints.
WedgeRun wedge_run_from_project(storage::ProjectStore& store, storage::RecordId visit,
                                const ProjectWedgeSettings& settings);

// What the wedges were made from, in words, for the tablet and the report:
// "Sets (dip/dip direction, friction): S1 60.0°/200.0° 30°, ..." or, for a
// visit's joints, "Joints, each taken as a set (...)".
std::string wedge_sets_line(const WedgeRun& run);

// The support the run checks, in words: "Support: bolts 3.0 m long, 1.5 m
// apart, 100 kN each; shotcrete 50 mm, shear strength 2.0 MPa" or
// "Support: none".
std::string wedge_support_line(const WedgeRun& run);

// The analysis of a run.
tunnel::WedgeAnalysis run_wedges(const WedgeRun& run);

}  // namespace rockface::app
