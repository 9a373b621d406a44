#pragma once
// One open camera's settings through libgphoto2's configuration widgets:
// each found under the first of the names the makers give it
// (gphoto2_widgets.h), read, and written as its widget's type takes a
// value, refusing a read-only one and a value the camera does not offer;
// and what the driver reads from settings of its own accord: the body's
// serial number, its battery level, its flash, its manual focus mode.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gphoto2/gphoto2.h>

#include "camera/camera.h"
#include "camera/gphoto2_handles.h"

namespace rockface::camera::gphoto2 {

class CameraSettings {
 public:
  // Turns a libgphoto2 result into CameraError saying `action`: the
  // connection's own check, which drops a camera that is gone so that the
  // next command reconnects.
  using Check = std::function<void(int rc, const std::string& action)>;

  // `model` names the camera in the messages.
  CameraSettings(::Camera* camera, GPContext* context, std::string model, Check check);

  // The whole widget tree.
  WidgetPtr root() const;
  // The first of `names` that the camera has, or empty.
  std::string find(const std::vector<std::string>& names) const;
  // The first of `names` that the camera has; throws CameraError
  // (not_supported) naming `what` and what rockface was `doing` (read, set)
  // when it has none.
  std::string require(const std::vector<std::string>& names, const std::string& doing,
                      const std::string& what) const;
  // Throws CameraError (not_supported) when the camera has no such setting.
  CameraSetting read(const std::string& name) const;
  // Throws CameraError: not_supported for no such setting or a read-only
  // one, bad_value for a value not among its choices.
  void write(const std::string& name, const std::string& value) const;

 private:
  ::Camera* camera_;
  GPContext* context_;
  std::string model_;
  Check check_;
};

// The body's serial number from the first serial-number widget it has;
// empty for none (the directory camlib, some compacts).
std::string read_serial_number(::Camera* camera, GPContext* context);

// The battery widget's value text; none when the body has no battery widget.
std::optional<std::string> read_battery_value(::Camera* camera, GPContext* context);
// The percent a battery value reads ("50%"); none for words ("Full") or nothing.
std::optional<int> battery_percent_of(const std::string& value);

// The flash as a flash-mode value says it: off for "off", "no flash",
// "suppress..." (any case), on for any other.
FlashState flash_state_of(const std::string& value);

// The focus-mode choice that is manual focus ("MF", "Manual", "MF (fixed)",
// any case); none when the camera offers none.
std::optional<std::string> manual_focus_choice(const std::vector<std::string>& choices);

}  // namespace rockface::camera::gphoto2
