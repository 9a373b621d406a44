#include "firmware-app/wedges/wedge_input.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "core/analysis/preset_options.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/orientation.h"
#include "core/tunnel/tolerances.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/field_report/field_report.h"

namespace rockface::app {

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

tunnel::WedgeJointSet joint_set(const WedgeSetInput& s) {
  tunnel::WedgeJointSet j;
  j.id = s.id;
  j.normal = geometry::plane_normal_deg(s.dip_deg, s.dipdir_deg);
  if (s.friction_deg) j.friction = *s.friction_deg * kRad;
  j.cohesion = s.cohesion_pa;
  return j;
}

tunnel::SupportPlaces places(const analysis::SceneWedgeSupportPlaces& p) {
  return {p.roof, p.walls, p.floor, p.face};
}

void frame_from_axis(WedgeRun& run, double trend_deg, double plunge_deg,
                     const Eigen::Vector3d& origin, const std::string& where) {
  run.trend_deg = trend_deg;
  run.plunge_deg = plunge_deg;
  run.frame = tunnel::axis_frame(trend_deg * kRad, plunge_deg * kRad, origin, where);
}

// The tunnel's drive at a chainage as trend / plunge in degrees.
std::pair<double, double> drive_axis(const tunnel::Alignment& a, double chainage) {
  const geometry::LineOrientation o = geometry::line_orientation(a.tangent_at(chainage));
  return {o.trend / kRad, o.plunge / kRad};
}

// A section beyond the alignment's ends would be extrapolated along the
// end's tangent and analysed as if it were in the drive (issue 40): a
// chainage past either end by more than a table's rounding
// (kChainageMismatchM) is a wrong chainage or a table not yet extended,
// and is refused naming its field.
void require_on_alignment(const tunnel::Alignment& a, double chainage, const std::string& where) {
  const double first = a.first_chainage(), last = a.last_chainage();
  if (chainage >= first - tunnel::kChainageMismatchM &&
      chainage <= last + tunnel::kChainageMismatchM)
    return;
  throw InputError(where,
                   "chainage " + format_fixed(chainage, 3) + " m lies beyond the alignment (" +
                       format_fixed(first, 3) + " to " + format_fixed(last, 3) + " m) by " +
                       format_fixed(chainage < first ? first - chainage : chainage - last, 3) +
                       " m: a section there is not in the drive; correct the chainage or "
                       "extend the alignment's table");
}

}  // namespace

std::pair<double, double> parse_axis(const std::string& text, const std::string& where) {
  const auto slash = text.find('/');
  double trend = NAN, plunge = NAN;
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    std::size_t used = 0;
    trend = std::stod(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("trend");
    const std::string p = text.substr(slash + 1);
    plunge = std::stod(p, &used);
    if (used != p.size()) throw std::invalid_argument("plunge");
  } catch (const std::exception&) {
    throw InputError(where, "\"" + text + "\" is not TREND/PLUNGE in degrees (e.g. 35/2)");
  }
  if (!(trend >= 0 && trend <= 360) || !(plunge > -90 && plunge < 90))
    throw InputError(where, "trend must be in [0, 360] and plunge in (-90, 90) degrees");
  return {trend, plunge};
}

