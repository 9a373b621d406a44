#include "core/tunnel/wedge_analysis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/common/degrees_per_radian.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/geometry/cone.h"
#include "core/geometry/orientation.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/effects/effect_gravity.h"
#include "core/kinematics/effects/effect_seismic.h"
#include "core/kinematics/effects/effect_water.h"
#include "core/kinematics/joint_pyramids.h"
#include "core/tunnel/support_ranges.h"
#include "core/tunnel/tolerances.h"
#include "core/tunnel/wedge_analysis_phases.h"
#include "core/tunnel/wedge_geometry.h"

namespace rockface::tunnel {

namespace {

kinematics::Effects load_effects(const WedgeOptions& o) {
  kinematics::Effects e;
  e.push_back(std::make_unique<kinematics::GravityEffect>(o.gravity));
  if (o.water)
    e.push_back(std::make_unique<kinematics::WaterEffect>(
        o.water->unit_weight, o.water->phreatic_point, o.water->phreatic_normal, o.water->sets));
  if (o.seismic) e.push_back(std::make_unique<kinematics::SeismicEffect>(*o.seismic));
  return e;
}

void check_options(const WedgeOptions& o) {
  // Each load named in its own message, within a range that no rock or
  // earthquake leaves: a value of 1e308 overflowed the wedge's weight and
  // was blamed on the shotcrete (issue 41).
  if (!(o.density >= kRockDensityRange.lo && o.density <= kRockDensityRange.hi))
    throw InputError("rock.density",
                     outside_range_text(o.density, kRockDensityRange, "a rock's density"));
  if (!o.gravity.allFinite() || !(o.gravity.norm() > 0) || o.gravity.norm() > 100)
    throw InputError("gravity", "must be a finite, non-zero acceleration of at most 100 m/s^2");
  if (o.seismic && !(o.seismic->allFinite() && o.seismic->stableNorm() <= kSeismicRange.hi))
    throw InputError("effects.seismic.acceleration",
                     outside_range_text(o.seismic->stableNorm(), kSeismicRange,
                                        "a pseudo-static acceleration's size"));
  if (o.water && !(o.water->unit_weight >= kWaterUnitWeightRange.lo &&
                   o.water->unit_weight <= kWaterUnitWeightRange.hi))
    throw InputError(
        "effects.water.unit_weight",
        outside_range_text(o.water->unit_weight, kWaterUnitWeightRange, "water's unit weight"));
  if (o.trace_length_limit && !(*o.trace_length_limit > 0))
    throw InputError("wedges.trace_length", "must be a positive number of metres");
  if (o.bolts) {
    const auto& b = *o.bolts;
    auto in_range = [](double v, const SupportRange& r, const char* field, const char* what) {
      if (!r.contains(v))
        throw InputError(std::string("wedges.support.bolts.") + field,
                         outside_range_text(v, r, what));
    };
    in_range(b.length, kBoltLengthRange, "length", "a bolt's length");
    in_range(b.spacing, kBoltSpacingRange, "spacing", "a bolt pattern's spacing");
    in_range(b.capacity, kBoltCapacityRange, "capacity", "a bolt's capacity");
    if (b.bond_strength)
      in_range(*b.bond_strength, kBoltBondRange, "bond_strength", "a bolt's bond strength");
  }
  if (o.shotcrete) {
    if (!(o.shotcrete->thickness > 0))
      throw InputError("wedges.support.shotcrete.thickness", "must be positive (m)");
    if (!(o.shotcrete->shear_strength > 0))
      throw InputError("wedges.support.shotcrete.shear_strength", "must be positive (Pa)");
  }
}

}  // namespace

const char* wedge_place_name(WedgePlace p) {
  switch (p) {
    case WedgePlace::roof:
      return "roof";
    case WedgePlace::right_wall:
      return "right wall";
    case WedgePlace::left_wall:
      return "left wall";
    case WedgePlace::floor:
      return "floor";
    case WedgePlace::face:
      return "face";
  }
  return "?";
}

TunnelFrame axis_frame(double trend, double plunge, const Eigen::Vector3d& origin,
                       const std::string& where) {
  if (!std::isfinite(trend) || !std::isfinite(plunge) || std::abs(plunge) > kPi / 2)
    throw InputError(where, "trend and plunge must be finite, the plunge within +-90 degrees");
  TunnelFrame f;
  f.origin = origin;
  f.along = geometry::line_direction({trend, plunge});
  const Eigen::Vector3d r = f.along.cross(Eigen::Vector3d::UnitZ());
  if (r.norm() < 1e-6)
    throw InputError(where, "a vertical axis is a shaft: its walls have no roof or floor");
  f.right = r.normalized();
  f.up = f.right.cross(f.along).normalized();
  return f;
}

namespace wedge_phases {

void check_sets(const std::vector<WedgeJointSet>& sets) {
  if (sets.size() < 3)
    throw InputError("sets",
                     "a wedge needs three joint sets; " + std::to_string(sets.size()) + " given");
  for (std::size_t i = 0; i < sets.size(); ++i)
    if (!sets[i].normal.allFinite() || !(sets[i].normal.norm() > 0.5))
      throw InputError("sets[" + std::to_string(i) + "]", "has no orientation");
}

DistinctSets distinct_sets(const std::vector<WedgeJointSet>& sets, double uncertainty) {
  DistinctSets out;
  const double same = std::max(uncertainty, kWedgeSameSetRad);
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const Eigen::Vector3d ni = sets[i].normal.normalized();
    bool merged = false;
    for (int k : out.kept) {
      const Eigen::Vector3d nk = sets[k].normal.normalized();
      // Poles, not normals: a plane and its flipped normal are one set.
      const double angle = std::atan2(ni.cross(nk).norm(), std::abs(ni.dot(nk)));
      if (angle > same) continue;
      out.notes.push_back("sets " + sets[k].id + " and " + sets[i].id +
                          " are one set (their poles " + format_fixed(angle * kDegPerRad, 1) +
                          " deg apart, within " + format_fixed(same * kDegPerRad, 1) +
                          " deg, the orientation uncertainty): " + sets[i].id +
                          " is left out, with its strength");
      merged = true;
      break;
    }
    if (!merged) out.kept.push_back(static_cast<int>(i));
  }
  if (out.kept.size() < 3)
    throw InputError("sets", "a wedge needs three distinct joint sets; " +
                                 std::to_string(sets.size()) + " given are " +
                                 std::to_string(out.kept.size()) + " within " +
                                 format_fixed(same * kDegPerRad, 1) + " deg of each other");
  if (out.kept.size() > static_cast<std::size_t>(kMaxWedgeSets))
    throw InputError("sets", std::to_string(out.kept.size()) +
                                 " distinct joint sets; a wedge analysis takes at most " +
                                 std::to_string(kMaxWedgeSets) +
                                 " (its work grows with the cube of the number of sets): "
                                 "choose the sets that matter");
  return out;
}

geometry::Cone face_excavation_pyramid(const TunnelFrame& frame) {
  kinematics::FreeFaceSpec face_spec;
  face_spec.normal = frame.along.z() >= 0 ? frame.along : Eigen::Vector3d(-frame.along);
  face_spec.rock_side =
      frame.along.z() >= 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
  return kinematics::excavation_pyramid({face_spec});
}

std::string code_text(std::size_t n, const std::vector<int>& idx, const std::vector<double>& sign) {
  std::string code(n, '2');
  for (std::size_t k = 0; k < idx.size(); ++k) code[idx[k]] = sign[k] > 0 ? '0' : '1';
  return code;
}

std::optional<NoWedge> parallel_sets(const std::vector<WedgeJointSet>& sets,
                                     const std::array<int, 3>& idx, double uncertainty) {
  const std::size_t n = sets.size();
  const auto [i, j, k] = idx;
  const double det = std::abs(sets[i].normal.dot(sets[j].normal.cross(sets[k].normal)));
  if (!(det < std::sin(uncertainty) * 1e-3)) return std::nullopt;
  const std::vector<std::string> ids{sets[i].id, sets[j].id, sets[k].id};
  NoWedge nw;
  nw.code = code_text(n, {i, j, k}, {1, 1, 1})
                .replace(static_cast<std::size_t>(i), 1, "*")
                .replace(static_cast<std::size_t>(j), 1, "*")
                .replace(static_cast<std::size_t>(k), 1, "*");
  nw.sets = ids;
  nw.reason = "sets " + ids[0] + ", " + ids[1] + " and " + ids[2] +
              " meet in one line (or two are parallel): they bound no wedge";
  return nw;
}

SetPyramid set_pyramid(const std::vector<WedgeJointSet>& sets, const std::array<int, 3>& idx,
                       int combination) {
  SetPyramid p;
  p.idx.assign(idx.begin(), idx.end());
  for (int m : idx) p.ids.push_back(sets[m].id);
  const int c = combination;
  p.sign = {(c & 4) ? -1.0 : 1.0, (c & 2) ? -1.0 : 1.0, (c & 1) ? -1.0 : 1.0};
  for (int m = 0; m < 3; ++m) {
    p.planes.push_back({p.idx[m], p.ids[m], sets[p.idx[m]].normal.normalized(), p.sign[m]});
    p.inward.push_back(p.planes.back().inward());
  }
  p.code = code_text(sets.size(), p.idx, p.sign);
  return p;
}

NoWedge unbuilt_wedge(const SetPyramid& p, double apex_out, const std::string& why) {
  // The two sets of the three whose poles are closest.
  double closest = kPi;
  std::size_t a = 0, b = 1;
  for (std::size_t i = 0; i < p.planes.size(); ++i)
    for (std::size_t j = i + 1; j < p.planes.size(); ++j) {
      const Eigen::Vector3d& ni = p.planes[i].normal;
      const Eigen::Vector3d& nj = p.planes[j].normal;
      const double angle = std::atan2(ni.cross(nj).norm(), std::abs(ni.dot(nj)));
      if (angle < closest) {
        closest = angle;
        a = i;
        b = j;
      }
    }
  const std::string pair =
      p.ids[a] + "/" + p.ids[b] + " at " + format_significant(closest * kDegPerRad, 3, " deg");
  NoWedge n;
  n.code = p.code;
  n.sets = p.ids;
  n.margin = 0;
  n.unbuilt = true;
  n.marginal = true;
  n.reason = "marginal: apex " + format_significant(apex_out, 3, " m") + " out (" +
             (closest < kWedgeNearParallelRad ? "near-parallel sets " + pair
                                              : "its closest sets " + pair) +
             "): its solid could not be built (" + why + ")";
  return n;
}

FoundWedge face_wedge(const Context& c, const SetPyramid& p,
                      const std::vector<Eigen::Vector3d>& edges, const geometry::Cone& face_ep) {
  FoundWedge out;
  const WedgeOptions& options = c.options;
  const TunnelFrame& frame = c.frame;
  if (!options.face) return out;
  std::vector<kinematics::JointSpec> js;
  std::vector<geometry::HalfSpace> hs(3);
  for (int m = 0; m < 3; ++m) {
    js.push_back({p.planes[m].normal, c.sets[p.idx[m]].friction});
    hs[m] = p.sign[m] > 0 ? geometry::HalfSpace::Upper : geometry::HalfSpace::Lower;
  }
  const kinematics::PyramidVerdict pv = kinematics::analyse_joint_pyramid(
      js, hs, face_ep, {options.uncertainty, Eigen::Vector3d::Zero()});
  if (!(pv.removable.value || pv.removable.marginal)) {
    out.none = NoWedge{p.code, p.ids, -pv.removable.margin,
                       "opens toward the tunnel but is not removable from the face: "
                       "its pyramid reaches into the rock ahead (by " +
                           format_fixed(pv.removable.margin * kDegPerRad, 1) + " deg)"};
    return out;
  }
  // Removable within the uncertainty only, with an edge of its pyramid
  // along the face or into the rock ahead: its wedge on the face has no
  // finite size (the triangle's corners divided by the edges' distance
  // behind the face, zero or negative, gave a solid that was "not
  // bounded", issue 40).
  for (const auto& e : edges)
    if (!(-e.dot(frame.along) > kWedgeAlongAxisSine * e.norm())) {
      out.none = NoWedge{p.code, p.ids, std::min(pv.removable.margin, 0.0),
                         "opens toward the tunnel but is removable from the face only within the "
                         "uncertainty (by " +
                             format_fixed(pv.removable.margin * kDegPerRad, 1) +
                             " deg): an edge of its pyramid runs along the face or into the rock "
                             "ahead, so its wedge there has no finite size"};
      return out;
    }
  const auto tri = face_unit_triangle(edges, frame);
  FaceFit fit = largest_face_triangle(c.section, tri);
  if (!(fit.scale > 0)) return out;
  Wedge w;
  w.code = p.code;
  w.sets = p.ids;
  double side = 0;
  for (const auto& a : tri)
    for (const auto& b : tri) side = std::max(side, (a - b).norm());
  if (options.trace_length_limit && fit.scale * side > *options.trace_length_limit) {
    Eigen::Vector2d mean = (tri[0] + tri[1] + tri[2]) / 3.0;
    const double s = *options.trace_length_limit / side;
    fit.offset += (fit.scale - s) * mean;
    w.scale = s / fit.scale;
    w.scaled = true;
    fit.scale = s;
  }
  w.place = WedgePlace::face;
  for (const auto& t : tri) w.outline.push_back(fit.offset + fit.scale * t);
  w.removable = pv.removable;
  const int first_free = static_cast<int>(c.sets.size());
  try {
    w.block = face_wedge_block(p.code, frame, c.datum, p.planes, fit, first_free + 1000);
  } catch (const std::exception& e) {
    out.none = unbuilt_wedge(p, fit.scale, e.what());
    return out;
  }
  const Eigen::Vector3d apex = frame.to_local(fit.offset.x(), fit.offset.y(), fit.scale);
  w.apex = apex + c.datum;
  w.apex_height = fit.scale;
  w.bolt_length_to_apex = fit.scale;
  const Eigen::Vector2d centre = fit.offset + fit.scale * (tri[0] + tri[1] + tri[2]) / 3.0;
  w.position_deg = std::atan2(centre.y() - c.centre.y(), centre.x() - c.centre.x()) * kDegPerRad;
  w.trace_lengths = traces_of(w.block);
  analyse_wedge(c, w, p.planes, apex);
  out.wedge = std::move(w);
  return out;
}

Eigen::Vector2d apex_at_trace_limit(
    const SectionPolygon& section, const std::vector<BasePiece>& base, const Eigen::Vector2d& q_max,
    double limit, const std::function<double(const Eigen::Vector2d&)>& longest_trace_at) {
  const Eigen::Vector2d mid = 0.5 * (base.front().a + base.back().b);
  auto at = [&](double l) { return Eigen::Vector2d(mid + l * (q_max - mid)); };
  double lo = 0, hi = 1;  // the apex reaches the outline at lo
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (lo + hi);
    (section.contains(at(m)) ? lo : hi) = m;
  }
  hi = 1;
  for (int it = 0; it < 60 && hi - lo > kWedgeTraceRel * (1 - lo); ++it) {
    const double m = 0.5 * (lo + hi);
    const double t = longest_trace_at(at(m));
    (t > limit ? hi : lo) = m;
  }
  return at(lo);
}

