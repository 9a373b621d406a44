#include "camera/gphoto2_errors.h"

#include <gphoto2/gphoto2-port-result.h>
#include <gphoto2/gphoto2-result.h>

namespace rockface::camera {

namespace {

// The camera's card is full, whatever code the driver put on it.
bool says_card_full(const std::string& driver_says) {
  return driver_says.find("ran full") != std::string::npos ||
         driver_says.find("Store Full") != std::string::npos;
}

}  // namespace

CameraError gphoto2_error(int code, const std::string& action, const std::string& driver_says) {
  using Kind = CameraError::Kind;
  Kind kind = Kind::other;
  std::string what;
  // What the failure is; the library's own code is still what the message quotes.
  switch (says_card_full(driver_says) ? GP_ERROR_NO_SPACE : code) {
    case GP_ERROR_CAMERA_BUSY:
      kind = Kind::busy;
      what =
          "the camera is busy (still saving the last picture, or a menu is open on it). "
          "Wait a moment and try again";
      break;
    case GP_ERROR_IO_USB_CLAIM:
    case GP_ERROR_IO_LOCK:
      kind = Kind::usb_claimed;
      what =
          "another program is using the camera's USB connection (on a desktop usually a "
          "photo importer or the file manager). Close it, or unplug and replug the camera";
      break;
    case GP_ERROR_TIMEOUT:
      // On the bus but silent: a body gone to sleep (standby) answers
      // nothing until it is woken (issue 42).
      kind = Kind::disconnected;
      what =
          "the camera did not answer: it has probably gone to sleep. Wake it (half-press the "
          "shutter release, or switch it off and on) and try again; set its standby timer "
          "longer for tethered work. rockface reconnects on the next command, and pictures "
          "already downloaded are safe";
      break;
    case GP_ERROR_IO_USB_FIND:
    case GP_ERROR_IO:
    case GP_ERROR_IO_INIT:
    case GP_ERROR_IO_READ:
    case GP_ERROR_IO_WRITE:
    case GP_ERROR_IO_UPDATE:
    case GP_ERROR_IO_USB_CLEAR_HALT:
      kind = Kind::disconnected;
      what =
          "the camera stopped answering: it was unplugged, switched off or went to sleep. "
          "Check the cable and switch it on; rockface reconnects on the next command, and "
          "pictures already downloaded are safe";
      break;
    case GP_ERROR_NO_SPACE:
      kind = Kind::card_full;
      what =
          "the camera's memory card is full. Free space or change the card; pictures "
          "already downloaded are safe on the tablet";
      break;
    case GP_ERROR_NOT_SUPPORTED:
      kind = Kind::not_supported;
      what = "this camera cannot do that over USB";
      break;
    case GP_ERROR_FILE_NOT_FOUND:
      kind = Kind::file_missing;
      what = "the picture is not (or no longer) on the camera or card";
      break;
    case GP_ERROR_DIRECTORY_NOT_FOUND:
      kind = Kind::file_missing;
      what = "the folder is not on the camera or card";
      break;
    case GP_ERROR_CORRUPTED_DATA:
      kind = Kind::file_unreadable;
      what = "the data came back damaged; it is still on the camera, try again";
      break;
    case GP_ERROR_MODEL_NOT_FOUND:
      kind = Kind::no_camera;
      what =
          "no camera of that model was found; check that it is plugged in, switched on and "
          "set to PTP (not mass storage)";
      break;
    case GP_ERROR_UNKNOWN_PORT:
      kind = Kind::no_camera;
      what = "that camera port does not exist";
      break;
    case GP_ERROR_CAMERA_ERROR:
      what =
          "the camera refused (is the lens attached, the mode dial on a shooting mode, "
          "the card in?)";
      break;
    case GP_ERROR_CANCEL:
      what = "cancelled";
      break;
    case GP_ERROR_NO_MEMORY:
      what = "the tablet ran out of memory";
      break;
    default:
      what = "the camera reported an error";
      break;
  }
  std::string said =
      " (libgphoto2: " + std::string(gp_result_as_string(code)) + ", code " + std::to_string(code);
  if (!driver_says.empty()) said += "; the camera driver: " + driver_says;
  return CameraError(kind, action + ": " + what + said + ")");
}

}  // namespace rockface::camera
