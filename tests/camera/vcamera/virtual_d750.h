#pragma once
// libgphoto2's virtual D750 for a test process (tools/virtual-camera.sh,
// docs/virtual-camera.md): IOLIBS set to the port drivers the script
// built for the installed libgphoto2, and a fresh working folder made the
// camera: ./001,001 (the USB ids the vusb port matches the model by) and
// ./vcamera/DCIM/100NIKON/DSC_0001.JPG (its card). The virtual camera reads
// its card once per process, so this runs before the first camera call.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "camera/camera_error.h"

namespace rockface::test {

struct VirtualD750 {
  // Empty when tools/virtual-camera.sh has not built the port drivers for
  // the installed libgphoto2; `missing` then says what to run.
  std::filesystem::path iolibs;
  std::string missing;
  std::filesystem::path folder;    // the working folder, the camera's home
  std::vector<uint8_t> card_jpeg;  // the bytes of the card's one JPEG
};

// Looks for the port drivers and, when they are there, sets the process up.
// `card_jpeg`: the card's one JPEG (empty: a small one with a D750's EXIF).
VirtualD750 set_up_virtual_d750(std::vector<uint8_t> card_jpeg = {});

// The opening of a suite on the virtual D750 with the card's own JPEG: the
// camera set up, the test skipped where tools/virtual-camera.sh has not
// built its port drivers (failed on CI, which builds them), and the spool
// folder named in the camera's working folder. A SetUp of its own calls
// this one first and returns when it skipped or failed.
class VirtualD750Fixture : public ::testing::Test {
 protected:
  void SetUp() override;

  VirtualD750 d750_;
  std::filesystem::path spool_;  // made by the camera on its first download
};

// A file's bytes: a spooled picture's, to compare with the card's.
std::vector<uint8_t> bytes_of(const std::filesystem::path& file);

// What rockface says when `f` throws CameraError (printed for the test's
// log), its kind in `kind`; "(no error)" when it throws none.
std::string message_of(const std::function<void()>& f, camera::CameraError::Kind* kind);

// Issue 42: a stereo pair through the virtual camera. vcamera.c serves
// every capture from the card's one JPEG, reading the file when the picture
// is downloaded, with the size it had when the card was read: the pair's
// two JPEGs, padded after their end-of-image marker to one size, are put
// on the card in turn (the left, then the right before the right shot).
struct CardPair {
  std::vector<uint8_t> left, right;  // the same size
};
CardPair same_size_jpegs(std::vector<uint8_t> left, std::vector<uint8_t> right);
// Puts `jpeg` on the card in place of its JPEG (the same size).
void put_on_card(const VirtualD750& d750, const std::vector<uint8_t>& jpeg);

// Issue 42: the camera stops sending a picture halfway. vcamera.c reads a
// capture's file from the card twice: whole for the new object's info when
// the shot is taken, and again for its data when it is downloaded. From
// its making until it is destroyed, this cuts the card's file to half its
// length once it has been read once (inotify, IN_CLOSE_NOWRITE): the shot
// is taken, and its download comes back short, which vcamera.c answers
// with PTP's GeneralError. `restore` puts the whole JPEG back.
class CardCutMidShot {
 public:
  explicit CardCutMidShot(const VirtualD750& d750);
  ~CardCutMidShot();
  CardCutMidShot(const CardCutMidShot&) = delete;
  CardCutMidShot& operator=(const CardCutMidShot&) = delete;
  bool cut() const { return cut_; }
  void restore();

 private:
  const VirtualD750& d750_;
  int fd_ = -1;
  std::atomic<bool> stop_{false}, cut_{false};
  std::thread watcher_;
};

}  // namespace rockface::test