Eigen::Vector2d lay_out_on_perimeter(const SectionPolygon& section,
                                     const std::vector<BasePiece>& base, const Eigen::Vector2d& q,
                                     Wedge& w) {
  // Where its face lies: the area-weighted centre of its pieces.
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double len = 0;
  std::set<std::size_t> segs;
  for (std::size_t p = 0; p < base.size(); ++p) {
    const double l = (base[p].b - base[p].a).norm();
    centre += l * 0.5 * (base[p].a + base[p].b);
    len += l;
    for (std::size_t g : section.segments_under(base[p].edge, base[p].a, base[p].b)) segs.insert(g);
    if (p == 0) continue;
    // The outline vertex between this piece and the previous one.
    const std::size_t e1 = base[p - 1].edge, e2 = base[p].edge, m = section.size();
    const std::size_t first = (e1 + 1) % m == e2 ? e1 : e2;  // in the outline's order
    const std::size_t second = first == e1 ? e2 : e1;
    const auto& v = section.vertices[second];
    if ((first + 1) % m != second || !v.corner) continue;
    const std::size_t sa = section.vertices[first].segment, sb = v.segment;
    w.corners.push_back("crosses the profile's corner at (" + format_fixed(v.p.x(), 1) + ", " +
                        format_fixed(v.p.y(), 1) + ") m between segment " + std::to_string(sa + 1) +
                        " (" + section.segment_kinds[sa] + ") and segment " +
                        std::to_string(sb + 1) + " (" + section.segment_kinds[sb] + ")");
  }
  centre /= len;
  w.outline.push_back(q);
  w.outline.push_back(base.front().a);
  for (const auto& piece : base) w.outline.push_back(piece.b);
  w.segments.assign(segs.begin(), segs.end());
  return centre;
}

