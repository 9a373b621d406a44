// Touch input onto ImGui 1.86's mouse: a tap is a press frame and a release
// frame; two fingers are a gesture and never press the mouse button.
#include <imgui.h>

#include <gtest/gtest.h>

#include "ui/widgets/touch_input.h"

namespace {

using rockface::ui::TouchEvent;
using rockface::ui::TouchInput;

class TouchInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
  }
  void TearDown() override { ImGui::DestroyContext(); }
  ImGuiIO& io() { return ImGui::GetIO(); }
};

TEST_F(TouchInputTest, TapWithinOneFrameBecomesHoverThenPressThenRelease) {
  TouchInput input;
  input.push({TouchEvent::Kind::down, 0, 100, 50});
  input.push({TouchEvent::Kind::up, 0, 100, 50});
  input.apply(io());
  EXPECT_FALSE(io().MouseDown[0]);  // the pointer comes first
  EXPECT_EQ(io().MousePos.x, 100);
  input.apply(io());
  EXPECT_TRUE(io().MouseDown[0]);
  EXPECT_EQ(io().MousePos.x, 100);
  EXPECT_EQ(io().MousePos.y, 50);
  EXPECT_FALSE(input.idle());
  input.apply(io());
  EXPECT_FALSE(io().MouseDown[0]);
  EXPECT_EQ(io().MousePos.x, 100);  // the release happens where the finger was
  EXPECT_TRUE(input.idle());
}

TEST_F(TouchInputTest, MovesOfOneFrameAreMergedAndDragTheMouse) {
  TouchInput input;
  input.push({TouchEvent::Kind::down, 0, 10, 10});
  input.apply(io());
  input.apply(io());
  for (int i = 1; i <= 5; ++i) input.push({TouchEvent::Kind::move, 0, 10.0f + i, 10});
  input.apply(io());
  EXPECT_TRUE(io().MouseDown[0]);
  EXPECT_EQ(io().MousePos.x, 15);
  EXPECT_TRUE(input.idle());
}

TEST_F(TouchInputTest, TwoFingersPinchWithoutPressingAndReportTheSpreadRatio) {
  TouchInput input;
  input.push({TouchEvent::Kind::down, 0, 100, 100});
  input.push({TouchEvent::Kind::down, 1, 200, 100});
  input.apply(io());  // the pointer moves to the first finger,
  input.apply(io());  // which presses ...
  input.apply(io());  // ... until the second finger lands
  EXPECT_FALSE(io().MouseDown[0]);
  EXPECT_TRUE(input.gesture().active);
  // Spread 100 -> 150 px and the centre moves 10 px down: zoom 1.5, pan (0, 10).
  input.push({TouchEvent::Kind::move, 0, 75, 110});
  input.push({TouchEvent::Kind::move, 1, 225, 110});
  input.apply(io());
  EXPECT_FALSE(io().MouseDown[0]);
  EXPECT_NEAR(input.gesture().pinch, 1.5f, 1e-5f);  // float ratio of exact pixel distances
  EXPECT_NEAR(input.gesture().pan.y(), 10.0f, 1e-5f);
  // Lifting one finger does not turn the other into a drag.
  input.push({TouchEvent::Kind::up, 1, 225, 110});
  input.apply(io());
  EXPECT_FALSE(io().MouseDown[0]);
  input.push({TouchEvent::Kind::up, 0, 75, 110});
  input.apply(io());
  EXPECT_FALSE(io().MouseDown[0]);
  EXPECT_FALSE(input.gesture().active);
}

}  // namespace
