#pragma once
// The one camera interface of the field workflow: the DSLR on the tablet
// (Gphoto2Camera) and the mock camera (MockCamera: replay of earlier
// captures, or synthetic scenes) both implement it.
//
// Settings are named as libgphoto2 names its configuration widgets
// ("f-number", "shutterspeed", "iso", ...). ExposureSettings names the
// handful the workflow sets; each driver maps them to what its camera calls
// them.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "camera/exif.h"

namespace rockface::camera {

struct CameraSetting {
  std::string name;   // widget name, e.g. "f-number"
  std::string label;  // what the camera calls it, e.g. "F-Number"
  std::string value;
  std::vector<std::string> choices;  // the values the camera offers; empty: free value
  bool read_only = false;
};

// What the workflow sets before a stereo pair: aperture priority, a fixed
// aperture, ISO, image format and where the camera stores the shot.
struct ExposureSettings {
  std::optional<std::string> program;         // e.g. "A" (Nikon) / "AV" (Canon): aperture priority
  std::optional<std::string> aperture;        // f-number, e.g. "8"
  std::optional<std::string> shutter;         // e.g. "1/125" (ignored in aperture priority)
  std::optional<std::string> iso;             // e.g. "200"
  std::optional<std::string> image_format;    // e.g. "JPEG Fine", "NEF+Fine"
  std::optional<std::string> capture_target;  // e.g. "Memory card"
};

enum class FlashState { off, on, unknown };

// One file that came off the camera.
struct CapturedFile {
  std::string camera_path;  // folder/name on the camera or card
  std::string saved_path;   // where it was stored on the tablet; empty if not stored
  std::vector<uint8_t> data;
};

// One shot: the JPEG (or the only file) and what came with it, e.g. the
// RAW of a RAW+JPEG pair.
struct Capture {
  CapturedFile image;
  std::vector<CapturedFile> companions;
  ExifInfo exif;  // of `image`
  // The body's serial number as it says over USB (the calibration belongs
  // to the body); empty when the camera gives none.
  std::string body_serial;
  // Said when the body's battery was low at the shot ("the camera's battery
  // is at 8 % ..."); empty otherwise or when the body reports no level.
  std::string battery_warning;
};

struct CameraEvent {
  enum class Kind { file_added, capture_complete, timeout, other };
  Kind kind = Kind::other;
  std::string detail;  // the file path for file_added, a message otherwise
};

class Camera {
 public:
  virtual ~Camera() = default;

  // "Nikon DSC D7500", "Directory Browse", "rockface replay" ...
  virtual std::string model() = 0;

  virtual std::vector<CameraSetting> settings() = 0;
  // Throws CameraError (kind not_supported) when the camera has no such setting.
  virtual CameraSetting setting(const std::string& name) = 0;
  // Throws CameraError when the camera does not offer `value`, naming what it offers.
  virtual void set_setting(const std::string& name, const std::string& value) = 0;
  // Sets each given field through the camera's own setting names.
  virtual void apply(const ExposureSettings& exposure) = 0;

  virtual FlashState flash() = 0;
  // Focuses once and keeps that focus for the following shots.
  virtual void lock_focus() = 0;

  // Takes one picture and downloads it with everything that belongs to it.
  virtual Capture capture() = 0;
  // A picture the camera took but did not send (it stopped answering
  // mid-download), fetched now with everything that belongs to it; nothing
  // when none waits. Throws CameraError while it still cannot be fetched
  // (the picture stays on the camera). A camera that downloads nothing
  // (the mock camera) has none.
  virtual std::optional<Capture> fetch_pending_capture() { return std::nullopt; }
  // The camera's paths of the files such a picture left behind.
  virtual std::vector<std::string> pending_downloads() { return {}; }
  // One live-view frame (BGR).
  virtual cv::Mat live_view() = 0;
  // Events that arrive within timeout_ms (at least a timeout event).
  virtual std::vector<CameraEvent> events(int timeout_ms) = 0;

  virtual void close() = 0;
};

}  // namespace rockface::camera
