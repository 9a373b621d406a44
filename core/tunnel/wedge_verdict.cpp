// A built wedge's verdict: its traces on the excavation, its place around
// the section, its mass, mode and factors of safety with and without the
// support that reaches it (wedge_analysis_phases.h).
#include <algorithm>
#include <cmath>

#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_bolt.h"
#include "core/kinematics/effects/effect_shotcrete.h"
#include "core/tunnel/wedge_analysis_phases.h"
#include "core/tunnel/wedge_support.h"

namespace rockface::tunnel::wedge_phases {

namespace {

bool support_here(const SupportPlaces& s, WedgePlace p) {
  switch (p) {
    case WedgePlace::roof:
      return s.roof;
    case WedgePlace::right_wall:
    case WedgePlace::left_wall:
      return s.walls;
    case WedgePlace::floor:
      return s.floor;
    case WedgePlace::face:
      return s.face;
  }
  return false;
}

}  // namespace

// Length of each joint's trace on the excavation (edges between a joint
// face and a free face), in the order of the block's planes.
std::vector<std::pair<std::string, double>> traces_of(const blocks::Polyhedron& b) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& e : b.edges()) {
    const auto& pl = b.planes()[b.faces()[e.left].plane];
    const auto& pr = b.planes()[b.faces()[e.right].plane];
    if ((pl.kind == blocks::PlaneKind::FreeFace) == (pr.kind == blocks::PlaneKind::FreeFace))
      continue;
    const std::string& joint = pl.kind == blocks::PlaneKind::Joint ? pl.name : pr.name;
    const double len = (b.vertices()[e.v1] - b.vertices()[e.v0]).norm();
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& p) { return p.first == joint; });
    if (it == out.end())
      out.emplace_back(joint, len);
    else
      it->second += len;
  }
  return out;
}

double longest(const std::vector<std::pair<std::string, double>>& t) {
  double m = 0;
  for (const auto& [id, len] : t) m = std::max(m, len);
  return m;
}

WedgePlace place_of(double angle_deg) {
  double a = std::fmod(angle_deg + 360.0, 360.0);
  if (a >= 45 && a <= 135) return WedgePlace::roof;
  if (a > 135 && a < 225) return WedgePlace::left_wall;
  if (a >= 225 && a <= 315) return WedgePlace::floor;
  return WedgePlace::right_wall;
}

// Mass, mode, factors of safety and support of a built wedge.
void analyse_wedge(const Context& c, Wedge& w, const std::vector<WedgePlane>& planes,
                   const Eigen::Vector3d& apex_local) {
  std::vector<kinematics::JointStrength> strengths;
  for (const auto& p : w.block.planes()) {
    kinematics::JointStrength s;
    if (p.kind == blocks::PlaneKind::Joint && p.index >= 0 &&
        p.index < static_cast<int>(c.sets.size())) {
      s.friction = c.sets[p.index].friction;
      s.cohesion = c.sets[p.index].cohesion;
    }
    strengths.push_back(s);
  }
  kinematics::BlockAnalysisInput in;
  in.density = c.options.density;
  in.strengths = strengths;
  in.effects = &c.loads;
  in.uncertainty = c.options.uncertainty;
  const kinematics::BlockAnalysis a = kinematics::analyse_block(w.block, in);
  w.mass = a.mass;
  w.weight = a.mass.mass * c.options.gravity.norm();
  w.effects_used = a.effects_used;
  w.notes.insert(w.notes.end(), a.notes.begin(), a.notes.end());
  const std::vector<kinematics::ContactPlane> contacts =
      kinematics::block_contacts(w.block, a.mass, strengths);
  if (a.mode)
    w.mode = a.mode;
  else if (w.removable.value || w.removable.marginal)
    w.mode = kinematics::sliding_mode(a.force, contacts, c.options.uncertainty);
  if (w.mode) w.fos = w.mode->fos;
  w.load_resultant = a.force;
  w.contacts = contacts;
  w.face_perimeter = kinematics::free_face_outline(w.block);
  for (std::size_t f = 0; f < w.block.faces().size(); ++f)
    if (w.block.planes()[w.block.faces()[f].plane].kind == blocks::PlaneKind::FreeFace)
      w.face_area += a.mass.face_areas[f];
  if (w.face_area > 0) w.weight_pressure = w.weight / w.face_area;
  if (!w.mode || !(c.options.bolts || c.options.shotcrete)) return;

  Eigen::Vector3d support = Eigen::Vector3d::Zero();
  if (c.options.bolts) {
    std::vector<Eigen::Vector3d> inward;
    for (const auto& p : planes) inward.push_back(p.inward());
    w.bolts = pattern_bolts_on_wedge(*c.options.bolts, w.block, c.section, c.frame,
                                     w.place == WedgePlace::face, apex_local, inward);
    for (std::size_t i = 0; i < w.bolts.size(); ++i) {
      const WedgeBolt& b = w.bolts[i];
      if (!(b.force > 0)) continue;
      const kinematics::BoltEffect bolt("bolt " + std::to_string(i + 1), b.head, b.direction,
                                        b.force);
      const kinematics::EffectLoad l = bolt.load(w.block, a.mass);
      if (!l.acts) continue;
      support += l.force;
      w.bolt_force += b.force;
      ++w.bolts_anchored;
    }
    if (w.bolts_anchored > 0) w.effects_used.push_back("bolts");
    const int short_bolts = static_cast<int>(w.bolts.size()) - w.bolts_anchored;
    if (short_bolts > 0)
      w.notes.push_back(std::to_string(short_bolts) + " of the " + std::to_string(w.bolts.size()) +
                        " pattern bolts on it end inside the wedge: they hold nothing");
  }
  if (c.options.shotcrete && support_here(c.options.shotcrete->places, w.place) &&
      w.mode->type != kinematics::ModeType::None) {
    const kinematics::ShotcreteEffect sc("shotcrete", c.options.shotcrete->thickness,
                                         c.options.shotcrete->shear_strength, w.mode->direction);
    const kinematics::EffectLoad l = sc.load(w.block, a.mass);
    if (l.acts) {
      support += l.force;
      w.shotcrete_force = l.force.norm();
      w.effects_used.push_back("shotcrete");
    }
  }
  const SupportedFos s = supported_fos(*w.mode, contacts, a.force, support);
  w.fos_supported = s.fos;
  for (int p : s.lifted_planes)
    for (const auto& bp : w.block.planes())
      if (bp.index == p && bp.kind == blocks::PlaneKind::Joint)
        w.notes.push_back("the support lifts the wedge off " + bp.name);
  if (w.face_area > 0) w.support_pressure = (w.bolt_force + w.shotcrete_force) / w.face_area;
}

}  // namespace rockface::tunnel::wedge_phases
