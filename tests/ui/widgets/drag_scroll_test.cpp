// Drag to scroll (issue 27): a finger dragged on a panel that scrolls moves
// its content with it, and the control it went down on is not pressed; a
// tap within the slop (2 mm) still presses; a drag begun on a slider moves
// the slider and scrolls nothing; the thin scroll bar is no touch target (a
// tap on it moves nothing, a drag on it drags the panel). A bare ImGui
// context (no GL) fed by TouchInput as the tablet feeds it, at scale 1
// (150 dpi: the slop is 11.8 px, a target 53 px).
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "ui/widgets/theme.h"
#include "ui/widgets/touch_input.h"
#include "ui/widgets/widgets.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_scroll.h"
#include "ui/widgets/widgets_text.h"

namespace {

using namespace rockface::ui;

constexpr int kItems = 30;
constexpr float kListHeight = 400;
// ImGui 1.86 floors a scroll position to whole pixels when it applies it.
constexpr float kScrollRoundingPx = 1;

class ListPanel : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    targets.set_dpi(kScaleOneDpi);
    apply_theme(Theme::daylight, 1.0f, targets.target_px());
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the working folder
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = ImVec2(800, 600);
    io.DeltaTime = 1.0f / 60;
    frame();
    frame();
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // One frame: a list of buttons with a slider among them, in a panel
  // shorter than its content.
  void frame() {
    input.apply(ImGui::GetIO());
    ImGui::NewFrame();
    targets.begin_frame();
    clear_drawn_text();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImGui::GetIO().DisplaySize);
    ImGui::Begin("screen", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove);
    if (const auto t = choice(targets, "pick", "item a", choice_items, 0)) chosen.push_back(*t);
    ImGui::BeginChild("list", ImVec2(300, kListHeight));
    for (int i = 0; i < kItems; ++i) {
      if (i == 3) slider(targets, "level", &level, 0, 1, "%.2f", 250);
      if (targets.button("item " + std::to_string(i), 250)) pressed.push_back(i);
    }
    scroll = ImGui::GetScrollY();
    scroll_max = ImGui::GetScrollMaxY();
    if (ImGui::GetCurrentWindow()->ScrollbarY)
      bar = ImGui::GetWindowScrollbarRect(ImGui::GetCurrentWindow(), ImGuiAxis_Y);
    ImGui::EndChild();
    ImGui::End();
    ImGui::Render();
  }

  void until_idle() {
    while (!input.idle()) frame();
    frame();
  }

  void drag(ImVec2 from, ImVec2 to, int steps) {
    input.push({TouchEvent::Kind::down, 0, from.x, from.y});
    until_idle();
    for (int i = 1; i <= steps; ++i) {
      const float t = static_cast<float>(i) / steps;
      input.push(
          {TouchEvent::Kind::move, 0, from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t});
      frame();
    }
    input.push({TouchEvent::Kind::up, 0, to.x, to.y});
    until_idle();
  }

  ImVec2 centre_of(const std::string& label) {
    const auto t = targets.find(label);
    EXPECT_TRUE(t && t->visible) << label;
    return t ? t->shown_centre() : ImVec2(0, 0);
  }

  TouchInput input;
  TouchTargets targets;
  std::vector<int> pressed;
  std::vector<std::size_t> chosen;
  const std::vector<std::string> choice_items = {"a", "b", "c", "d", "e", "f",
                                                 "g", "h", "i", "j", "k", "l"};
  float level = 0.5f, scroll = 0, scroll_max = 0;
  ImRect bar;
};

