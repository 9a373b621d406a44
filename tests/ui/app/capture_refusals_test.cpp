// The Capture screen against a camera that refuses (issue 42): an error
// tapped away with OK leaves the tablet running (reading the emptied error
// list on that tap was a std::bad_alloc or a segmentation fault), and a body
// that gives no focus control over USB still shoots, the geologist told to
// focus it by hand. Headless renderer, no project: nothing else is needed.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "camera/camera_error.h"
#include "core/common/error.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

using namespace rockface;
using namespace rockface::ui;

constexpr int kWidth = 800, kHeight = 500;
const auto kCapture = static_cast<std::size_t>(Screen::capture);

// A camera whose focus cannot be locked over USB, as libgphoto2's virtual
// D750 (and bodies whose focus mode is a switch on the lens) answers.
class NoFocusControlCamera final : public camera::Camera {
 public:
  explicit NoFocusControlCamera(int* shots) : shots_(shots) {}
  std::string model() override { return "Test body without focus control"; }
  std::vector<camera::CameraSetting> settings() override { return {}; }
  camera::CameraSetting setting(const std::string& name) override {
    throw camera::CameraError(camera::CameraError::Kind::not_supported, "no " + name);
  }
  void set_setting(const std::string&, const std::string&) override {}
  void apply(const camera::ExposureSettings&) override {}
  camera::FlashState flash() override { return camera::FlashState::unknown; }
  void lock_focus() override {
    throw camera::CameraError(camera::CameraError::Kind::not_supported,
                              "The test body does not let rockface lock focus over USB: focus "
                              "once on the face, then switch the lens to MF");
  }
  camera::Capture capture() override {
    ++*shots_;
    camera::Capture c;
    c.image.camera_path = "/DCIM/100TEST/SHOT" + std::to_string(*shots_) + ".JPG";
    c.image.data = {0xFF, 0xD8, 0xFF, 0xD9};
    return c;
  }
  cv::Mat live_view() override { return {}; }
  std::vector<camera::CameraEvent> events(int) override { return {}; }
  void close() override {}

 private:
  int* shots_;
};

class NoFocusControlConnector final : public CameraConnector {
 public:
  std::unique_ptr<camera::Camera> connect() override {
    return std::make_unique<NoFocusControlCamera>(&shots);
  }
  std::string describe() const override { return "test body"; }
  int shots = 0;
};

class FailingConnector final : public CameraConnector {
 public:
  std::unique_ptr<camera::Camera> connect() override {
    throw Error("No camera found: plug the camera in");
  }
  std::string describe() const override { return "no camera"; }
};

std::unique_ptr<HeadlessSession> session_with(CameraConnector& connector) {
  FieldServices services;
  services.camera = &connector;
  auto s = std::make_unique<HeadlessSession>(UiOptions{}, services, kWidth, kHeight);
  s->settle();
  s->tap("Capture");
  return s;
}

TEST(UiCaptureRefusals, AnErrorTappedAwayLeavesTheTabletRunning) {
  FailingConnector connector;
  auto s = session_with(connector);
  s->tap("Connect camera");
  s->settle();
  ASSERT_EQ(s->state().statuses.errors(kCapture).size(), 1u);
  // The tap that empties the error list: the frame drawing it must not read it again.
  s->tap("OK");
  s->frame();
  EXPECT_TRUE(s->state().statuses.errors(kCapture).empty());
  // Still answering: the same refusal again, and away again.
  s->tap("Connect camera");
  s->settle();
  ASSERT_EQ(s->state().statuses.errors(kCapture).size(), 1u);
  EXPECT_NE(s->state().statuses.errors(kCapture).back().find("No camera found"), std::string::npos);
  s->tap("OK");
  EXPECT_TRUE(s->state().statuses.errors(kCapture).empty());
}

TEST(UiCaptureRefusals, ABodyWithoutFocusControlStillShootsAndSaysFocusByHand) {
  NoFocusControlConnector connector;
  auto s = session_with(connector);
  s->tap("Connect camera");
  s->settle();
  ASSERT_TRUE(s->state().capture.camera);
  s->tap("Shoot left");
  s->settle();
  ASSERT_TRUE(s->state().capture.left.has_value());
  EXPECT_TRUE(s->state().statuses.errors(kCapture).empty());
  const std::string said = s->state().statuses.message(kCapture);
  EXPECT_NE(said.find("focus as set by hand"), std::string::npos) << said;
  EXPECT_NE(said.find("switch the lens to MF"), std::string::npos) << said;
  s->tap("Shoot right");
  s->settle();
  ASSERT_TRUE(s->state().capture.right.has_value());
  EXPECT_EQ(connector.shots, 2);
  EXPECT_EQ(s->state().capture.right->image.camera_path, "/DCIM/100TEST/SHOT2.JPG");
}

}  // namespace
