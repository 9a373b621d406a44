#include "core/analysis/support_check.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/number_format.h"
#include "core/kinematics/effects/effect_shotcrete.h"
#include "core/tunnel/support_ranges.h"
#include "core/tunnel/wedge_support.h"

namespace rockface::analysis {

namespace {

// The force bisection's steps: 60 halvings of [0, 10 MN] leave ~1e-11 N.
constexpr int kBisectionSteps = 60;

std::string kn(double n) {
  return format_significant(n / 1000.0, 3, " kN");
}
std::string m(double v) {
  return format_fixed(v, 2, " m");
}

// The smallest force f in [0, hi] with fos(f) >= target, none when fos(hi)
// falls short. fos is monotone in f where no plane lifts off; where the
// support lifts the block off a plane it can fall again, so the answer is
// checked at the end.
template <class Fos>
std::optional<double> required_force(const Fos& fos, double target, double hi) {
  if (!(fos(hi) >= target)) return std::nullopt;
  if (fos(0.0) >= target) return 0.0;
  double lo = 0;
  for (int i = 0; i < kBisectionSteps; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fos(mid) >= target ? hi : lo) = mid;
  }
  return hi;
}

double fos_or_zero(const tunnel::SupportedFos& s) {
  return s.fos.value_or(0.0);
}

}  // namespace

tunnel::WedgeOptions with_class_support(tunnel::WedgeOptions base, const SupportClass& c) {
  base.bolts.reset();
  base.shotcrete.reset();
  if (c.bolts) {
    tunnel::PatternBolts b;
    b.length = c.bolts->length_m;
    b.spacing = c.bolts->spacing_m;
    b.capacity = c.bolts->capacity_n;
    b.bond_strength = c.bolts->bond_n_per_m;
    base.bolts = b;
  }
  if (c.shotcrete_m > 0 && c.shotcrete_shear_pa) {
    tunnel::Shotcrete s;
    s.thickness = c.shotcrete_m;
    s.shear_strength = *c.shotcrete_shear_pa;
    s.places.face = false;  // the face's lining is the face support's
    base.shotcrete = s;
  }
  return base;
}

bool has_face_support(const SupportClass& c) {
  return c.face.bolts || (c.face.shotcrete_m > 0 && c.shotcrete_shear_pa);
}

tunnel::WedgeOptions with_class_face_support(tunnel::WedgeOptions base, const SupportClass& c) {
  base.bolts.reset();
  base.shotcrete.reset();
  base.perimeter = false;
  base.face = true;
  const tunnel::SupportPlaces face_only{false, false, false, true};
  if (c.face.bolts) {
    tunnel::PatternBolts b;
    b.length = c.face.bolts->length_m;
    b.spacing = c.face.bolts->spacing_m;
    b.capacity = c.face.bolts->capacity_n;
    b.bond_strength = c.face.bolts->bond_n_per_m;
    b.places = face_only;
    base.bolts = b;
  }
  if (c.face.shotcrete_m > 0 && c.shotcrete_shear_pa) {
    tunnel::Shotcrete s;
    s.thickness = c.face.shotcrete_m;
    s.shear_strength = *c.shotcrete_shear_pa;
    s.places = face_only;
    base.shotcrete = s;
  }
  return base;
}

