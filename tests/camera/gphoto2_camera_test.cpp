// Gphoto2Camera through libgphoto2's real "Directory Browse" camlib: a
// folder on port disk:/path is served as a camera, through the same code
// path (abilities, port lookup, init, folder listing, file download, error
// translation) as a DSLR on USB.
#include "camera/gphoto2_camera.h"

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "camera/exif.h"
#include "tests/support/temp_folders.h"

namespace rockface::camera {
namespace {

namespace fs = std::filesystem;
constexpr const char* kDirectoryModel = "Directory Browse";

fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-gphoto2-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  rockface::test::remove_when_passed(dir);
  return dir;
}

std::vector<uint8_t> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A card with two shots, one in a sub-folder, carrying EXIF.
fs::path card(const std::string& name) {
  const fs::path dir = fresh_dir(name);
  fs::create_directories(dir / "DCIM");
  for (const char* shot : {"DSC_0001.JPG", "DCIM/DSC_0002.JPG"}) {
    cv::Mat img(40, 60, CV_8UC3, cv::Scalar(30, 90, 150));
    std::vector<uint8_t> jpeg;
    cv::imencode(".jpg", img, jpeg);
    ExifInfo e;
    e.model = "NIKON D7500";
    e.focal_length_mm = 24;
    std::ofstream out(dir / shot, std::ios::binary);
    const auto tagged = with_exif(jpeg, e);
    out.write(reinterpret_cast<const char*>(tagged.data()),
              static_cast<std::streamsize>(tagged.size()));
  }
  return dir;
}

Gphoto2Camera::Options options(const fs::path& dir, const fs::path& spool) {
  Gphoto2Camera::Options o;
  o.model = kDirectoryModel;
  o.port = "disk:" + dir.string();
  o.spool_dir = spool.string();
  return o;
}

std::string message_of(const std::function<void()>& f, CameraError::Kind* kind = nullptr) {
  try {
    f();
  } catch (const CameraError& e) {
    if (kind) *kind = e.kind();
    return e.what();
  }
  return "(no error)";
}

TEST(Gphoto2DirectoryCamlib, ListsAndDownloadsIntoTheSpool) {
  const fs::path dir = card("list");
  const fs::path spool = fresh_dir("list-spool");
  Gphoto2Camera cam(options(dir, spool));
  EXPECT_EQ(cam.model(), kDirectoryModel);
  EXPECT_EQ(cam.port(), "disk:" + dir.string());
  auto files = cam.list_files();
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files, (std::vector<std::string>{"/DCIM/DSC_0002.JPG", "/DSC_0001.JPG"}));
  const CapturedFile f = cam.download("/DCIM/DSC_0002.JPG");
  EXPECT_EQ(f.data, bytes_of(dir / "DCIM/DSC_0002.JPG"));
  ASSERT_FALSE(f.saved_path.empty());
  EXPECT_EQ(bytes_of(f.saved_path), f.data);
  EXPECT_FALSE(fs::exists(f.saved_path + ".part"));
  EXPECT_NEAR(*read_exif(f.data).focal_length_mm, 24.0, 1e-9);
  // The same name again does not overwrite what is already stored.
  const CapturedFile again = cam.download("/DCIM/DSC_0002.JPG");
  EXPECT_NE(again.saved_path, f.saved_path);
  EXPECT_TRUE(fs::exists(f.saved_path));
}

TEST(Gphoto2DirectoryCamlib, CommandsFromSeveralThreadsAreServedInTurn) {
  const fs::path dir = card("threads");
  Gphoto2Camera cam(options(dir, {}));
  std::vector<std::future<size_t>> runs;
  for (int i = 0; i < 4; ++i)
    runs.push_back(std::async(std::launch::async, [&cam] {
      size_t total = 0;
      for (int k = 0; k < 5; ++k) total += cam.download("/DSC_0001.JPG").data.size();
      return total;
    }));
  const size_t one = fs::file_size(dir / "DSC_0001.JPG");
  for (auto& r : runs) EXPECT_EQ(r.get(), 5 * one);
}

