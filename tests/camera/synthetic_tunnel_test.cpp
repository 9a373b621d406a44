#include "camera/synthetic_tunnel.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "core/common/error.h"

namespace rockface::camera {
namespace {

using Eigen::Vector3d;

tunnel::Alignment straight_north() {
  return tunnel::Alignment::from_elements({{0, {1000, 2000, 300}}, {100, {1000, 2100, 300}}}, {0},
                                          Vector3d(1000, 2000, 300));
}

TEST(RenderedTunnel, SectionTruthOfABumpOnACircleIsTheClosedForm) {
  const double radius = 3, depth = 0.3, a = 4.0, b = 6.5;
  const tunnel::DesignProfile circle = tunnel::circle_profile(radius);
  RenderedTunnelSpec spec;
  spec.breaks.push_back({10, 14, a, b, depth});
  // At the middle of the break's chainage the bump is d sin^2 over [a, b]:
  // area = integral d w (1 + d w / (2 R)) ds = d L / 2 + 3 d^2 L / (16 R).
  const double L = b - a;
  const double expected = depth * L / 2 + 3 * depth * depth * L / (16 * radius);
  const SectionTruth t = rendered_section_truth(spec, circle, 12.0);
  // Midpoint rule at 1 mm on a smooth integrand: error ~ (1e-3)^2 relative.
  EXPECT_NEAR(t.overbreak_m2, expected, 1e-5);
  EXPECT_EQ(t.underbreak_m2, 0);
  // Outside the break's chainage nothing.
  EXPECT_EQ(rendered_section_truth(spec, circle, 9.0).overbreak_m2, 0);
  // An underbreak of the same shape: d < 0 shrinks the area term.
  spec.breaks[0].depth_m = -depth;
  const SectionTruth u = rendered_section_truth(spec, circle, 12.0);
  EXPECT_NEAR(u.underbreak_m2, depth * L / 2 - 3 * depth * depth * L / (16 * radius), 1e-5);
}

TEST(RenderedTunnel, WallsLieOnTheDesignLineAwayFromTheBreaks) {
  const double radius = 3;
  const tunnel::Alignment alignment = straight_north();
  const tunnel::DesignProfile circle = tunnel::circle_profile(radius);
  RenderedTunnelSpec spec;
  spec.chainage_from = 10;
  spec.face_chainage = 14.25;
  spec.section_m = 0.5;
  spec.facet_m = 0.1;
  spec.breaks.push_back({11, 13, 4.0, 6.5, 0.3});
  const auto patches = rendered_tunnel_patches(spec, alignment, circle, "test");
  ASSERT_FALSE(patches.empty());
  EXPECT_EQ(patches.back().id, "FACE-4");
  int cols = 0;  // a facet every 0.1 m along each segment, its ends kept
  for (const auto& seg : circle.segments()) cols += static_cast<int>(std::ceil(seg.length() / 0.1));
  // Rows of 0.5 m to 14.0 m (half a section short of the face), then the
  // face's outline: 8 + 1; chainage 12 is a row.
  const int rows = 9;
  EXPECT_EQ(patches.size(), static_cast<std::size_t>(rows * cols * 2 + 4));
  double farthest = 0;
  for (std::size_t k = 0; k + 4 < patches.size(); ++k)
    for (const auto& v : patches[k].polygon) {
      // The axis runs north through the datum: distance in the (x, z) plane.
      const double r = std::hypot(v.x(), v.z());
      EXPECT_GE(r, radius - 1e-9);
      farthest = std::max(farthest, r);
    }
  // The break's crest (chainage 12, s 5.25) lies within half a facet
  // (0.05 m) of a vertex: sin^2 there is at least cos^2(pi 0.05 / 2.5) = 0.996.
  EXPECT_LE(farthest, radius + 0.3 + 1e-9);
  EXPECT_GT(farthest, radius + 0.3 * 0.996);
  // Without relief the face's four quarters lie in the section at chainage
  // 14.25 (y = 14.25 in the datum frame).
  for (std::size_t k = patches.size() - 4; k < patches.size(); ++k)
    for (const auto& v : patches[k].polygon) EXPECT_NEAR(v.y(), 14.25, 1e-9);
}

TEST(RenderedTunnel, AFaceWithReliefIsFourPlanarQuartersMeetingTheWalls) {
  const tunnel::DesignProfile horseshoe = tunnel::horseshoe_profile(3.0, 1.0, 5.0, -1.5);
  RenderedTunnelSpec spec;
  spec.chainage_from = 10;
  spec.face_chainage = 14;
  spec.face_relief_m = 0.4;
  const auto patches = rendered_tunnel_patches(spec, straight_north(), horseshoe, "test");
  std::vector<const camera::SyntheticPatch*> faces;
  for (const auto& p : patches)
    if (p.id.rfind("FACE", 0) == 0) faces.push_back(&p);
  ASSERT_EQ(faces.size(), 4u);
  for (const auto* f : faces) {
    // The apex bulges 0.4 m toward the cameras (toward smaller chainage).
    EXPECT_NEAR(f->polygon.front().y(), 14.0 - 0.4, 1e-9);
    // Planar: every vertex on the plane of the first three (1e-9 m: the
    // quarter is linear in u and v, so only rounding is left).
    const Vector3d n =
        (f->polygon[1] - f->polygon[0]).cross(f->polygon.back() - f->polygon[0]).normalized();
    for (const auto& v : f->polygon) EXPECT_NEAR(n.dot(v - f->polygon[0]), 0.0, 1e-9) << f->id;
  }
  // The walls' last row is the face's outline: every wall vertex nearest the
  // face is a vertex of a face quarter.
  for (std::size_t k = 0; k + 4 < patches.size(); ++k)
    for (const auto& v : patches[k].polygon) EXPECT_LE(v.y(), 14.0 + 1e-9);
}

TEST(RenderedTunnel, ARangeOffTheAlignmentIsRefusedByName) {
  RenderedTunnelSpec spec;
  spec.chainage_from = 95;
  spec.face_chainage = 105;
  try {
    rendered_tunnel_patches(spec, straight_north(), tunnel::circle_profile(3),
                            "scene: tunnel.render");
    FAIL() << "a range beyond chainage 100 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tunnel.render"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("off the alignment"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rockface::camera
