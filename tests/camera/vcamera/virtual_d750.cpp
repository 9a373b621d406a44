#include "tests/camera/vcamera/virtual_d750.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "camera/exif.h"
#include "tests/support/temp_folders.h"

namespace rockface::test {
namespace fs = std::filesystem;

namespace {

std::string installed_libgphoto2_version() {
  std::string out;
  if (FILE* p = ::popen("dpkg-query -W -f='${Version}' libgphoto2-port12 2>/dev/null", "r")) {
    std::array<char, 128> buf{};
    while (std::fgets(buf.data(), buf.size(), p)) out += buf.data();
    ::pclose(p);
  }
  return out;
}

// Where tools/virtual-camera.sh caches its build for this version.
fs::path cached_iolibs(const std::string& version) {
  fs::path root;
  if (const char* c = std::getenv("ROCKFACE_CACHE"); c && *c)
    root = c;
  else if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    root = fs::path(x) / "rockface";
  else
    root = fs::path(std::getenv("HOME") ? std::getenv("HOME") : "/") / ".cache" / "rockface";
  return root / "vcamera" / ("libgphoto2-" + version) / "iolibs";
}

// A small JPEG with the EXIF a D750 writes (the fields rockface reads).
std::vector<uint8_t> d750_jpeg() {
  cv::Mat img(48, 64, CV_8UC3, cv::Scalar(40, 110, 170));
  cv::rectangle(img, cv::Rect(8, 8, 20, 12), cv::Scalar(200, 200, 200), cv::FILLED);
  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", img, jpeg);
  camera::ExifInfo e;
  e.make = "NIKON CORPORATION";
  e.model = "NIKON D750";
  e.focal_length_mm = 24;
  e.f_number = 8;
  e.exposure_time_s = 1.0 / 125;
  e.iso = 200;
  e.width = 64;
  e.height = 48;
  return camera::with_exif(jpeg, e);
}

}  // namespace

VirtualD750 set_up_virtual_d750(std::vector<uint8_t> card_jpeg) {
  VirtualD750 d;
  const std::string version = installed_libgphoto2_version();
  const fs::path iolibs = cached_iolibs(version);
  if (version.empty() || !fs::exists(iolibs / "vusb.so")) {
    d.missing = "libgphoto2's virtual camera is not built for libgphoto2 " +
                (version.empty() ? std::string("(not installed)") : version) + " (no " +
                (iolibs / "vusb.so").string() + "): run tools/virtual-camera.sh";
    return d;
  }
  d.iolibs = iolibs;
  ::setenv("IOLIBS", iolibs.c_str(), 1);

  d.folder = fs::temp_directory_path() / ("rockface-vcamera-" + std::to_string(::getpid()));
  fs::remove_all(d.folder);
  fs::create_directories(d.folder / "vcamera" / "DCIM" / "100NIKON");
  remove_when_passed(d.folder);
  // The D750's USB ids, vendor then product, each little-endian.
  const unsigned char ids[4] = {0xb0, 0x04, 0x37, 0x04};
  std::ofstream(d.folder / "001,001", std::ios::binary)
      .write(reinterpret_cast<const char*>(ids), 4);
  d.card_jpeg = card_jpeg.empty() ? d750_jpeg() : std::move(card_jpeg);
  std::ofstream(d.folder / "vcamera" / "DCIM" / "100NIKON" / "DSC_0001.JPG", std::ios::binary)
      .write(reinterpret_cast<const char*>(d.card_jpeg.data()),
             static_cast<std::streamsize>(d.card_jpeg.size()));
  // The port's file and the card are found relative to the working folder.
  fs::current_path(d.folder);
  return d;
}

void VirtualD750Fixture::SetUp() {
  d750_ = set_up_virtual_d750();
  if (d750_.iolibs.empty()) {
    // CI builds it (tools/test.sh): there, its absence is a failure.
    if (const char* ci = std::getenv("CI"); ci && std::string(ci) == "true")
      FAIL() << d750_.missing;
    GTEST_SKIP() << d750_.missing;
  }
  spool_ = d750_.folder / "spool";
}

std::vector<uint8_t> bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string message_of(const std::function<void()>& f, camera::CameraError::Kind* kind) {
  try {
    f();
  } catch (const camera::CameraError& e) {
    *kind = e.kind();
    std::printf("said: %s\n", e.what());
    return e.what();
  }
  return "(no error)";
}

CardPair same_size_jpegs(std::vector<uint8_t> left, std::vector<uint8_t> right) {
  // Bytes after the end-of-image marker are no part of the picture:
  // decoders and the EXIF reader stop before them.
  const std::size_t size = std::max(left.size(), right.size());
  left.resize(size, 0);
  right.resize(size, 0);
  return {std::move(left), std::move(right)};
}

void put_on_card(const VirtualD750& d750, const std::vector<uint8_t>& jpeg) {
  std::ofstream(d750.folder / "vcamera" / "DCIM" / "100NIKON" / "DSC_0001.JPG", std::ios::binary)
      .write(reinterpret_cast<const char*>(jpeg.data()), static_cast<std::streamsize>(jpeg.size()));
}

namespace {
fs::path card_file(const VirtualD750& d750) {
  return d750.folder / "vcamera" / "DCIM" / "100NIKON" / "DSC_0001.JPG";
}
}  // namespace

CardCutMidShot::CardCutMidShot(const VirtualD750& d750) : d750_(d750) {
  fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0 || ::inotify_add_watch(fd_, card_file(d750).c_str(), IN_CLOSE_NOWRITE) < 0) return;
  watcher_ = std::thread([this] {
    while (!stop_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      char events[4096];
      if (::read(fd_, events, sizeof events) <= 0) continue;
      // Read once (the object's info): the download reads it next.
      fs::resize_file(card_file(d750_), d750_.card_jpeg.size() / 2);
      cut_ = true;
      return;
    }
  });
}

CardCutMidShot::~CardCutMidShot() {
  stop_ = true;
  if (watcher_.joinable()) watcher_.join();
  if (fd_ >= 0) ::close(fd_);
}

void CardCutMidShot::restore() {
  stop_ = true;
  if (watcher_.joinable()) watcher_.join();
  put_on_card(d750_, d750_.card_jpeg);
}

}  // namespace rockface::test
