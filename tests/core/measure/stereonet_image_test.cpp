// The stereonet picture: poles land where the projection puts them, in the
// colour of their set; the kinematic zone is shaded where planes slide.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

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

// The lower-hemisphere equal-area point of a downward direction, written
// here from the projection's definition (Lisle & Leyshon, Stereographic
// projection techniques, 2004: r = sqrt(2) sin(theta / 2), theta the angle
// from the downward vertical), not from core/geometry.
Eigen::Vector2d schmidt(const Eigen::Vector3d& d) {
  const Eigen::Vector3d down = d.z() > 0 ? Eigen::Vector3d(-d) : d;
  const double theta = std::acos(std::clamp(-down.z(), -1.0, 1.0));
  const double h = std::hypot(down.x(), down.y());
  if (h == 0) return {0, 0};
  return std::sqrt(2.0) * std::sin(theta / 2) * Eigen::Vector2d(down.x() / h, down.y() / h);
}

// Whether the picture has ink (not white paper) within `r` px of `p`.
bool inked_near(const cv::Mat& img, const Eigen::Vector2d& p, int r) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = static_cast<int>(std::lround(p.x())) + dx,
                y = static_cast<int>(std::lround(p.y())) + dy;
      if (x < 0 || y < 0 || x >= img.cols || y >= img.rows) continue;
      if (img.at<cv::Vec3b>(y, x) != cv::Vec3b(255, 255, 255)) return true;
    }
  return false;
}

TEST(StereonetImage, AJointsGreatCircleIsDrawnNinetyDegreesFromItsPole) {
  // Issue 39: the great circle of every joint, not only of the sets' means.
  const rg::PlaneOrientation plane{deg_to_rad(60), deg_to_rad(200)};
  const Eigen::Vector3d pole = rg::plane_normal(plane);
  // The circle's points as core/geometry projects them: each one back on
  // the sphere is perpendicular to the pole (1e-9: the projection and its
  // inverse are closed forms).
  for (const auto& p :
       rg::project_great_circle(plane, rg::Projection::EqualArea, rg::Hemisphere::Lower)) {
    const auto d = rg::direction_at(p, rg::Projection::EqualArea, rg::Hemisphere::Lower);
    ASSERT_TRUE(d);
    EXPECT_NEAR(d->dot(pole), 0, 1e-9);
  }
  rm::StereonetPicture pic;
  pic.density_contours = false;
  pic.size_px = 600;
  pic.poles = {pole};
  pic.plane_great_circles = true;
  const cv::Mat with = rm::render_stereonet(pic);
  pic.plane_great_circles = false;
  const cv::Mat without = rm::render_stereonet(pic);
  // The plane's directions at 90 degrees from the pole, by Rodrigues'
  // rotation of the dip direction's horizontal about the pole, projected by
  // the formula above: each has the circle drawn within 2 px (the line's
  // width and rounding), and the picture without it has no ink there.
  const Eigen::Vector3d strike(std::cos(plane.dipdir), -std::sin(plane.dipdir), 0);
  int drawn = 0, checked = 0;
  for (int k = 1; k < 36; ++k) {
    const double t = rockface::kPi * k / 36;
    const Eigen::Vector3d d = std::cos(t) * strike + std::sin(t) * pole.cross(strike);
    ASSERT_NEAR(d.dot(pole), 0, 1e-12);
    const Eigen::Vector2d px = rm::net_to_pixel(schmidt(d), 600);
    // Away from the pole's dot and the net's centre cross, which ink anyway.
    if ((px - rm::net_to_pixel(schmidt(pole), 600)).norm() < 12) continue;
    if ((px - rm::net_to_pixel({0, 0}, 600)).norm() < 12) continue;
    if (schmidt(d).norm() > 1 - 12.0 / 240) continue;  // the primitive circle (radius 240 px)
    ++checked;
    drawn += inked_near(with, px, 2) && !inked_near(without, px, 1);
  }
  EXPECT_GT(checked, 25);
  EXPECT_EQ(drawn, checked);
}

TEST(StereonetImage, TheFrictionCircleLiesAtTheFrictionAngleFromTheVertical) {
  // Poles of planes dipping exactly phi lie phi from the downward vertical:
  // at r = sqrt(2) sin(phi / 2) on the net.
  rm::StereonetPicture pic;
  pic.density_contours = false;
  pic.size_px = 600;
  pic.friction = deg_to_rad(30);
  const cv::Mat img = rm::render_stereonet(pic);
  const double r = std::sqrt(2.0) * std::sin(deg_to_rad(15));
  for (int k = 0; k < 12; ++k) {
    const double a = 2 * rockface::kPi * k / 12 + 0.1;  // off the centre cross's arms
    const Eigen::Vector2d px = rm::net_to_pixel(r * Eigen::Vector2d(std::sin(a), std::cos(a)), 600);
    EXPECT_TRUE(inked_near(img, px, 1)) << k;
    // Inside it, at half its radius (44 px in), the paper is white.
    const Eigen::Vector2d in =
        rm::net_to_pixel(0.5 * r * Eigen::Vector2d(std::sin(a), std::cos(a)), 600);
    EXPECT_FALSE(inked_near(img, in, 1)) << k;
  }
}

TEST(StereonetImage, TheTitleLeavesTheNorthMarkUncovered) {
  // Issue 39: "joints, visit 1" was written over the net's N.
  for (int size : {400, 600, 900}) {
    rm::StereonetPicture pic;
    pic.density_contours = false;
    pic.size_px = size;
    pic.poles = {rg::plane_normal({deg_to_rad(40), deg_to_rad(120)})};
    const cv::Mat bare = rm::render_stereonet(pic);
    pic.title = "joints, visit 1 of the tunnel face at chainage 112";
    const cv::Mat titled = rm::render_stereonet(pic);
    cv::Mat changed;
    cv::compare(bare, titled, changed, cv::CMP_NE);
    cv::cvtColor(changed, changed, cv::COLOR_BGR2GRAY);
    const cv::Rect n = rm::north_label_box(size);
    cv::Mat grey;
    cv::cvtColor(bare, grey, cv::COLOR_BGR2GRAY);
    ASSERT_GT(cv::countNonZero(grey(n) != 255), 0) << "no N where north_label_box says";
    EXPECT_GT(cv::countNonZero(changed), 0) << "no title written";
    EXPECT_EQ(cv::countNonZero(changed(n)), 0) << "the title covers the N at " << size << " px";
    // And it stays in the picture: nothing written in its last column.
    EXPECT_EQ(cv::countNonZero(changed.col(size - 1)), 0);
  }
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