WedgeSupportCheck check_wedge(const tunnel::Wedge& w, const SupportClass& c) {
  WedgeSupportCheck out;
  const double target = target_fos(c);
  // A face wedge is held by the face bolts (along the drive), the others
  // by the pattern of the roof and walls.
  const bool on_face = w.place == tunnel::WedgePlace::face;
  const std::optional<BoltPattern>& pattern = on_face ? c.face.bolts : c.bolts;
  const std::string bolts_name = on_face ? "face bolts" : "bolts";
  out.id = w.id;
  out.place = tunnel::wedge_place_name(w.place);
  out.volume_m3 = w.mass.volume;
  out.weight_n = w.weight;
  out.apex_depth_m = w.bolt_length_to_apex;
  out.mode = w.mode ? kinematics::mode_name(w.mode->type) : "none";
  out.fos_unsupported = w.fos;
  out.fos_supported = w.fos_supported ? w.fos_supported : w.fos;
  out.bolts = static_cast<int>(w.bolts.size());
  out.bolts_anchored = w.bolts_anchored;
  double anchorage = kMinBoltAnchorageM;
  if (pattern && pattern->bond_n_per_m)
    anchorage = std::max(anchorage, pattern->capacity_n / *pattern->bond_n_per_m);
  out.required_bolt_length_m = w.bolt_length_to_apex + anchorage;
  out.bolts_reach_past_apex = pattern && pattern->length_m > w.bolt_length_to_apex;

  // The capacity per bolt that, with every bolt of the pattern on it
  // anchored, brings it to the target (the shotcrete as the analysis
  // counted it, against the mode).
  if (w.mode && !w.bolts.empty()) {
    Eigen::Vector3d per_unit = Eigen::Vector3d::Zero();
    for (const auto& b : w.bolts) per_unit += b.direction;
    const Eigen::Vector3d lining = -w.shotcrete_force * w.mode->direction;
    auto fos = [&](double capacity) {
      return fos_or_zero(tunnel::supported_fos(*w.mode, w.contacts, w.load_resultant,
                                               capacity * per_unit + lining));
    };
    out.required_capacity_n = required_force(fos, target, tunnel::kBoltCapacityRange.hi);
  }

  const bool moves = w.mode && w.mode->type != kinematics::ModeType::None;
  out.below_target = moves && out.fos_supported && *out.fos_supported < target;
  if (moves && !out.fos_supported) out.below_target = true;  // no friction angle: not shown safe
  if (!out.below_target) return out;
  if (!pattern) {
    out.fixes.push_back(bolts_name + ": the class has none");
  } else if (w.bolts.empty()) {
    out.fixes.push_back("the " + std::string(on_face ? "face pattern" : "pattern") + " at " +
                        m(pattern->spacing_m) + " puts no bolt on its face (" +
                        format_significant(w.face_area, 3, " m²") + "): spot bolts");
  } else {
    if (!out.bolts_reach_past_apex || out.bolts_anchored < out.bolts)
      out.fixes.push_back(bolts_name + " of at least " + m(out.required_bolt_length_m) + " (apex " +
                          m(w.bolt_length_to_apex) + " deep, plus anchorage)");
    if (!out.required_capacity_n)
      out.fixes.push_back("no bolt capacity at " + m(pattern->spacing_m) +
                          " spacing holds it: a closer pattern or heavier support");
    else if (*out.required_capacity_n > pattern->capacity_n)
      out.fixes.push_back(bolts_name + " of at least " + kn(*out.required_capacity_n) + " at " +
                          m(pattern->spacing_m) + " spacing (the class's " +
                          kn(pattern->capacity_n) + ")");
  }
  if (!out.fos_supported) out.fixes.push_back("a friction angle of its joints to check it at all");
  return out;
}

