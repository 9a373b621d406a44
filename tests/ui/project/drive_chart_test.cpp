// Issue 39: Project → Sets along the drive on the tunnel-drive sample's
// project plots every placed visit's measured joints against chainage (its
// three joints form no set; the chart was empty), drawn with the tablet's
// font: the title on its own line above the panels.
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "tests/ui/drive_project.h"
#include "tests/ui/drive_tablet.h"
#include "ui/app/app_state.h"

namespace {

using namespace rockface;

TEST(DriveChart, TheDriveSamplesJointsArePlottedAlongTheChainage) {
  test::DriveTablet tablet(test::drive_project());
  ui::HeadlessSession& s = tablet.session;
  ui::AppState& app = s.state();
  tablet.show("Project", "Sets along the drive");
  const auto& t = app.project.tunnel;
  ASSERT_TRUE(t.drive) << (t.lines.empty() ? "" : t.lines.front());
  EXPECT_EQ(t.drive->visits, 1);
  const std::size_t scene_joints = test::drive_scene_json().at("joints").size();
  ASSERT_EQ(t.drive->joints.size(), scene_joints);
  const cv::Mat frame = s.screenshot();
  ASSERT_FALSE(frame.empty());
  EXPECT_EQ(t.drive_drawn.joint_marks, static_cast<int>(scene_joints));
  // Each joint where the scene puts it: the replay stores the scene's joints
  // as they are written (a stored REAL, no rounding), so 1e-6 deg is exact.
  const nlohmann::json scene = test::drive_scene_json();
  for (const auto& truth : scene.at("joints")) {
    bool found = false;
    for (const auto& j : t.drive->joints)
      found = found || (j.label == truth.at("id") &&
                        std::abs(j.dip_deg - truth.at("dip").get<double>()) < 1e-6 &&
                        std::abs(j.dipdir_deg - truth.at("dipdir").get<double>()) < 1e-6);
    EXPECT_TRUE(found) << truth.at("id");
  }
}

}  // namespace
