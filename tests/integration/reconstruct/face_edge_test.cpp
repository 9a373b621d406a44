// Issue 38, "The 3D image beyond the rock": a face photographed against a
// featureless dark background must not grow a sheet of surface off its edge
// into the background. The synthetic face (three facets from 2.5 m below to
// 3.5 m above the cameras' height, 10 m away) ends inside the frame at its
// top and bottom; above and below it the mock camera renders its dark
// background with the sensor's noise. The truth of where the rock ends is
// the renderer's own depth image of the left view (0 where the ray meets
// nothing), not the reconstruction under test: every vertex of the 3D image
// is looked up at its pixel in the left photograph.
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/synthetic_truth.h"

namespace rp = rockface::photogrammetry;

namespace {

struct BeyondTheRock {
  std::size_t vertices = 0, beyond = 0;
  double area_m2 = 0, beyond_area_m2 = 0;  // of the triangles; beyond: all three vertices
  double farthest_px = 0;                  // from the nearest rock pixel, full-size px
};

// Whether the left photograph sees rock within `margin` px of `px`.
bool rock_near(const cv::Mat& depth, const Eigen::Vector2f& px, int margin) {
  const int x = static_cast<int>(std::lround(px.x())), y = static_cast<int>(std::lround(px.y()));
  for (int dy = -margin; dy <= margin; ++dy)
    for (int dx = -margin; dx <= margin; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) continue;
      if (depth.at<float>(v, u) > 0) return true;
    }
  return false;
}

BeyondTheRock beyond_the_rock(const rp::SurfaceMesh& mesh, const cv::Mat& depth, int margin) {
  BeyondTheRock out;
  out.vertices = mesh.vertices.size();
  std::vector<char> beyond(mesh.vertices.size(), 0);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (rock_near(depth, mesh.pixels[i], margin)) continue;
    beyond[i] = 1;
    ++out.beyond;
    // How far into the background: the nearest rock pixel, searched in
    // rings up to 100 px.
    for (int r = margin + 1; r <= 100; ++r)
      if (rock_near(depth, mesh.pixels[i], r) || r == 100) {
        out.farthest_px = std::max(out.farthest_px, static_cast<double>(r));
        break;
      }
  }
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &a = mesh.vertices[static_cast<std::size_t>(t[0])],
                          &b = mesh.vertices[static_cast<std::size_t>(t[1])],
                          &c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    out.area_m2 += area;
    if (beyond[static_cast<std::size_t>(t[0])] && beyond[static_cast<std::size_t>(t[1])] &&
        beyond[static_cast<std::size_t>(t[2])])
      out.beyond_area_m2 += area;
  }
  return out;
}

void expect_no_sheet_beyond_the_rock(const rp::ReconstructionPreset& preset) {
  // Sensor noise sigma 2 grey levels and blur 0.6 px (synthetic_face's
  // noisy variant): the background is noise, not black.
  const auto scene = rockface::testing::synthetic_face(1200, 800, true, 2.0);
  rockface::NoProgress progress;
  const auto render = rockface::camera::render_scene(scene, progress);
  const rp::ReconstructionResult r =
      rp::reconstruct(render.images[0], render.images[1], render.intrinsics, render.intrinsics,
                      preset, rockface::testing::pole_and_compass(scene, render, 0.0), progress);
  // A vertex within half a matching window of the rock (plus the lattice
  // step), in full-size pixels, may carry the rock's disparity: the window
  // straddles the edge.
  const int margin = static_cast<int>(
      std::ceil((preset.sgbm_block_size / 2 + preset.lattice_step) / r.dense_scale));
  const BeyondTheRock b = beyond_the_rock(r.mesh, render.depth_left, margin);
  ASSERT_GT(b.vertices, 10000u) << preset.name;
  const double fraction = static_cast<double>(b.beyond) / static_cast<double>(b.vertices);
  std::cout << preset.name << ": " << b.beyond << " of " << b.vertices << " vertices ("
            << 100 * fraction << " %) more than " << margin
            << " px off the rock in the left photograph, up to " << b.farthest_px
            << " px; triangles beyond it " << b.beyond_area_m2 << " of " << b.area_m2 << " m2\n";
  // Issue 38 found 4.6 % (6.5 % at fast) of the points up to 0.84 m beyond
  // the face's edge. What may remain: specks of the background's noise the
  // speckle filter lets through (a region of fewer than 100 px is removed,
  // so a speck left is at most a few hundred px of ~900,000): 0.1 % of the
  // vertices, and no sheet: 0.1 % of the surface's area.
  EXPECT_LT(fraction, 0.001) << preset.name;
  EXPECT_LT(b.beyond_area_m2, 0.001 * b.area_m2) << preset.name;
}

}  // namespace

TEST(FaceEdge, NoSheetBeyondTheFaceIntoADarkBackgroundAtStandard) {
  expect_no_sheet_beyond_the_rock(rp::preset_standard());
}

TEST(FaceEdge, NoSheetBeyondTheFaceIntoADarkBackgroundAtFast) {
  expect_no_sheet_beyond_the_rock(rp::preset_fast());
}