TEST_F(ListPanel, ADragOnAButtonScrollsTheListAndPressesNothing) {
  ASSERT_GT(scroll_max, 1000) << "the list must be much taller than its panel";
  const ImVec2 at = centre_of("item 4");
  drag(at, ImVec2(at.x, at.y - 200), 10);
  EXPECT_NEAR(scroll, 200, kScrollRoundingPx) << "the content follows the finger";
  EXPECT_TRUE(pressed.empty()) << "the button under the finger was pressed by a drag";
  // And back down past the top, from the panel's empty right side near its
  // top (the slider now lies there): the list stops at its start.
  const float top = targets.find("item 4")->views.front().clip_min.y;
  drag(ImVec2(270, top + 10), ImVec2(270, top + 380), 10);
  EXPECT_EQ(scroll, 0);
  EXPECT_TRUE(pressed.empty());
}

TEST_F(ListPanel, ATapThatWobblesWithinTheSlopPressesAndDoesNotScroll) {
  const float slop = targets.drag_slop_px();
  EXPECT_NEAR(slop, 2 / 25.4f * kScaleOneDpi, 1e-3f);  // 2 mm at the DPI, float arithmetic
  const ImVec2 at = centre_of("item 4");
  drag(at, ImVec2(at.x, at.y - slop * 0.8f), 3);  // a fingertip rolling
  EXPECT_EQ(scroll, 0);
  ASSERT_EQ(pressed.size(), 1u);
  EXPECT_EQ(pressed[0], 4);
}

TEST_F(ListPanel, ADragBegunOnASliderMovesTheSliderNotTheList) {
  const auto grab = targets.find("level grab");
  ASSERT_TRUE(grab && grab->drags);
  const ImVec2 at = grab->shown_centre();
  // Up and to the right: the list would scroll, the slider moves.
  drag(at, ImVec2(at.x + 60, at.y - 120), 10);
  EXPECT_EQ(scroll, 0) << "a drag begun on the slider scrolled its panel";
  // 60 px right on a 250 px slider is about +0.25: 0.05 is past any
  // rounding of the grab and short of the move.
  EXPECT_GT(level, 0.55f) << "the slider did not follow the finger";
  EXPECT_TRUE(pressed.empty());
}

TEST_F(ListPanel, TheScrollBarIsAThinIndicatorThatATapDoesNotMove) {
  EXPECT_NEAR(bar.GetWidth(), kScrollIndicatorPx, kScrollRoundingPx);
  // Low on the bar, below its grab: ImGui's own bar would jump there.
  const ImVec2 low(bar.GetCenter().x, bar.Max.y - 20);
  drag(low, low, 1);
  EXPECT_EQ(scroll, 0) << "a tap on the scroll bar moved the list";
  // A drag on it drags the panel, as anywhere in it: the content follows.
  drag(low, ImVec2(low.x, low.y - 150), 10);
  EXPECT_NEAR(scroll, 150, kScrollRoundingPx);
  EXPECT_TRUE(pressed.empty());
}

TEST_F(ListPanel, AnOpenChoicesListScrollsByADragAndChoosesNothing) {
  const ImVec2 frame = centre_of("pick");
  drag(frame, frame, 1);  // a tap opens the list
  const auto last = targets.find("pick: l");
  ASSERT_TRUE(last) << "the choice did not open";
  ASSERT_FALSE(last->visible) << "the list must be longer than it shows";
  const auto first = targets.find("pick: a");
  ASSERT_TRUE(first && first->visible && !first->views.empty());
  // Up from the list's lower edge, across its whole height: the last item
  // comes into view and the item the finger went down on is not chosen.
  const ScrollView& list = first->views.front();
  const float x = (list.clip_min.x + list.clip_max.x) / 2;
  for (int k = 0; k < 4 && !targets.find("pick: l")->visible; ++k)
    drag(ImVec2(x, list.clip_max.y - 4), ImVec2(x, list.clip_min.y + 4), 10);
  EXPECT_TRUE(targets.find("pick: l")->visible) << "the list's last item never came into view";
  EXPECT_TRUE(chosen.empty()) << "a drag chose an item of the list";
  // A tap on it chooses it.
  drag(centre_of("pick: l"), centre_of("pick: l"), 1);
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_EQ(chosen[0], 11u);
}

}  // namespace
