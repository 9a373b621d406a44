// The virtual view of an imported 3D image
// (core/photogrammetry/surface/virtual_view.h): every vertex's pixel is
// where its camera sees it, the view is drawn in the vertex colours, holes
// stay background.
#include "core/photogrammetry/surface/virtual_view.h"

#include <gtest/gtest.h>

#include "core/photogrammetry/surface/cloud_meshing.h"

namespace {

using namespace rockface::photogrammetry;

TEST(VirtualView, PixelsAreTheCameraProjectionAndColoursAreDrawn) {
  // A 1 x 1 m floor on a 2 cm grid, red, seen from above.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 50; ++i)
    for (int k = 0; k <= 50; ++k) points.emplace_back(0.02 * i, 0.02 * k, 0.001 * ((i * k) % 3));
  const auto mesh = mesh_point_cloud(points);
  const std::vector<std::array<std::uint8_t, 3>> red(points.size(), {200, 10, 10});
  VirtualViewInput in;
  in.vertices = &points;
  in.triangles = &mesh.triangles;
  in.colours = &red;
  in.centre = mesh.centroid;
  in.toward_viewer = mesh.normal.z() > 0 ? mesh.normal : Eigen::Vector3d(-mesh.normal);
  in.point_spacing = mesh.median_spacing;
  const VirtualView view = render_virtual_view(in);
  ASSERT_EQ(view.pixels.size(), points.size());
  // A pixel about the spacing: 1 m over 2 cm is about 50 px.
  EXPECT_GT(view.intrinsics.width, 256 - 1);  // the least side allowed
  for (std::size_t i = 0; i < points.size(); i += 37) {
    const Eigen::Vector3d c = view.pose.R * (points[i] - view.pose.centre);
    ASSERT_GT(c.z(), 0);  // in front of the camera
    // 1e-3 px: the float pixels of a projection in doubles.
    EXPECT_NEAR(view.pixels[i].x(), view.intrinsics.fx * c.x() / c.z() + view.intrinsics.cx, 1e-3);
    EXPECT_NEAR(view.texcoords[i][0] * static_cast<float>(view.intrinsics.width),
                view.pixels[i].x(), 1e-2);
  }
  // The middle of the view is the floor's red (BGR); a corner outside the
  // floor's projection is the hole grey.
  const cv::Vec3b mid = view.image.at<cv::Vec3b>(view.image.rows / 2, view.image.cols / 2);
  EXPECT_EQ(mid, cv::Vec3b(10, 10, 200));
  EXPECT_EQ(view.image.at<cv::Vec3b>(0, 0), cv::Vec3b(96, 96, 96));
}

}  // namespace
