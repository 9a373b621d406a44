#pragma once
// A small synthetic scene for camera tests: a tunnel face 6 m wide and 5 m
// high about 10 m from the stations, with a floor, two joints, a 2 m range
// pole with 0.25 m targets, and an 800 x 600 camera (fx 1200) so a render
// takes well under a second.
#include "camera/synthetic_scene.h"

namespace rockface::test {

inline camera::SyntheticScene small_tunnel_scene() {
  camera::SyntheticScene s;
  // The face leans back 0.5 m over its height; the floor runs up to it.
  s.patches.push_back({"S1", {{-3, 10, 0}, {3, 10, 0}, {3, 10.5, 5}, {-3, 10.5, 5}}});
  s.patches.push_back({"FLOOR", {{-3, 0, 0}, {3, 0, 0}, {3, 10, 0}, {-3, 10, 0}}});
  s.joints.push_back({"J1", Eigen::Vector3d(0.5, -0.3, 0.8).normalized(), {0, 10, 2}});
  s.joints.push_back({"J2", Eigen::Vector3d(-0.6, -0.2, 0.5).normalized(), {0.5, 10, 3}});
  s.camera.width = 800;
  s.camera.height = 600;
  s.camera.fx = s.camera.fy = 1200;
  s.camera.cx = 399.5;
  s.camera.cy = 299.5;
  s.camera.distortion = {-0.08, 0.03, 0.0005, -0.0003, 0.0};
  s.stations[0] = {{-0.9, 0, 1.6}, {0, 10, 2.2}};
  s.stations[1] = {{0.9, 0, 1.6}, {0, 10, 2.2}};
  s.range_pole = camera::SyntheticRangePole{{1.5, 8, 0.6}, 2.0, 0.25};
  s.effects.distortion = true;
  s.texture_seed = 7;
  return s;
}

}  // namespace rockface::test
