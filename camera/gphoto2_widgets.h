#pragma once
// libgphoto2's configuration widgets as the tablet reads them: the names
// different makers give each setting (most common first: Nikon, Canon,
// Sony, Fuji as the ptp2 camlib names them), and a widget read into a
// CameraSetting (value and choices).
#include <string>
#include <vector>

#include <gphoto2/gphoto2.h>

#include "camera/camera.h"
#include "camera/gphoto2_camera.h"

namespace rockface::camera::gphoto2 {

extern const std::vector<std::string> kProgramNames;
extern const std::vector<std::string> kApertureNames;
extern const std::vector<std::string> kShutterNames;
extern const std::vector<std::string> kIsoNames;
extern const std::vector<std::string> kFormatNames;
extern const std::vector<std::string> kTargetNames;
extern const std::vector<std::string> kFlashNames;
extern const std::vector<std::string> kFocusModeNames;
extern const std::vector<std::string> kAutofocusNames;
extern const std::vector<std::string> kWhiteBalanceNames;
extern const std::vector<std::string> kSerialNames;
// ptp2 names the PTP BatteryLevel property (0x5001) "batterylevel" on
// every maker; its value reads "50%" (Canon EOS bodies say words: "Full").
extern const std::vector<std::string> kBatteryNames;

// The widget names of one of the tablet's settings.
const std::vector<std::string>& widget_names(TabletSetting which);

// One widget's name, label, value and choices.
CameraSetting setting_of_widget(CameraWidget* w);

// Every setting under a window or section widget (buttons left out).
void collect_leaf_settings(CameraWidget* w, std::vector<CameraSetting>& out);

}  // namespace rockface::camera::gphoto2
