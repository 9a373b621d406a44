#pragma once
// Camera failures as the geologist should hear them. `kind` lets the
// caller react (reconnect after `disconnected`, wait after `busy`); the
// message says what happened and what to do, with the library's own code
// at the end for support.
#include <string>

#include "core/common/error.h"

namespace rockface::camera {

class CameraError : public Error {
 public:
  enum class Kind {
    busy,             // still writing the last shot, or a menu is open
    usb_claimed,      // another program holds the USB device
    disconnected,     // unplugged, switched off, asleep, or the card folder is gone
    card_full,        // no space on the memory card
    not_supported,    // the camera cannot do this over USB
    no_file,          // the shot ended without a picture (not focused, shutter did not fire)
    file_missing,     // the file is not (or no longer) on the camera or card
    file_unreadable,  // the file is there but cannot be read
    bad_value,        // a setting value the camera does not offer
    no_camera,        // no camera found, unknown model or port
    other
  };
  CameraError(Kind kind, const std::string& message) : Error(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace rockface::camera
