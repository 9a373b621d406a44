// Issue 38: a visit whose round saw no wall or roof (or lies off the
// alignment) has no over- or underbreak figures: they are unknown (null in
// `rockface profile --json`), never 0; and the developed view's message
// stays inside the picture.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/tunnel/design_profile.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/field_report/tunnel_pictures.h"

namespace rockface::app {
namespace {

VisitProfile unmeasured(tunnel::DeviationStatus status) {
  VisitProfile v;
  v.tunnel.name = "Main drive";
  v.deviation.status = status;
  v.deviation.message =
      "no section of the round saw the walls or the roof: the 3D image holds the face only, so "
      "there is nothing to compare with the design profile (photograph the walls behind the face "
      "as well)";
  return v;
}

TEST(VisitProfileJson, NoWallsInViewGivesUnknownFiguresNotZeros) {
  for (const auto status :
       {tunnel::DeviationStatus::no_walls_in_view, tunnel::DeviationStatus::outside_alignment}) {
    const auto j = nlohmann::json::parse(visit_profile_json(unmeasured(status)));
    EXPECT_EQ(j["status"], tunnel::deviation_status_name(status));
    EXPECT_TRUE(j["overbreak_volume_m3"].is_null()) << j["overbreak_volume_m3"];
    EXPECT_TRUE(j["underbreak_volume_m3"].is_null()) << j["underbreak_volume_m3"];
    EXPECT_TRUE(j["max_overbreak_m"].is_null()) << j["max_overbreak_m"];
    EXPECT_FALSE(j.contains("max_underbreak_m"));
  }
}

TEST(VisitProfileJson, AMeasuredRoundKeepsItsFiguresEvenWhenZero) {
  VisitProfile v = unmeasured(tunnel::DeviationStatus::ok);
  v.deviation.message.clear();
  const auto j = nlohmann::json::parse(visit_profile_json(v));
  ASSERT_TRUE(j["overbreak_volume_m3"].is_number());
  EXPECT_EQ(j["overbreak_volume_m3"].get<double>(), 0.0);
  EXPECT_TRUE(j["max_overbreak_m"].is_number());
}

TEST(DevelopedViewPicture, ALongMessageIsWrappedInsideThePicture) {
  const VisitProfile v = unmeasured(tunnel::DeviationStatus::no_walls_in_view);
  const tunnel::DesignProfile profile = tunnel::rectangle_profile(6.0, 5.0, 0.0);
  const int width = 480;
  const cv::Mat img = storage::developed_view_picture(v.deviation, profile, width);
  ASSERT_EQ(img.cols, width);
  // The message needs several lines at this width: the picture grew to hold
  // them rather than cutting them off.
  EXPECT_GT(img.rows, 160);
  // No ink in the right margin: every text line ends inside the picture.
  // (Anti-aliasing bleeds at most a pixel or two past a glyph; the margin
  // is 20 px, so 12 px of it must be blank paper.)
  const cv::Mat margin = img.colRange(width - 12, width);
  cv::Mat grey;
  cv::extractChannel(margin, grey, 0);
  double lowest = 0;
  cv::minMaxLoc(grey, &lowest);
  EXPECT_EQ(lowest, 255) << "ink in the right margin";
  // And the message's last line is there, at the bottom of the grown picture.
  cv::Mat body;
  cv::extractChannel(img.rowRange(img.rows - 40, img.rows), body, 0);
  cv::minMaxLoc(body, &lowest);
  EXPECT_LT(lowest, 128);
}

}  // namespace
}  // namespace rockface::app
