// Each screen's status line keeps its own message and errors stay until
// read; the tablet's settings file remembers the theme and refuses a bad one
// by name.
#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/support/test_paths.h"
#include "ui/app/status_lines.h"
#include "ui/app/ui_settings.h"

namespace {

using namespace rockface::ui;

TEST(StatusLines, EachScreenKeepsItsOwnMessageAndErrorsStayUntilDismissed) {
  StatusLines s;
  s.say(2, "Loading model: model 1 loaded");
  EXPECT_EQ(s.message(2), "Loading model: model 1 loaded");
  EXPECT_EQ(s.message(0), "");  // another screen does not show it
  s.error(4, "Analysis: no joints");
  s.say(4, "Saving trace: trace T7 saved");
  ASSERT_EQ(s.errors(4).size(), 1u);  // a later message does not hide the error
  EXPECT_EQ(s.line(4), "Analysis: no joints; Saving trace: trace T7 saved");
  s.error(4, "Analysis: no joints");  // the same error again is one to read
  EXPECT_EQ(s.errors(4).size(), 1u);
  s.dismiss(4);
  EXPECT_TRUE(s.errors(4).empty());
  EXPECT_EQ(s.line(4), "Saving trace: trace T7 saved");
}

TEST(UiSettings, TheThemeIsRememberedAndABadFileIsRefusedByField) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("rockface-settings-" + std::to_string(::getpid()));
  const auto file = dir / "rockface" / "ui.json";
  std::filesystem::remove_all(dir);
  EXPECT_EQ(load_ui_settings(file).theme, Theme::daylight);  // no file: the default
  save_ui_settings(file, UiSettings{Theme::tunnel, {}});
  EXPECT_EQ(load_ui_settings(file).theme, Theme::tunnel);
  std::ofstream(file) << R"({"theme": "sunset"})";
  try {
    load_ui_settings(file);
    FAIL() << "a theme that does not exist was taken";
  } catch (const rockface::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("theme"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