WedgeRun wedge_run_from_scene(const storage::Scene& scene,
                              std::optional<std::pair<double, double>> axis) {
  const std::string& src = scene.source;
  if (!scene.wedges)
    throw InputError(src + ": wedges", "missing: the scene asks for no wedge analysis");
  const analysis::SceneWedges& w = *scene.wedges;
  WedgeRun run;
  run.source = src;
  run.datum = scene.datum;
  run.preset = scene.analysis.preset;
  // The sets.
  std::vector<std::string> ids = w.sets;
  if (ids.empty())
    for (const auto& j : scene.joints) ids.push_back(j.id);
  for (const auto& id : ids) {
    const analysis::SceneJoint* j = scene.joint(id);
    WedgeSetInput s{id, j->dip, j->dipdir, j->friction, j->cohesion.value_or(0), "scene"};
    run.sets.push_back(s);
  }
  if (run.sets.size() < 3)
    throw InputError(
        src + ": " + (w.sets.empty() ? "joints" : "wedges.sets"),
        "a wedge needs three joint sets; " + std::to_string(run.sets.size()) + " given");
  // The profile.
  if (w.profile) {
    run.profile = *w.profile;
    run.profile_source = w.profile_source;
  } else if (scene.tunnel) {
    run.profile = scene.tunnel->record.profile;
    run.profile_source = "tunnel";
  } else {
    throw InputError(src + ": wedges.profile",
                     "missing, and the scene has no tunnel to take the design profile from");
  }
  try {
    run.profile.require_valid("profile");
  } catch (const InputError& e) {
    throw InputError(src + ": wedges.profile", e.what());
  }
  // The section: its origin and the axis.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::optional<std::pair<double, double>> tunnel_axis;
  if (scene.tunnel) {
    std::optional<double> c = w.chainage;
    std::string field = "wedges.chainage";
    if (!c && scene.tunnel->placement) {
      c = scene.tunnel->placement->chainage;
      field = "tunnel.placement.chainage";
    }
    if (!c && scene.tunnel->render) {
      c = scene.tunnel->render->face_chainage;
      field = "tunnel.render.face_chainage";
    }
    if (c) {
      const tunnel::Alignment a = scene.tunnel->record.alignment(scene.datum);
      require_on_alignment(a, *c, src + ": " + field);
      origin = a.point_at(*c);
      tunnel_axis = drive_axis(a, *c);
      run.chainage = c;
    }
  }
  if (w.origin) origin = *w.origin - scene.datum;
  const std::string axis_where = axis ? "--axis" : src + ": wedges.axis";
  if (!axis && w.trend) axis = std::make_pair(*w.trend, *w.plunge);
  if (!axis) axis = tunnel_axis;
  if (!axis)
    throw InputError(src + ": wedges.axis",
                     "missing: give the axis (trend, plunge), or a tunnel and a chainage");
  frame_from_axis(run, axis->first, axis->second, origin, axis_where);
  // Options.
  tunnel::WedgeOptions& o = run.options;
  o.density = scene.density;
  o.gravity = scene.gravity;
  o.uncertainty = scene.analysis.orientation_uncertainty_deg * kRad;
  o.sagitta_m = analysis::preset_options(run.preset).wedge_sagitta_m;
  o.trace_length_limit = w.trace_length;
  o.perimeter = w.perimeter;
  o.face = w.face;
  if (scene.effects.water) {
    const auto& sw = *scene.effects.water;
    tunnel::WedgeWater water;
    water.unit_weight = sw.unit_weight;
    water.phreatic_point = sw.phreatic_point;
    water.phreatic_normal = geometry::plane_normal_deg(sw.phreatic_dip, sw.phreatic_dipdir);
    for (const auto& id : sw.joints)
      for (std::size_t k = 0; k < run.sets.size(); ++k)
        if (run.sets[k].id == id) water.sets.push_back(static_cast<int>(k));
    if (!sw.joints.empty() && water.sets.empty())
      run.notes.push_back("effects.water names none of the wedges' sets: no water on them");
    else
      o.water = water;
  }
  o.seismic = scene.effects.seismic;
  for (const auto& name : scene.effects.listed())
    if (name != "gravity" && name != "water" && name != "seismic")
      run.notes.push_back("effects." + name +
                          " acts on the scene's blocks, not on the wedges (their support is "
                          "wedges.support)");
  if (w.bolts) {
    tunnel::PatternBolts b;
    b.length = w.bolts->length;
    b.spacing = w.bolts->spacing;
    b.capacity = w.bolts->capacity;
    b.bond_strength = w.bolts->bond_strength;
    b.places = places(w.bolts->on);
    o.bolts = b;
  }
  if (w.shotcrete) {
    tunnel::Shotcrete s;
    s.thickness = w.shotcrete->thickness;
    s.shear_strength = w.shotcrete->shear_strength;
    s.places = places(w.shotcrete->on);
    o.shotcrete = s;
  }
  return run;
}