FoundWedge perimeter_wedge(const Context& c, const SetPyramid& p,
                           const std::vector<Eigen::Vector3d>& edges, double jp_margin) {
  FoundWedge out;
  const SectionPolygon& section = c.section;
  const WedgeOptions& options = c.options;
  const TunnelFrame& frame = c.frame;
  const int first_free = static_cast<int>(c.sets.size());
  const PyramidSector sector = pyramid_sector(edges, frame);
  if (!sector.pointed) {
    out.none = NoWedge{p.code, p.ids, sector.margin,
                       "seen along the axis its pyramid spans " +
                           format_fixed(sector.span * kDegPerRad, 1) +
                           " deg (180 or more): the wedge would run along the tunnel without end"};
    return out;
  }
  const Eigen::Vector2d q_max = largest_apex(section, sector);
  if (section.distance(q_max) <= kWedgeVertexMergeRel * (q_max.norm() + section.perimeter)) {
    // Both edges of the sector touch the outline at one point (an edge of
    // the pyramid runs along a straight side seen along the axis): the
    // largest wedge there has no size.
    out.none = NoWedge{p.code, p.ids, 0,
                       "its wedge has no size: seen along the axis an edge of its "
                       "pyramid runs along a straight side of the section"};
    return out;
  }
  auto build = [&](const Eigen::Vector2d& q, std::vector<BasePiece>& base) {
    base = visible_base(section, sector, q);
    return perimeter_wedge_block(p.code, frame, c.datum, p.planes, section, base, q, 0, first_free);
  };
  Wedge w;
  w.code = p.code;
  w.sets = p.ids;
  std::vector<BasePiece> base;
  Eigen::Vector2d q = q_max;
  try {
    w.block = build(q, base);
    w.trace_lengths = traces_of(w.block);
    if (options.trace_length_limit && longest(w.trace_lengths) > *options.trace_length_limit) {
      const double full = longest(w.trace_lengths);
      q = apex_at_trace_limit(section, base, q_max, *options.trace_length_limit,
                              [&](const Eigen::Vector2d& at) {
                                std::vector<BasePiece> b;
                                return longest(traces_of(build(at, b)));
                              });
      w.block = build(q, base);
      w.trace_lengths = traces_of(w.block);
      w.scaled = true;
      w.scale = longest(w.trace_lengths) / full;
    }
  } catch (const std::exception& e) {
    out.none = unbuilt_wedge(p, section.distance(q), e.what());
    return out;
  }
  w.removable = geometry::decide(std::min(jp_margin, sector.margin), options.uncertainty);
  const Eigen::Vector3d apex = frame.to_local(q.x(), q.y(), 0);
  w.apex = apex + c.datum;
  const Eigen::Vector2d c0 = base.front().a, cm = base.back().b;
  const Eigen::Vector2d chord = cm - c0;
  w.apex_height = chord.norm() > 0
                      ? std::abs(chord.x() * (q - c0).y() - chord.y() * (q - c0).x()) / chord.norm()
                      : (q - c0).norm();
  w.bolt_length_to_apex = section.distance(q);
  const Eigen::Vector2d centre = lay_out_on_perimeter(section, base, q, w);
  w.position_deg = std::atan2(centre.y() - c.centre.y(), centre.x() - c.centre.x()) * kDegPerRad;
  w.place = place_of(w.position_deg);
  w.notes.insert(w.notes.end(), w.corners.begin(), w.corners.end());
  analyse_wedge(c, w, p.planes, apex);
  out.wedge = std::move(w);
  return out;
}

