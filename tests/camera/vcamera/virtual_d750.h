#pragma once
// libgphoto2's virtual D750 for a test process (tools/virtual-camera.sh,
// docs/virtual-camera.md): IOLIBS set to the port drivers the script
// built for the installed libgphoto2, and a fresh working folder made the
// camera: ./001,001 (the USB ids the vusb port matches the model by) and
// ./vcamera/DCIM/100NIKON/DSC_0001.JPG (its card). The virtual camera reads
// its card once per process, so this runs before the first camera call.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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
VirtualD750 set_up_virtual_d750();

}  // namespace rockface::test
