// The window platform (X11 + EGL) on a virtual X server: the same script
// gives the same picture in a window as headless.
#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/ui/demo_project.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::test;

TEST(UiWindow, ScriptInAWindowDrawsWhatHeadlessDraws) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "xvfb-run is not installed (tools/setup.sh installs xvfb)";
  const fs::path dir = ui_test_dir() / "window";
  fs::create_directories(dir);
  const fs::path script = dir / "steps.json";
  std::ofstream(script) << R"({"viewport": [800, 500], "steps": [
      {"tap": "Blocks"}, {"tap": "row TB1"}, {"screenshot": "blocks"}]})";
  // One density for both: a window takes its screen's (Xvfb's) unless told,
  // and the touch targets' size follows it.
  const std::string common = "ui --project " + demo_project().string() +
                             " --scale 0.6 --dpi 90 --max-triangles 20000 --script " +
                             script.string();
  ASSERT_EQ(run_rockface_logged(common + " --headless --screenshots " + (dir / "headless").string(),
                                dir / "headless.txt"),
            0);
  ASSERT_EQ(run_rockface_logged(common + " --screenshots " + (dir / "window").string(),
                                dir / "window.txt", "xvfb-run -a -s '-screen 0 1024x768x24' "),
            0);
  const cv::Mat a = cv::imread((dir / "headless" / "blocks.png").string());
  const cv::Mat b = cv::imread((dir / "window" / "blocks.png").string());
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  // Same renderer (llvmpipe) and the same frames: the pictures agree except
  // where timing differs (ImGui's hover fades); allow 1 % of the pixels.
  const double changed = cv::countNonZero(diff.reshape(1)) / static_cast<double>(diff.total() * 3);
  EXPECT_LT(changed, 0.01);
}

}  // namespace
