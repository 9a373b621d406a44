#pragma once
// The Capture screen's own state: the camera and the shots of the pair
// being taken.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "camera/camera.h"
#include "core/common/preset.h"
#include "ui/widgets/keypad.h"

namespace rockface::ui {

struct CaptureState {
  std::shared_ptr<camera::Camera> camera;  // used on the worker only while a task runs
  std::string connection = "not connected";
  std::optional<camera::Capture> left, right;
  bool stored = false;  // the pair is saved in the project, or queued to be (issue 45)
  std::vector<std::string> guidance;
  float distance_m = 10;  // to the face, for the base length hint
  // Distance between the pole's target centres: typed once per project
  // (AppState::open_project takes the project's last), issue 42, in
  // millimetres on the keypad while `typing_pole`.
  float range_pole_m = 2.0f;
  bool typing_pole = false;
  TypedNumber pole_mm{6};
  // The visit's reconstruction preset: standard unless the geologist wants
  // a fast first look (issue 42: the tablet always took fast).
  Preset preset = Preset::standard;
  cv::Mat live_view;
  unsigned live_view_texture = 0;
};

}  // namespace rockface::ui