WedgeRun wedge_run_from_project(storage::ProjectStore& store, storage::RecordId visit,
                                const ProjectWedgeSettings& settings) {
  const std::string where = store.file().string() + ", visit " + std::to_string(visit);
  WedgeRun run;
  run.source = where;
  run.visit = visit;
  run.preset = settings.preset;
  run.datum = store.project().datum;
  const auto tun = store.load_tunnel();
  if (!tun)
    throw InputError(store.file().string(),
                     "the project has no tunnel: add its alignment and design profile first");
  run.profile = tun->profile;
  run.profile_source = tun->profile_source.empty() ? "tunnel" : tun->profile_source;
  const auto placement = store.load_visit_placement(visit);
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::optional<std::pair<double, double>> axis = settings.axis;
  const tunnel::Alignment alignment = tun->alignment(run.datum);
  if (placement) {
    require_on_alignment(alignment, placement->chainage, where + ": placement");
    run.chainage = placement->chainage;
    origin = alignment.point_at(placement->chainage);
    if (!axis) axis = drive_axis(alignment, placement->chainage);
  } else {
    if (!axis)
      throw InputError(where, "the visit is not placed in the tunnel: give --axis TREND/PLUNGE");
    run.notes.push_back(
        "the visit is not placed in the tunnel: the section is taken at the "
        "alignment's first station");
    origin = alignment.point_at(alignment.first_chainage());
  }
  frame_from_axis(run, axis->first, axis->second, origin, settings.axis ? "--axis" : where);
  // The visit's sets when its joints form them; else its joints one by one,
  // as UnWedge takes three orientations (issue 39): a geologist who measured
  // one joint per orientation expects that joint's wedges.
  const auto observed = visit_set_observations(store, visit);
  for (const auto& s : observed) {
    const geometry::PlaneOrientation o = geometry::plane_orientation(s.normal);
    WedgeSetInput in{
        s.name,    o.dip / kRad, o.dipdir / kRad, settings.friction_deg, settings.cohesion_pa,
        "measured"};
    run.sets.push_back(in);
  }
  const std::size_t set_count = run.sets.size();
  int joints_with_friction = 0;
  std::size_t joint_count = 0;
  if (set_count < 3) {
    const auto joints = store.list_joints(visit);
    joint_count = joints.size();
    if (joint_count >= 3) {
      run.sets.clear();
      for (const auto& j : joints) {
        WedgeSetInput in{
            j.label, j.dip_deg, j.dipdir_deg, settings.friction_deg, settings.cohesion_pa, "joint"};
        // The joint's own strength, unless the geologist typed one for all.
        if (!settings.friction_given && j.friction_deg) {
          in.friction_deg = *j.friction_deg;
          in.cohesion_pa = j.cohesion_pa.value_or(0);
          ++joints_with_friction;
        }
        run.sets.push_back(in);
      }
      run.notes.push_back("the visit's " + std::to_string(set_count) +
                          " measured joint sets are fewer than three: the wedges are those of "
                          "its " +
                          std::to_string(joint_count) + " joints, each taken as a set");
    }
  }
  if (run.sets.size() < 3)
    throw InputError(where, "has " + std::to_string(set_count) + " measured joint sets and " +
                                std::to_string(joint_count) +
                                " joints; a wedge needs three of either");
  const std::size_t assumed = run.sets.size() - static_cast<std::size_t>(joints_with_friction);
  if (!settings.friction_given && assumed > 0)
    run.notes.push_back(std::string(joints_with_friction > 0 ? "the joints stored without strength"
                                    : set_count >= 3         ? "the measured sets carry no strength"
                                                             : "the joints carry no strength") +
                        ": a friction angle of " +
                        std::to_string(static_cast<int>(settings.friction_deg)) +
                        " deg and no cohesion are assumed (--friction)");
  tunnel::WedgeOptions& o = run.options;
  o.sagitta_m = analysis::preset_options(settings.preset).wedge_sagitta_m;
  o.trace_length_limit = settings.trace_length;
  o.bolts = settings.bolts;
  o.shotcrete = settings.shotcrete;
  return run;
}

std::string wedge_sets_line(const WedgeRun& run) {
  bool joints = !run.sets.empty();
  for (const auto& s : run.sets) joints = joints && s.source == "joint";
  std::string line = joints ? "Joints, each taken as a set (dip/dip direction, friction): "
                            : "Sets (dip/dip direction, friction): ";
  for (std::size_t k = 0; k < run.sets.size(); ++k) {
    const WedgeSetInput& s = run.sets[k];
    line += (k ? ", " : "") + s.id + " " + storage::report_number(s.dip_deg, 1) + "°/" +
            storage::report_number(s.dipdir_deg, 1) + "°" +
            (s.friction_deg ? " " + storage::report_number(*s.friction_deg, 1) + "°" : "");
  }
  return line;
}

std::string wedge_support_line(const WedgeRun& run) {
  std::string line;
  if (const auto& b = run.options.bolts)
    line += "bolts " + storage::report_number(b->length, 1) + " m long, " +
            storage::report_number(b->spacing, 1) + " m apart, " +
            storage::report_number(b->capacity / 1000, 0) + " kN each";
  if (const auto& c = run.options.shotcrete)
    line += (line.empty() ? "" : "; ") + std::string("shotcrete ") +
            storage::report_number(c->thickness * 1000, 0) + " mm, shear strength " +
            storage::report_number(c->shear_strength / 1e6, 1) + " MPa";
  return "Support: " + (line.empty() ? std::string("none") : line);
}

tunnel::WedgeAnalysis run_wedges(const WedgeRun& run) {
  std::vector<tunnel::WedgeJointSet> sets;
  for (const auto& s : run.sets) sets.push_back(joint_set(s));
  tunnel::WedgeAnalysis a =
      tunnel::analyse_wedges(run.profile, run.frame, run.datum, sets, run.options);
  a.notes.insert(a.notes.begin(), run.notes.begin(), run.notes.end());
  return a;
}

}  // namespace rockface::app
