#include "tests/camera/vcamera/virtual_d750.h"

#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>

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

VirtualD750 set_up_virtual_d750() {
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
  d.card_jpeg = d750_jpeg();
  std::ofstream(d.folder / "vcamera" / "DCIM" / "100NIKON" / "DSC_0001.JPG", std::ios::binary)
      .write(reinterpret_cast<const char*>(d.card_jpeg.data()),
             static_cast<std::streamsize>(d.card_jpeg.size()));
  // The port's file and the card are found relative to the working folder.
  fs::current_path(d.folder);
  return d;
}

}  // namespace rockface::test
