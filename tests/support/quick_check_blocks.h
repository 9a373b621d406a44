#pragma once
// The blocks of the quick checks (issue 17): random convex blocks of 4 to 12
// faces cut from planes tangent to a sphere, one to three of them free
// faces, the rest joints. Shared by tests/core/kinematics/rotation/quick_checks_test.cpp
// (verdicts and margins against a reference written by the code before the
// speed-ups) and tools/bench/quick_checks_bench.cpp (blocks per second).
//
// quick_checks_dump() writes every verdict and margin of finiteness,
// removability and corner / edge rotatability of one block, one item a line,
// numbers with 17 significant digits.
#include <cmath>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/blocks/polyhedron.h"
#include "core/kinematics/block_analysis.h"
#include "core/kinematics/rotation_input.h"
#include "core/kinematics/rotation_space.h"
#include "tests/support/rotation_blocks.h"

namespace rockface::test_rotation {

// `count` blocks with exactly `faces` faces (rejection sampling), the same
// for every run: mt19937 from the seed, raw 32-bit outputs only.
inline std::vector<blocks::Polyhedron> quick_check_blocks(int faces, int count,
                                                          unsigned seed = 17) {
  std::mt19937 gen(seed * 1000 + static_cast<unsigned>(faces));
  auto uniform = [&] { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };
  std::vector<blocks::Polyhedron> out;
  for (int trial = 0; trial < 400 * count && static_cast<int>(out.size()) < count; ++trial) {
    std::vector<Side> sides;
    const int free_faces = 1 + trial % 3;
    for (int i = 0; i < faces; ++i) {
      const double z = 2 * uniform() - 1, phi = 2 * M_PI * uniform();
      const double rho = std::sqrt(1 - z * z);
      const Eigen::Vector3d n(rho * std::cos(phi), rho * std::sin(phi), z);
      const double reach = 0.8 + 0.4 * uniform();
      sides.push_back(
          {(i < free_faces ? "F" : "J") + std::to_string(i), i >= free_faces, -n, reach * n});
    }
    try {
      blocks::Polyhedron p =
          convex_polyhedron("q" + std::to_string(faces) + "-" + std::to_string(out.size()), sides);
      if (static_cast<int>(p.faces().size()) == faces) out.push_back(std::move(p));
    } catch (const std::exception&) {
      // Not bounded with these planes: draw again.
    }
  }
  return out;
}

// Every block of the quick checks: `per_size` blocks of each size 4..12.
inline std::vector<blocks::Polyhedron> quick_check_mix(int per_size, unsigned seed = 17) {
  std::vector<blocks::Polyhedron> all;
  for (int faces = 4; faces <= 12; ++faces)
    for (auto& p : quick_check_blocks(faces, per_size, seed)) all.push_back(std::move(p));
  return all;
}

inline void dump_line(std::string& out, const char* fmt, auto... args) {
  char line[256];
  std::snprintf(line, sizeof line, fmt, args...);
  out += line;
  out += '\n';
}

inline void dump_verdict(std::string& out, const char* what, const geometry::Verdict& v) {
  dump_line(out, "%s %d %.17g %d", what, v.value ? 1 : 0, v.margin, v.marginal ? 1 : 0);
}

inline std::string quick_checks_dump(const blocks::Polyhedron& block,
                                     const kinematics::Finiteness& f,
                                     const kinematics::RotationAnalysis& r) {
  std::string out;
  dump_line(out, "block %s faces %d vertices %d", block.id().c_str(),
            static_cast<int>(block.faces().size()), static_cast<int>(block.vertices().size()));
  dump_line(out, "jp %.17g jp_ep %.17g", f.jp_margin, f.jp_ep_margin);
  dump_verdict(out, "finite", f.finite);
  dump_verdict(out, "removable", f.removable);
  for (const auto& c : r.corners) {
    dump_line(out, "corner %d limits %d voids %d margin %.17g", c.vertex,
              static_cast<int>(c.limits.size()), c.void_limits, c.signed_margin);
    dump_verdict(out, "rotatable", c.rotatable);
    dump_line(out, "rays %d", static_cast<int>(c.extreme_rays.size()));
    for (const auto& x : c.extreme_rays)
      dump_line(out, "ray %.17g %.17g %.17g", x.x(), x.y(), x.z());
    for (const auto& s : c.sliding) {
      dump_line(out, "sliding %d margin %.17g also %d", s.plane, s.signed_margin,
                static_cast<int>(s.also_sliding.size()));
      dump_verdict(out, "feasible", s.feasible);
    }
  }
  for (const auto& e : r.edges) {
    dump_line(out, "edge %d %d margin %.17g axis %.17g %.17g %.17g", e.vertices[0], e.vertices[1],
              e.signed_margin, e.axis.x(), e.axis.y(), e.axis.z());
    dump_verdict(out, "rotatable", e.rotatable);
  }
  return out;
}

}  // namespace rockface::test_rotation