TEST(Gphoto2DirectoryCamlib, MissingPortSaysSo) {
  CameraError::Kind kind{};
  const std::string msg =
      message_of([] { Gphoto2Camera cam(options("/nonexistent/card", {})); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::disconnected);
  EXPECT_NE(msg.find("/nonexistent/card"), std::string::npos) << msg;
  EXPECT_NE(msg.find("does not exist or is not mounted"), std::string::npos) << msg;

  Gphoto2Camera::Options bad_port = options("/tmp", {});
  bad_port.port = "nosuchport:7";
  const std::string port_msg = message_of([&] { Gphoto2Camera cam(bad_port); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::no_camera);
  EXPECT_NE(port_msg.find("no camera port \"nosuchport:7\""), std::string::npos) << port_msg;

  Gphoto2Camera::Options bad_model = options("/tmp", {});
  bad_model.model = "Hasselblad Moonwalker";
  const std::string model_msg = message_of([&] { Gphoto2Camera cam(bad_model); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::no_camera);
  EXPECT_NE(model_msg.find("Hasselblad Moonwalker"), std::string::npos) << model_msg;
}

TEST(Gphoto2DirectoryCamlib, UnreadableFileIsNamedAndTheCameraStaysUsable) {
  const fs::path dir = card("unreadable");
  Gphoto2Camera cam(options(dir, fresh_dir("unreadable-spool")));
  ASSERT_EQ(cam.list_files().size(), 2u);
  fs::remove(dir / "DSC_0001.JPG");  // gone between listing and download
  CameraError::Kind kind{};
  const std::string msg = message_of([&] { cam.download("/DSC_0001.JPG"); }, &kind);
  EXPECT_TRUE(kind == CameraError::Kind::file_unreadable || kind == CameraError::Kind::file_missing)
      << msg;
  RecordProperty("message", msg);
  EXPECT_NE(msg.find("DSC_0001.JPG"), std::string::npos) << msg;
  EXPECT_NE(msg.find("libgphoto2:"), std::string::npos) << msg;
  // Not mistaken for an unplugged camera: the next download just works.
  EXPECT_EQ(cam.download("/DCIM/DSC_0002.JPG").data.size(),
            fs::file_size(dir / "DCIM/DSC_0002.JPG"));
}

TEST(Gphoto2DirectoryCamlib, ReconnectsWhenTheCardComesBack) {
  const fs::path dir = card("replug");
  const fs::path spool = fresh_dir("replug-spool");
  Gphoto2Camera cam(options(dir, spool));
  const CapturedFile before = cam.download("/DSC_0001.JPG");
  // The card is pulled: the camera is reported gone...
  const fs::path away = dir.string() + "-away";
  fs::remove_all(away);
  fs::rename(dir, away);
  CameraError::Kind kind{};
  const std::string msg = message_of([&] { cam.download("/DSC_0001.JPG"); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::disconnected) << msg;
  // ...what was downloaded before is still on the tablet...
  EXPECT_EQ(bytes_of(before.saved_path), before.data);
  // ...and once it is back, the next command reconnects by itself.
  fs::rename(away, dir);
  EXPECT_EQ(cam.download("/DSC_0001.JPG").data, before.data);
}

TEST(Gphoto2DirectoryCamlib, WhatTheCamlibCannotDoIsSaidPlainly) {
  const fs::path dir = card("unsupported");
  Gphoto2Camera cam(options(dir, {}));
  CameraError::Kind kind{};
  std::string msg = message_of([&] { cam.capture(); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::not_supported) << msg;
  EXPECT_NE(msg.find("Taking a picture: this camera cannot do that over USB"), std::string::npos)
      << msg;
  msg = message_of([&] { cam.settings(); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::not_supported) << msg;
  msg = message_of([&] { cam.live_view(); }, &kind);
  EXPECT_EQ(kind, CameraError::Kind::not_supported) << msg;
  EXPECT_EQ(cam.pending_downloads().size(), 0u);  // a failed capture leaves nothing pending
}

}  // namespace
}  // namespace rockface::camera
