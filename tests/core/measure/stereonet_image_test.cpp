// The stereonet picture: poles land where the projection puts them, in the
// colour of their set; the kinematic zone is shaded where planes slide.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/common/units.h"
#include "core/measure/stereonet_image.h"

namespace rm = rockface::measure;
namespace rg = rockface::geometry;
using rockface::deg_to_rad;

namespace {

cv::Vec3b colour_at(const cv::Mat& img, const Eigen::Vector2d& p) {
  return img.at<cv::Vec3b>(static_cast<int>(std::lround(p.y())),
                           static_cast<int>(std::lround(p.x())));
}

cv::Vec3b bgr(const cv::Scalar& s) {
  return cv::Vec3b(static_cast<std::uint8_t>(s[0]), static_cast<std::uint8_t>(s[1]),
                   static_cast<std::uint8_t>(s[2]));
}

}  // namespace

TEST(StereonetImage, KnownPolesAreDrawnWhereTheyProject) {
  rm::StereonetPicture pic;
  pic.density_contours = false;
  pic.size_px = 600;
  // A horizontal plane's pole is the centre; a vertical plane dipping east
  // has its pole on the primitive at west (lower hemisphere); 60/180 plots
  // north of the centre at r = sqrt(2) sin(30 deg).
  const rg::PlaneOrientation planes[] = {
      {0, 0}, {deg_to_rad(60), deg_to_rad(180)}, {deg_to_rad(45), deg_to_rad(45)}};
  for (int i = 0; i < 3; ++i) {
    pic.poles.push_back(rg::plane_normal(planes[i]));
    pic.pole_sets.push_back(i);
  }
  const cv::Mat img = rm::render_stereonet(pic);
  ASSERT_EQ(img.rows, 600);
  const Eigen::Vector2d expected[] = {
      {0, 0},
      {0, std::sqrt(2.0) * std::sin(deg_to_rad(30))},
      {-std::sqrt(2.0) * std::sin(deg_to_rad(22.5)) * std::sqrt(0.5),
       -std::sqrt(2.0) * std::sin(deg_to_rad(22.5)) * std::sqrt(0.5)}};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector2d net = rg::project_pole(planes[i], pic.projection, pic.hemisphere);
    EXPECT_LT((net - expected[i]).norm(), 1e-12) << "pole " << i;
    if (i == 0) continue;  // the centre cross is drawn over the first pole
    EXPECT_EQ(colour_at(img, rm::net_to_pixel(net, 600)), bgr(rm::set_colour(i))) << "pole " << i;
  }
  // The net's centre is the picture's centre; the primitive has radius 0.4 size.
  EXPECT_LT((rm::net_to_pixel({0, 0}, 600) - Eigen::Vector2d(299.5, 299.5)).norm(), 1e-12);
  EXPECT_LT((rm::net_to_pixel({1, 0}, 600) - Eigen::Vector2d(539.5, 299.5)).norm(), 1e-12);
}

TEST(StereonetImage, SlidingZoneIsShadedForTheFreeFace) {
  rm::StereonetPicture pic;
  pic.density_contours = false;
  pic.size_px = 400;
  pic.kinematics = rm::KinematicOverlay{{deg_to_rad(70), deg_to_rad(180)}, deg_to_rad(30)};
  const cv::Mat img = rm::render_stereonet(pic);
  const cv::Vec3b shade(210, 210, 255);
  // A 50/180 plane slides out of a 70/180 face with 30 deg friction: its pole
  // is shaded. 20/180 (below friction) and 50/090 (outside the lateral limit)
  // are not, nor is 80/180 (steeper than the face: does not daylight).
  auto at = [&](double dip, double dipdir) {
    return colour_at(img, rm::net_to_pixel(rg::project_pole({deg_to_rad(dip), deg_to_rad(dipdir)},
                                                            pic.projection, pic.hemisphere),
                                           400));
  };
  EXPECT_EQ(at(50, 180), shade);
  EXPECT_NE(at(20, 180), shade);
  EXPECT_NE(at(50, 90), shade);
  EXPECT_NE(at(80, 180), shade);
}

TEST(StereonetImage, BadInputIsRefused) {
  rm::StereonetPicture pic;
  pic.size_px = 100;
  EXPECT_THROW(rm::render_stereonet(pic), rockface::InputError);
  pic.size_px = 400;
  pic.poles = {Eigen::Vector3d::UnitZ()};
  pic.pole_sets = {0, 1};
  EXPECT_THROW(rm::render_stereonet(pic), rockface::InputError);
}