BlockSupportCheck check_block(const MovingBlock& b, const SupportClass& c) {
  BlockSupportCheck out;
  const double target = target_fos(c);
  out.id = b.id;
  out.mode = kinematics::mode_name(b.mode.type);
  out.fos_unsupported = b.fos;
  const Eigen::Vector3d d = b.bolt_direction.normalized();
  double anchorage = kMinBoltAnchorageM;
  Eigen::Vector3d support = Eigen::Vector3d::Zero();
  const auto& bolts = c.face.bolts;
  if (bolts) {
    if (bolts->bond_n_per_m)
      anchorage = std::max(anchorage, bolts->capacity_n / *bolts->bond_n_per_m);
    // Whole bolts of the square pattern on the exposed face.
    out.bolts =
        static_cast<int>(std::floor(b.exposed_area_m2 / (bolts->spacing_m * bolts->spacing_m)));
    const double beyond = bolts->length_m - b.depth_m;
    if (beyond > 0 && out.bolts > 0) {
      double force = bolts->capacity_n;
      if (bolts->bond_n_per_m) force = std::min(force, *bolts->bond_n_per_m * beyond);
      out.bolts_anchored = out.bolts;
      // Each bolt as BoltEffect puts it on a block: its force along its
      // direction (where its head lies does not enter a translational FoS).
      support += out.bolts * force * d;
      out.bolt_force_n = out.bolts * force;
    } else if (out.bolts > 0) {
      out.notes.push_back("the face bolts (" + m(bolts->length_m) + ") end inside the block (" +
                          m(b.depth_m) + " deep): they hold nothing");
    }
  }
  if (c.face.shotcrete_m > 0 && b.mode.type != kinematics::ModeType::None) {
    if (!c.shotcrete_shear_pa) {
      out.notes.push_back("face shotcrete not counted: the class gives no shear strength");
    } else if (!(b.exposed_outline_m > 0)) {
      out.notes.push_back("face shotcrete not counted: the outline of the exposed face is unknown");
    } else {
      const kinematics::ShotcreteEffect lining("face shotcrete", c.face.shotcrete_m,
                                               *c.shotcrete_shear_pa, b.mode.direction);
      out.shotcrete_force_n = lining.capacity(b.exposed_outline_m);
      support -= out.shotcrete_force_n * b.mode.direction;
    }
  }
  out.required_bolt_length_m = b.depth_m + anchorage;
  const tunnel::SupportedFos s = tunnel::supported_fos(b.mode, b.contacts, b.loads, support);
  out.fos_supported = s.fos;
  const Eigen::Vector3d lining = -out.shotcrete_force_n * b.mode.direction;
  auto fos = [&](double total) {
    return fos_or_zero(tunnel::supported_fos(b.mode, b.contacts, b.loads, total * d + lining));
  };
  // Up to the face's area in bolts of the largest capacity (10 MN each at
  // a 1 m pattern): beyond that no face support of bolts is realistic.
  const double hi = tunnel::kBoltCapacityRange.hi * std::max(1.0, b.exposed_area_m2);
  out.required_face_force_n = required_force(fos, target, hi);

  const bool moves = b.mode.type != kinematics::ModeType::None;
  out.below_target = moves && (!out.fos_supported || *out.fos_supported < target);
  if (!out.below_target) return out;
  if (!out.required_face_force_n) {
    out.fixes.push_back("no face support along the drive holds it: remove it (scale) or pin it");
  } else {
    const double have = out.bolt_force_n;
    if (!bolts)
      out.fixes.push_back("face bolts: " + kn(*out.required_face_force_n) +
                          " in all along the drive (the class has none)");
    else if (out.bolts_anchored == 0 && out.bolts > 0)
      out.fixes.push_back("face bolts of at least " + m(out.required_bolt_length_m) +
                          " (the block is " + m(b.depth_m) + " deep)");
    else if (out.bolts == 0)
      out.fixes.push_back("the face pattern at " + m(bolts->spacing_m) +
                          " puts no whole bolt on it (" +
                          format_significant(b.exposed_area_m2, 3, " m²") + "): spot bolts, " +
                          kn(*out.required_face_force_n) + " in all");
    else
      out.fixes.push_back("face bolts of " + kn(*out.required_face_force_n) + " in all (now " +
                          kn(have) + ")");
  }
  if (!out.fos_supported) out.fixes.push_back("a friction angle of its joints to check it at all");
  return out;
}

SupportCheck check_support(const SupportClass& c, const tunnel::WedgeAnalysis* supported,
                           const std::vector<MovingBlock>& blocks,
                           const tunnel::WedgeAnalysis* face_supported) {
  SupportCheck out;
  out.class_name = c.name;
  out.target_fos = target_fos(c);
  if (supported) {
    int face_unmatched = 0;
    for (const auto& w : supported->wedges) {
      if (!w.mode) continue;  // not removable: nothing to hold
      const tunnel::Wedge* held = &w;
      if (w.place == tunnel::WedgePlace::face && has_face_support(c)) {
        // The same wedge (its sets and pyramid) under the face support.
        const tunnel::Wedge* match = nullptr;
        if (face_supported)
          for (const auto& f : face_supported->wedges)
            if (f.place == tunnel::WedgePlace::face && f.code == w.code && f.sets == w.sets &&
                f.mode)
              match = &f;
        if (match)
          held = match;
        else
          ++face_unmatched;
      }
      out.wedges.push_back(check_wedge(*held, c));
      out.wedges.back().id = w.id;  // the name the wedge list gives it
      if (out.wedges.back().below_target) ++out.below_target;
    }
    if (face_unmatched > 0)
      out.notes.push_back(std::to_string(face_unmatched) +
                          " face wedges checked without the class's face support (no wedge "
                          "analysis with it)");
  } else {
    out.notes.push_back("no wedge analysis: the class's pattern is not checked on wedges");
  }
  for (const auto& b : blocks) {
    out.blocks.push_back(check_block(b, c));
    if (out.blocks.back().below_target) ++out.below_target;
  }
  if (c.shotcrete_m > 0 && !c.shotcrete_shear_pa)
    out.notes.push_back("the class's shotcrete is not counted: it gives no shear strength");
  return out;
}

}  // namespace rockface::analysis
