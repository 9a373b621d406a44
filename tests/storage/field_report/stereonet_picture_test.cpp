// The report's stereonet (issue 39): besides the poles, what a geologist
// reads a kinematic check from: the joints' great circles, a stored set's
// cones from its K and count, the friction circle of the weakest joint and
// the sliding zone of the largest face plane.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "core/geometry/stereonet.h"
#include "core/measure/joint_sets.h"
#include "core/measure/stereonet_image.h"
#include "storage/field_report/field_report_pictures.h"

namespace rockface::storage {
namespace {

FieldReport visit_with_a_face() {
  FieldReport r;
  r.visit_id = 1;
  r.joints = {{"J1", "S1", "traces T1", 60, 200, 32.0, 0.0},
              {"J2", "S1", "traces T2", 62, 204, 28.0, 0.0},
              {"J3", "", "traces T3", 20, 350, std::nullopt, std::nullopt}};
  for (const auto& j : r.joints)
    r.poles.push_back(geometry::plane_normal_deg(j.dip_deg, j.dipdir_deg));
  r.pole_sets = {0, 0, -1};
  // Stored as the project keeps a set: K and count, no alpha95.
  r.sets = {{"S1", 12, 61, 202, 80, std::nullopt, "stored"}};
  // The floor is the larger, but nothing slides out of a floor.
  // A wall whose plane came from its corners has no known dip direction.
  r.face_planes = {
      {"FLOOR", 2, 10, 50, true}, {"FACE", 80, 200, 40, true}, {"WALL", 90, 150, 60, false}};
  return r;
}

bool inked_near(const cv::Mat& img, const Eigen::Vector2d& p, int r) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = static_cast<int>(std::lround(p.x())) + dx,
                y = static_cast<int>(std::lround(p.y())) + dy;
      if (x >= 0 && y >= 0 && x < img.cols && y < img.rows &&
          img.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255))
        return true;
    }
  return false;
}

TEST(ReportStereonet, TheWeakestJointAndTheLargestFaceAreChecked) {
  const FieldReport r = visit_with_a_face();
  ASSERT_TRUE(stereonet_friction_deg(r));
  EXPECT_EQ(*stereonet_friction_deg(r), 28.0);  // J2's, the lower of the two given
  ASSERT_NE(stereonet_face(r), nullptr);
  EXPECT_EQ(stereonet_face(r)->label, "FACE");
  // Markland's zone is shaded (the picture's shade, core/measure): a 50/200
  // plane slides out of an 80/200 face with 28 deg friction.
  const int size = 600;
  const cv::Mat net = stereonet_picture(r, size);
  const Eigen::Vector2d p = measure::net_to_pixel(
      geometry::project_pole({deg_to_rad(50), deg_to_rad(200)}, geometry::Projection::EqualArea,
                             geometry::Hemisphere::Lower),
      size);
  EXPECT_EQ(
      net.at<cv::Vec3b>(static_cast<int>(std::lround(p.y())), static_cast<int>(std::lround(p.x()))),
      cv::Vec3b(210, 210, 255));
}

TEST(ReportStereonet, AStoredSetsConesComeFromItsKAndCount) {
  FieldReport r = visit_with_a_face();
  r.face_planes.clear();
  const int size = 600;
  const cv::Mat net = stereonet_picture(r, size);
  // The set's mean pole, and the points alpha95 (from K = 80, N = 12) and
  // the 95 % variability cone away from it towards the centre of the net:
  // each on a drawn circle, within 2 px (line width and rounding).
  const Eigen::Vector3d mean = geometry::plane_normal_deg(61, 202);
  const Eigen::Vector3d down = mean.z() > 0 ? Eigen::Vector3d(-mean) : mean;
  const Eigen::Vector3d towards_centre =
      (-Eigen::Vector3d::UnitZ() - down.dot(-Eigen::Vector3d::UnitZ()) * down).normalized();
  for (const double angle : {measure::alpha95_from(80, 12), measure::fisher_cone(80)}) {
    ASSERT_GT(angle, 0);
    ASSERT_LT(angle, deg_to_rad(45));
    const Eigen::Vector3d d = std::cos(angle) * down + std::sin(angle) * towards_centre;
    const Eigen::Vector2d px =
        measure::net_to_pixel(geometry::project_direction(d, geometry::Projection::EqualArea,
                                                          geometry::Hemisphere::Lower),
                              size);
    EXPECT_TRUE(inked_near(net, px, 2)) << rad_to_deg(angle) << " deg";
  }
}

}  // namespace
}  // namespace rockface::storage
