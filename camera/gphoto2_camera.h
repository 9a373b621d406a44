#pragma once
// The DSLR over libgphoto2 2.5. One thread owns the camera and serves a
// command queue (libgphoto2 is not thread-safe); every public member may be
// called from any thread and blocks until its command has run.
//
// Nothing captured is lost: every file is written to the spool folder as
// soon as it is downloaded (through core/common/atomic_file.h: a temporary
// name, synced to the card, renamed when complete), and
// a shot taken but not yet downloaded when the camera fails stays in
// pending_downloads() until retry_pending() fetches it after a reconnect.
//
// After a failure that means "unplugged", the next command reconnects: the
// camera is looked up again by model (the USB port number changes on
// replug).
//
// Any libgphoto2 camlib works, including the "Directory Browse" camlib on a
// port "disk:/path", which serves the files of a folder (a card reader, or
// a folder in tests) through the same code as a camera.
#include <memory>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "camera/camera_error.h"

namespace rockface::camera {

class CommandThread;

// The settings the tablet reads and sets on every body, whatever each maker
// (and libgphoto2's driver for it) calls them.
enum class TabletSetting { iso, aperture, shutter_speed, image_format, focus_mode, white_balance };
// "ISO", "aperture", "shutter speed", "image format", "focus mode", "white balance".
const char* tablet_setting_name(TabletSetting setting);

struct DetectedCamera {
  std::string model;  // e.g. "Nikon DSC D7500"
  std::string port;   // e.g. "usb:001,007"
};

class Gphoto2Camera final : public Camera {
 public:
  struct Options {
    std::string model;      // libgphoto2 model name; empty: the first camera detected
    std::string port;       // e.g. "usb:001,007" or "disk:/media/card"; empty: that of the model
    std::string spool_dir;  // where downloaded files are stored; must be writable
    int event_drain_ms = 3000;  // how long to wait for follow-up files after a capture
    // How long a shot may take to give its file: the release, autofocus,
    // the exposure and the write to the card. ptp2's own capture waits
    // for the new file without a bound when the body makes none (issue
    // 42), so rockface triggers the shot and waits for it itself.
    int capture_timeout_ms = 30000;
    // How long the file may follow the body's "capture complete" (a slow
    // card's write of a large RAW) before the shot is said to have none.
    int file_after_complete_ms = 10000;
    // A body that answers "busy" (PTP DeviceBusy: still writing the last
    // shot, a menu open) to a shot or a download is asked again this many
    // times, busy_wait_ms apart, before rockface says so.
    int busy_retries = 5;
    int busy_wait_ms = 500;
  };

  // A battery level at or below this (percent) is said with each shot.
  static constexpr int kLowBatteryPercent = 15;

  // Cameras on USB, as libgphoto2 detects them.
  static std::vector<DetectedCamera> detect();

  // Opens the camera. Throws CameraError naming what is wrong.
  explicit Gphoto2Camera(Options options);
  ~Gphoto2Camera() override;

  // The connection.
  std::string model() override;
  std::string port();
  // The body's serial number ("serialnumber" over PTP); empty when it gives none.
  std::string serial_number();
  void close() override;

  // Settings, named as libgphoto2 names the camera's widgets.
  std::vector<CameraSetting> settings() override;
  CameraSetting setting(const std::string& name) override;
  void set_setting(const std::string& name, const std::string& value) override;
  // Each field under the first of its libgphoto2 names (they differ from
  // maker to maker) that this camera has; refuses one it cannot set over USB.
  void apply(const ExposureSettings& exposure) override;
  // One of the tablet's settings under the first of its libgphoto2 names
  // this camera has, with its choices. Throws CameraError (not_supported)
  // naming the setting when the camera has none of them.
  CameraSetting tablet_setting(TabletSetting which);
  // Sets it; throws as tablet_setting() does, and as set_setting() does for
  // a value the camera does not offer or a setting it shows read-only.
  void set_tablet_setting(TabletSetting which, const std::string& value);
  // unknown when the camera has no flash setting.
  FlashState flash() override;
  // The battery level in percent, as the body reports it over USB; none
  // when it reports none (or on AC power).
  std::optional<int> battery_percent();

  // Shooting, in the order of the workflow: aim, focus, shoot, download.
  cv::Mat live_view() override;
  // Autofocuses once, then switches to the camera's manual focus mode.
  void lock_focus() override;
  // Triggers the shot (asking a busy body again, busy_retries times),
  // waits up to capture_timeout_ms for its file, then event_drain_ms for
  // its follow-up files (the RAW of a RAW+JPEG pair), and spools every file
  // as it is downloaded. A shot that gives no file throws CameraError
  // (no_file) saying so; a low battery (kLowBatteryPercent) is said in the
  // Capture's battery_warning.
  Capture capture() override;
  std::optional<Capture> fetch_pending_capture() override;
  // Waits up to timeout_ms on the camera.
  std::vector<CameraEvent> events(int timeout_ms) override;
  // Files on the camera or card, as "folder/name" paths, folders walked
  // recursively from `folder`.
  std::vector<std::string> list_files(const std::string& folder = "/");
  // Downloads one file into the spool folder.
  CapturedFile download(const std::string& camera_path);
  // Shots taken but not downloaded because the camera failed in between.
  std::vector<std::string> pending_downloads() override;
  // Downloads them now; those that fail stay pending. Throws nothing for a
  // file that fails; returns what was fetched.
  std::vector<CapturedFile> retry_pending();

 private:
  struct State;
  std::unique_ptr<State> state_;  // touched only on the camera thread
  std::unique_ptr<CommandThread> thread_;
};

}  // namespace rockface::camera
