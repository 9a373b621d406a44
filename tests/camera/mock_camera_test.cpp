#include "camera/mock_camera.h"

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "camera/camera_error.h"
#include "camera/capture_guidance.h"
#include "camera/synthetic_renderer.h"
#include "core/common/error.h"
#include "tests/camera/test_scene.h"
#include "tests/support/temp_folders.h"

namespace rockface::camera {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-mock-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::test::remove_when_passed(dir);
  return dir;
}

void write(const fs::path& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

// A site visit of three shots, written out of order, one with its RAW. Each
// test names its own folder: ctest may run them in parallel.
fs::path site_visit(const std::string& name) {
  const fs::path dir = fresh_dir("visit-" + name);
  for (int i : {3, 1, 2}) {
    cv::Mat img(60, 80, CV_8UC3, cv::Scalar(10 * i, 50, 90));
    std::vector<uint8_t> jpeg;
    cv::imencode(".jpg", img, jpeg);
    ExifInfo e;
    e.model = "NIKON D7500";
    e.datetime = "2026:05:17 09:41:0" + std::to_string(i);
    e.focal_length_mm = 20.0 + i;
    e.f_number = 8;
    e.iso = 100 * i;
    e.flash_fired = false;
    write(dir / ("DSC_000" + std::to_string(i) + ".JPG"), with_exif(jpeg, e));
  }
  write(dir / "DSC_0002.NEF", {1, 2, 3, 4, 5});
  write(dir / "notes.txt", {'h', 'i'});
  return dir;
}

TEST(MockCameraReplay, ServesCapturesInOrderWithTheirExifAndRaw) {
  const fs::path spool = fresh_dir("spool");
  auto cam = MockCamera::replay(site_visit("order").string(), spool.string());
  EXPECT_EQ(cam->shots_left(), 3u);
  // The first shot's settings are shown before shooting.
  EXPECT_EQ(cam->setting("iso").value, "100");
  for (int i = 1; i <= 3; ++i) {
    const Capture c = cam->capture();
    EXPECT_EQ(fs::path(c.image.camera_path).filename(), "DSC_000" + std::to_string(i) + ".JPG");
    EXPECT_EQ(c.exif.datetime, "2026:05:17 09:41:0" + std::to_string(i));
    ASSERT_TRUE(c.exif.focal_length_mm);
    EXPECT_NEAR(*c.exif.focal_length_mm, 20.0 + i, 1e-9);
    EXPECT_EQ(*c.exif.iso, 100 * i);
    EXPECT_EQ(c.companions.size(), i == 2 ? 1u : 0u);
    // Stored on the tablet as soon as it was taken.
    ASSERT_FALSE(c.image.saved_path.empty());
    EXPECT_TRUE(fs::exists(c.image.saved_path));
    const auto events = cam->events(100);
    ASSERT_GE(events.size(), 3u);
    EXPECT_EQ(events.front().kind, CameraEvent::Kind::file_added);
    EXPECT_EQ(events.back().kind, CameraEvent::Kind::timeout);
  }
  EXPECT_TRUE(fs::exists(spool / "DSC_0002.NEF"));
  EXPECT_EQ(cam->shots_left(), 0u);
  try {
    cam->capture();
    FAIL() << "a fourth shot was served";
  } catch (const CameraError& e) {
    EXPECT_NE(std::string(e.what()).find("all 3 captures"), std::string::npos) << e.what();
  }
}

TEST(MockCameraReplay, EmptyOrMissingFolderIsBadInput) {
  EXPECT_THROW(MockCamera::replay("/nonexistent/visit"), InputError);
  const fs::path empty = fresh_dir("empty");
  try {
    MockCamera::replay(empty.string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), empty.string());
    EXPECT_NE(e.reason().find("no JPEG"), std::string::npos);
  }
}

TEST(MockCameraReplay, LiveViewShowsTheNextShot) {
  auto cam = MockCamera::replay(site_visit("live").string());
  const cv::Mat frame = cam->live_view();
  EXPECT_EQ(frame.cols, 80);
  EXPECT_NEAR(frame.at<cv::Vec3b>(30, 40)[0], 10, 3);  // DSC_0001's blue level, JPEG-rounded
}

