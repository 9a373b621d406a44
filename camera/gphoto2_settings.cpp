#include "camera/gphoto2_settings.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <utility>

#include "camera/camera_error.h"
#include "camera/gphoto2_widgets.h"

namespace rockface::camera::gphoto2 {

namespace {

// Named apart from gphoto2_camera.cpp's `lower`: the demo preset's unity batch holds both.
std::string lower_case(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

CameraSettings::CameraSettings(::Camera* camera, GPContext* context, std::string model, Check check)
    : camera_(camera), context_(context), model_(std::move(model)), check_(std::move(check)) {}

WidgetPtr CameraSettings::root() const {
  CameraWidget* root = nullptr;
  check_(gp_camera_get_config(camera_, &root, context_), "Reading the camera settings");
  return WidgetPtr(root);
}

std::string CameraSettings::find(const std::vector<std::string>& names) const {
  WidgetPtr tree = root();
  for (const auto& n : names) {
    CameraWidget* child = nullptr;
    if (gp_widget_get_child_by_name(tree.get(), n.c_str(), &child) == GP_OK) return n;
  }
  return {};
}

std::string CameraSettings::require(const std::vector<std::string>& names, const std::string& doing,
                                    const std::string& what) const {
  const std::string name = find(names);
  if (name.empty())
    throw CameraError(CameraError::Kind::not_supported,
                      "The " + model_ + " does not let rockface " + doing + " the " + what +
                          " over USB; set it on the camera");
  return name;
}

CameraSetting CameraSettings::read(const std::string& name) const {
  WidgetPtr tree = root();
  CameraWidget* child = nullptr;
  if (gp_widget_get_child_by_name(tree.get(), name.c_str(), &child) < GP_OK)
    throw CameraError(CameraError::Kind::not_supported,
                      "The " + model_ + " has no setting \"" + name + "\"");
  return setting_of_widget(child);
}

void CameraSettings::write(const std::string& name, const std::string& value) const {
  WidgetPtr tree = root();
  CameraWidget* child = nullptr;
  if (gp_widget_get_child_by_name(tree.get(), name.c_str(), &child) < GP_OK)
    throw CameraError(CameraError::Kind::not_supported,
                      "The " + model_ + " has no setting \"" + name + "\"");
  const CameraSetting current = setting_of_widget(child);
  if (current.read_only)
    throw CameraError(CameraError::Kind::not_supported,
                      "The " + model_ + "'s " + current.label +
                          " cannot be changed over USB (set it on the "
                          "camera)");
  if (!current.choices.empty() &&
      std::find(current.choices.begin(), current.choices.end(), value) == current.choices.end()) {
    std::string offered;
    for (const auto& c : current.choices) offered += (offered.empty() ? "" : ", ") + c;
    throw CameraError(CameraError::Kind::bad_value, "The " + model_ + " offers " + current.label +
                                                        " " + offered + "; \"" + value +
                                                        "\" is not one of them");
  }
  CameraWidgetType type;
  gp_widget_get_type(child, &type);
  int rc;
  if (type == GP_WIDGET_TOGGLE || type == GP_WIDGET_DATE) {
    const int v = std::atoi(value.c_str());
    rc = gp_widget_set_value(child, &v);
  } else if (type == GP_WIDGET_RANGE) {
    const float v = std::strtof(value.c_str(), nullptr);
    rc = gp_widget_set_value(child, &v);
  } else {
    rc = gp_widget_set_value(child, value.c_str());
  }
  check_(rc, "Setting " + current.label + " to " + value);
  rc = gp_camera_set_single_config(camera_, name.c_str(), child, context_);
  if (rc == GP_ERROR_NOT_SUPPORTED) rc = gp_camera_set_config(camera_, tree.get(), context_);
  check_(rc, "Setting " + current.label + " to " + value);
}

std::string read_serial_number(::Camera* camera, GPContext* context) {
  CameraWidget* root = nullptr;
  if (gp_camera_get_config(camera, &root, context) < GP_OK) return {};
  WidgetPtr owned(root);
  for (const auto& n : kSerialNames) {
    CameraWidget* child = nullptr;
    if (gp_widget_get_child_by_name(root, n.c_str(), &child) == GP_OK)
      return setting_of_widget(child).value;
  }
  return {};
}

std::optional<std::string> read_battery_value(::Camera* camera, GPContext* context) {
  for (const auto& n : kBatteryNames) {
    CameraWidget* w = nullptr;
    if (gp_camera_get_single_config(camera, n.c_str(), &w, context) < GP_OK) continue;
    WidgetPtr owned(w);
    return setting_of_widget(w).value;
  }
  return std::nullopt;
}

std::optional<int> battery_percent_of(const std::string& value) {
  if (value.empty() || !std::isdigit(static_cast<unsigned char>(value.front())))
    return std::nullopt;
  return std::atoi(value.c_str());
}

FlashState flash_state_of(const std::string& value) {
  const std::string v = lower_case(value);
  if (v.find("off") != std::string::npos || v.find("no flash") != std::string::npos ||
      v.find("suppress") != std::string::npos)
    return FlashState::off;
  return FlashState::on;
}

std::optional<std::string> manual_focus_choice(const std::vector<std::string>& choices) {
  for (const auto& choice : choices) {
    const std::string c = lower_case(choice);
    if (c == "mf" || c.find("manual") != std::string::npos || c == "mf (fixed)") return choice;
  }
  return std::nullopt;
}

}  // namespace rockface::camera::gphoto2
