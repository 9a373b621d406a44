// The headless script format: every step kind parses, and a bad step is
// refused naming the file and the step.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "ui/app/ui_script.h"

namespace {

using rockface::InputError;
using rockface::ui::parse_ui_script;
using rockface::ui::ScriptStep;

TEST(UiScript, ParsesEveryStepKind) {
  const auto s = parse_ui_script(R"({"viewport": [640, 400], "steps": [
      {"tap": "Blocks"}, {"tap": [10, 20]}, {"drag": [[1, 2], [3, 4]], "frames": 4},
      {"pinch": {"centre": [5, 6], "from": 50, "to": 80}}, {"wait": "task"},
      {"frames": 3}, {"screenshot": "blocks"}]})",
                                 "steps.json");
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 400);
  ASSERT_EQ(s.steps.size(), 7u);
  EXPECT_EQ(s.steps[0].kind, ScriptStep::Kind::tap);
  EXPECT_EQ(s.steps[0].label, "Blocks");
  EXPECT_EQ(s.steps[1].points[0].y(), 20);
  EXPECT_EQ(s.steps[2].kind, ScriptStep::Kind::drag);
  EXPECT_EQ(s.steps[2].frames, 4);
  EXPECT_EQ(s.steps[3].pinch_to, 80);
  EXPECT_EQ(s.steps[4].kind, ScriptStep::Kind::wait_task);
  EXPECT_EQ(s.steps[5].frames, 3);
  EXPECT_EQ(s.steps[6].label, "blocks");
}

TEST(UiScript, BadStepsNameTheFileAndStep) {
  auto message = [](const std::string& text) {
    try {
      parse_ui_script(text, "steps.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message(R"({"steps": [{"tap": "A"}, {"jump": 1}]})"),
            "steps.json: steps[1]: unknown step (tap, drag, pinch, wait, frames, screenshot)");
  EXPECT_NE(message(R"({"steps": [{"screenshot": "../x"}]})").find("steps[0].screenshot"),
            std::string::npos);
  EXPECT_NE(message(R"({"steps": [{"tap": [1]}]})").find("steps[0].tap"), std::string::npos);
  EXPECT_NE(message(R"({"viewport": [10, 10], "steps": []})").find("viewport"), std::string::npos);
  EXPECT_NE(message("[1, 2]").find("not a JSON object"), std::string::npos);
}

}  // namespace