void order_wedges(std::vector<Wedge>& wedges) {
  std::stable_sort(wedges.begin(), wedges.end(), [](const Wedge& a, const Wedge& b) {
    if (a.place != b.place) return a.place < b.place;
    return a.mass.volume > b.mass.volume;
  });
}

}  // namespace wedge_phases

double wedge_sagitta(Preset preset) {
  switch (preset) {
    case Preset::fast:
      return 0.01;
    case Preset::standard:
      return 0.002;
    case Preset::precise:
      return 0.0005;
  }
  return 0.002;
}

namespace {

// The sets with each plane that lies within kWedgeAxisParallelRad of
// containing the axis turned onto it (its normal made square to the axis),
// each such set said in notes.
std::vector<WedgeJointSet> axis_parallel_snapped(const std::vector<WedgeJointSet>& given,
                                                 const Eigen::Vector3d& along,
                                                 std::vector<std::string>& notes) {
  std::vector<WedgeJointSet> sets = given;
  for (auto& s : sets) {
    const Eigen::Vector3d n = s.normal.normalized();
    const double off = n.dot(along);  // sine of the angle between plane and axis
    if (off == 0 || std::abs(off) > std::sin(kWedgeAxisParallelRad)) continue;
    s.normal = (n - off * along).normalized();
    if (std::abs(off) <= kWedgeAlongAxisSine) continue;  // parallel but for rounding
    std::ostringstream note;
    note.precision(2);
    note << "set " << s.id << " lies within " << std::abs(std::asin(off)) * kDegPerRad
         << " deg of containing the tunnel's axis: taken as parallel to it";
    notes.push_back(note.str());
  }
  return sets;
}

}  // namespace