TEST(MockCameraSynthetic, TwoShotsWithExifFromTheSettings) {
  const auto scene = test::small_tunnel_scene();
  auto cam = MockCamera::synthetic(scene);
  ExposureSettings exposure;
  exposure.program = "A";
  exposure.aperture = "11";
  exposure.iso = "400";
  exposure.image_format = "NEF+Fine";
  cam->apply(exposure);
  EXPECT_EQ(cam->flash(), FlashState::off);
  cam->lock_focus();
  const Capture left = cam->capture();
  const Capture right = cam->capture();
  for (const Capture* c : {&left, &right}) {
    // The EXIF is in the JPEG itself, not only beside it.
    const ExifInfo e = read_exif(c->image.data);
    ASSERT_TRUE(e.focal_length_mm);
    EXPECT_NEAR(*e.focal_length_mm, 1200 * 23.5 / 800, 1e-6);  // fx * sensor width / width
    EXPECT_NEAR(*e.f_number, 11, 1e-9);
    EXPECT_EQ(*e.iso, 400);
    EXPECT_FALSE(*e.flash_fired);
    ASSERT_EQ(c->companions.size(), 1u);  // the lossless render stands in for the RAW
  }
  EXPECT_NO_THROW(require_same_optics(left.exif, right.exif));
  // The lossless companion is exactly the render of that station.
  NoProgress quiet;
  const auto view = render_view(scene, 1, rendered_intrinsics(scene), false, quiet);
  const cv::Mat png = cv::imdecode(right.companions[0].data, cv::IMREAD_COLOR);
  EXPECT_EQ(cv::norm(png, view.image, cv::NORM_INF), 0.0);
  // The JPEG differs from it only by compression (quality 95: about one grey level).
  const cv::Mat jpeg = cv::imdecode(right.image.data, cv::IMREAD_COLOR);
  EXPECT_LT(cv::norm(jpeg, view.image, cv::NORM_L1) / (3.0 * jpeg.total()), 2.0);
  EXPECT_THROW(cam->capture(), CameraError);
}

// The same scene seen by a 320 x 240 camera: what these tests check does
// not depend on image size, and four renders stay fast.
SyntheticScene tiny_scene() {
  auto scene = test::small_tunnel_scene();
  scene.camera.width = 320;
  scene.camera.height = 240;
  scene.camera.fx = scene.camera.fy = 480;
  scene.camera.cx = 159.5;
  scene.camera.cy = 119.5;
  return scene;
}

TEST(MockCameraSynthetic, RefocusBetweenShotsIsRefusedByTheCapturePath) {
  auto scene = tiny_scene();
  scene.stations[1].look_at = {0, 6, 2.2};  // the right shot focuses on something nearer
  auto cam = MockCamera::synthetic(scene);
  const Capture left = cam->capture();
  const Capture right = cam->capture();
  EXPECT_THROW(require_same_optics(left.exif, right.exif), InputError);
  // With focus locked before the pair, the same stations give one focus.
  auto locked = MockCamera::synthetic(scene);
  locked->lock_focus();
  const Capture l2 = locked->capture();
  const Capture r2 = locked->capture();
  EXPECT_NO_THROW(require_same_optics(l2.exif, r2.exif));
}

TEST(MockCameraSynthetic, SettingsOfferOnlyWhatTheBodyHas) {
  auto cam = MockCamera::synthetic(tiny_scene());
  try {
    cam->set_setting("f-number", "7");
    FAIL();
  } catch (const CameraError& e) {
    EXPECT_EQ(e.kind(), CameraError::Kind::bad_value);
    EXPECT_NE(std::string(e.what()).find("5.6, 8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cam->setting("whitebalance"), CameraError);
  cam->set_setting("flashmode", "On");
  EXPECT_EQ(cam->flash(), FlashState::on);
  const cv::Mat frame = cam->live_view();
  EXPECT_EQ(frame.cols, 320);  // at most 1024 wide: a small camera is shown whole
  cam->close();
  EXPECT_THROW(cam->capture(), CameraError);
}

}  // namespace
}  // namespace rockface::camera
