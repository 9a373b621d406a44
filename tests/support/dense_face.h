#pragma once
// A densely mapped tunnel face for tests: a vertical face 20 x 10 m (the
// plane y = 0, rock to the north) mapped trace by trace, each trace with a
// joint plane of its own measured from it. The planes scatter (dip +-4,
// dip direction +-6 degrees) about three sets, 60/200, 75/110 and 20/350,
// as the poles of single traces do; each trace runs 2-8 m along its plane's
// line on the face, cut at the face's edges. Deterministic for a seed.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/orientation.h"

namespace rockface::test {

struct DenseFaceTrace {
  std::string id, joint;  // "T7", "J7"
  double dip = 0, dipdir = 0, friction = 30;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // on the plane and the face
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
};

struct DenseFace {
  double width = 20, height = 10;  // m, along x and z
  std::vector<DenseFaceTrace> traces;
  std::vector<Eigen::Vector3d> polygon() const {
    return {{0, 0, 0}, {width, 0, 0}, {width, 0, height}, {0, 0, height}};
  }
};

inline DenseFace dense_face(int traces, unsigned seed = 5) {
  DenseFace face;
  std::mt19937 rng(seed);
  std::normal_distribution<double> dip_scatter(0, 4), dipdir_scatter(0, 6);
  std::uniform_real_distribution<double> along_x(1, face.width - 1), along_z(1, face.height - 1),
      half_length(1, 4);
  const double sets[3][2] = {{60, 200}, {75, 110}, {20, 350}};
  for (int i = 0; i < traces; ++i) {
    DenseFaceTrace t;
    t.id = "T" + std::to_string(i + 1);
    t.joint = "J" + std::to_string(i + 1);
    t.dip = std::clamp(sets[i % 3][0] + dip_scatter(rng), 1.0, 89.0);
    t.dipdir = std::fmod(sets[i % 3][1] + dipdir_scatter(rng) + 360, 360);
    t.friction = 30 + i % 5;
    const Eigen::Vector3d n = geometry::plane_normal_deg(t.dip, t.dipdir);
    t.point = {along_x(rng), 0, along_z(rng)};
    // The plane's line on the face y = 0: along (n_z, 0, -n_x).
    const Eigen::Vector3d along = Eigen::Vector3d(n.z(), 0, -n.x()).normalized();
    // Cut at the face's edges: the largest run inside the face on each side.
    auto reach = [&](double sign) {
      double s = half_length(rng);
      for (int k = 0; k < 3; ++k) {
        if (along[k] == 0 || k == 1) continue;
        const double limit = (sign * along[k] > 0 ? (k == 0 ? face.width : face.height) : 0);
        s = std::min(s, (limit - t.point[k]) / (sign * along[k]));
      }
      return t.point + sign * s * along;
    };
    t.from = reach(-1);
    t.to = reach(+1);
    face.traces.push_back(t);
  }
  return face;
}

}  // namespace rockface::test