WedgeAnalysis analyse_wedges(const DesignProfile& profile, const TunnelFrame& frame,
                             const Eigen::Vector3d& datum,
                             const std::vector<WedgeJointSet>& given_sets,
                             const WedgeOptions& options) {
  using namespace wedge_phases;
  check_sets(given_sets);
  std::vector<std::string> axis_notes;
  const std::vector<WedgeJointSet> sets =
      axis_parallel_snapped(given_sets, frame.along.normalized(), axis_notes);
  check_options(options);
  WedgeAnalysis out;
  out.frame = frame;
  // The wedges are built about the section's own origin: the blocks'
  // datum is the section's absolute position, so that their planes'
  // offsets are of the wedges' size, not of the section's distance from
  // the scene's datum (at 10 km or 5.2e6 m the half-spaces of a 1 m wedge
  // lost their digits and the pieces no longer joined, issue 40).
  TunnelFrame local = frame;
  local.origin = Eigen::Vector3d::Zero();
  const Eigen::Vector3d section_datum = datum + frame.origin;
  out.section = section_polygon(profile, options.sagitta_m, "profile");
  out.notes = out.section.notes;
  out.notes.insert(out.notes.end(), axis_notes.begin(), axis_notes.end());
  const kinematics::Effects loads = load_effects(options);
  for (const auto& e : loads) out.effects_simulated.push_back(e->name());
  if (options.bolts) out.effects_simulated.push_back("bolts");
  if (options.shotcrete) out.effects_simulated.push_back("shotcrete");
  const Context ctx{out.section, local, section_datum, sets, options, loads, profile.ray_centre()};
  const geometry::Cone face_ep = face_excavation_pyramid(local);

  // A pyramid without a wedge is marginal when its margin is inside the
  // uncertainty or its wedge could not be built (then it may well have one).
  auto no_wedge = [&](NoWedge n) {
    n.marginal = n.unbuilt || std::abs(n.margin) <= options.uncertainty;
    out.none.push_back(std::move(n));
  };
  auto found = [&](FoundWedge f) {
    if (f.none) no_wedge(std::move(*f.none));
    if (f.wedge) out.wedges.push_back(std::move(*f.wedge));
  };
  // Sets within the uncertainty of each other are one set: the others keep
  // their digit ('2') in every code, and no wedge is found twice.
  const DistinctSets distinct = distinct_sets(sets, options.uncertainty);
  out.notes.insert(out.notes.end(), distinct.notes.begin(), distinct.notes.end());
  const std::vector<int>& kept = distinct.kept;
  const std::size_t n = kept.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const std::array<int, 3> idx{kept[i], kept[j], kept[k]};
        if (auto none = parallel_sets(sets, idx, options.uncertainty)) {
          no_wedge(std::move(*none));
          continue;
        }
        for (int combination = 0; combination < 8; ++combination) {
          const SetPyramid p = set_pyramid(sets, idx, combination);
          const geometry::Cone jp(p.inward);
          const geometry::ConeMargin jm = jp.margin();
          if (!(jm.angle > 0)) continue;  // independent planes: never empty
          const std::vector<Eigen::Vector3d> edges = jp.edges(jm.angle);
          // Inside, or on a face of the pyramid (a set containing the axis):
          // a face pyramid, whose wedge the face decides (removable or
          // not). A pyramid with an edge along the axis is a perimeter
          // pyramid that never ends, not a face one. (Taken as a perimeter
          // pyramid, one with the axis on its face spans 180 degrees seen
          // along the axis: its face wedge came and went with the sign of
          // a 1e-9 degree tilt of that set, issue 40.)
          const double back = jp.margin_of(-frame.along);
          bool edge_along = false;
          for (const auto& e : edges)
            edge_along = edge_along || (e - e.dot(frame.along) * frame.along).norm() <
                                           kWedgeAlongAxisSine * e.norm();
          if (back > kWedgeAlongAxisSine || (back > -kWedgeAlongAxisSine && !edge_along)) {
            found(face_wedge(ctx, p, edges, face_ep));
            continue;
          }
          if (jp.margin_of(frame.along) > kWedgeAlongAxisSine)
            continue;  // opens into the rock ahead of the face
          if (!options.perimeter) continue;
          FoundWedge around = perimeter_wedge(ctx, p, edges, jm.angle);
          // A pyramid that gives no perimeter wedge (seen along the axis it
          // spans 180 degrees or more, or its wedge has no size) but lies
          // wholly behind the face is a face wedge: with a set near the
          // axis, the pyramid whose face on that set just misses the axis
          // (the face wedge came with a turn of the set by 0.01 degree one
          // way and went with the same turn the other way, issue 40).
          bool behind = !edge_along;
          for (const auto& e : edges)
            behind = behind && e.dot(frame.along) < -kWedgeAlongAxisSine * e.norm();
          if (!around.wedge && around.none && !around.none->unbuilt && around.none->margin <= 0 &&
              behind && options.face) {
            FoundWedge at_face = face_wedge(ctx, p, edges, face_ep);
            if (at_face.wedge) around = std::move(at_face);
          }
          found(std::move(around));
        }
      }
  // A wedge whose apex lies within the chords' sagitta of the excavation
  // is smaller than the section is drawn: it may be an artefact of the
  // chords, and its factor of safety (15.9 on a 4e-7 m3 sliver with a
  // margin of 30 degrees) is not one to trust. It is left out of the
  // wedges (and so of their support) and listed, marginal, with its size
  // among the pyramids without a wedge (issue 40).
  std::vector<Wedge> kept_wedges;
  for (Wedge& w : out.wedges) {
    if (!(w.apex_height <= options.sagitta_m)) {
      kept_wedges.push_back(std::move(w));
      continue;
    }
    no_wedge(NoWedge{
        w.code, w.sets, 0,
        "a sliver of " + format_significant(w.mass.volume, 2) + " m3 at the " +
            wedge_place_name(w.place) + ": its apex lies " + format_fixed(w.apex_height * 1000, 2) +
            " mm from the excavation, within the " + format_fixed(options.sagitta_m * 1000, 1) +
            " mm to which the section is drawn; left out"});
  }
  out.wedges = std::move(kept_wedges);
  order_wedges(out.wedges);
  for (std::size_t i = 0; i < out.wedges.size(); ++i) {
    // Built by appending: "W" + number trips GCC 12's false -Wrestrict
    // (a string's replace, inlined at -O3) in this function.
    std::string id("W");
    id.append(std::to_string(i + 1));
    out.wedges[i].id = std::move(id);
  }
  if (out.wedges.empty())
    out.notes.push_back("no removable wedge: " +
                        (out.none.empty() ? std::string("the sets form none around this section")
                                          : out.none.front().reason));
  return out;
}

}  // namespace rockface::tunnel
