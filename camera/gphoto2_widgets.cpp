#include "camera/gphoto2_widgets.h"

namespace rockface::camera::gphoto2 {

// Logical settings and the widget names different makers give them, most
// common first (Nikon, Canon, Sony, Fuji as libgphoto2's ptp2 camlib names them).
const std::vector<std::string> kProgramNames{"expprogram", "autoexposuremode", "exposuremode"};
const std::vector<std::string> kApertureNames{"f-number", "aperture"};
const std::vector<std::string> kShutterNames{"shutterspeed", "shutterspeed2"};
const std::vector<std::string> kIsoNames{"iso", "isospeed"};
const std::vector<std::string> kFormatNames{"imagequality", "imageformat"};
const std::vector<std::string> kTargetNames{"capturetarget"};
const std::vector<std::string> kFlashNames{"flashmode", "flashmode2", "canonflashmode"};
const std::vector<std::string> kFocusModeNames{"focusmode", "focusmode2", "afmode"};
const std::vector<std::string> kAutofocusNames{"autofocusdrive"};
const std::vector<std::string> kWhiteBalanceNames{"whitebalance"};
const std::vector<std::string> kSerialNames{"serialnumber", "eosserialnumber"};
const std::vector<std::string> kBatteryNames{"batterylevel"};

const std::vector<std::string>& widget_names(TabletSetting which) {
  switch (which) {
    case TabletSetting::iso:
      return kIsoNames;
    case TabletSetting::aperture:
      return kApertureNames;
    case TabletSetting::shutter_speed:
      return kShutterNames;
    case TabletSetting::image_format:
      return kFormatNames;
    case TabletSetting::focus_mode:
      return kFocusModeNames;
    case TabletSetting::white_balance:
      break;
  }
  return kWhiteBalanceNames;
}

CameraSetting setting_of_widget(CameraWidget* w) {
  CameraSetting s;
  const char* text = nullptr;
  gp_widget_get_name(w, &text);
  s.name = text ? text : "";
  text = nullptr;
  gp_widget_get_label(w, &text);
  s.label = text ? text : "";
  int ro = 0;
  gp_widget_get_readonly(w, &ro);
  s.read_only = ro != 0;
  CameraWidgetType type;
  gp_widget_get_type(w, &type);
  switch (type) {
    case GP_WIDGET_TEXT:
    case GP_WIDGET_RADIO:
    case GP_WIDGET_MENU: {
      const char* value = nullptr;
      if (gp_widget_get_value(w, &value) == GP_OK && value) s.value = value;
      const int n = gp_widget_count_choices(w);
      for (int i = 0; i < n; ++i) {
        const char* choice = nullptr;
        if (gp_widget_get_choice(w, i, &choice) == GP_OK && choice) s.choices.push_back(choice);
      }
      break;
    }
    case GP_WIDGET_RANGE: {
      float value = 0;
      if (gp_widget_get_value(w, &value) == GP_OK) s.value = std::to_string(value);
      break;
    }
    case GP_WIDGET_TOGGLE:
    case GP_WIDGET_DATE: {
      int value = 0;
      if (gp_widget_get_value(w, &value) == GP_OK) s.value = std::to_string(value);
      break;
    }
    default:
      break;
  }
  return s;
}

void collect_leaf_settings(CameraWidget* w, std::vector<CameraSetting>& out) {
  CameraWidgetType type;
  gp_widget_get_type(w, &type);
  if (type == GP_WIDGET_WINDOW || type == GP_WIDGET_SECTION) {
    const int n = gp_widget_count_children(w);
    for (int i = 0; i < n; ++i) {
      CameraWidget* child = nullptr;
      if (gp_widget_get_child(w, i, &child) == GP_OK) collect_leaf_settings(child, out);
    }
    return;
  }
  if (type != GP_WIDGET_BUTTON) out.push_back(setting_of_widget(w));
}

}  // namespace rockface::camera::gphoto2

namespace rockface::camera {

const char* tablet_setting_name(TabletSetting setting) {
  switch (setting) {
    case TabletSetting::iso:
      return "ISO";
    case TabletSetting::aperture:
      return "aperture";
    case TabletSetting::shutter_speed:
      return "shutter speed";
    case TabletSetting::image_format:
      return "image format";
    case TabletSetting::focus_mode:
      return "focus mode";
    case TabletSetting::white_balance:
      break;
  }
  return "white balance";
}

}  // namespace rockface::camera
