#pragma once
// The replay's traces when the scene gives picks (docs/scene-extensions.md,
// `picks`): they are measured on the reconstructed 3D image (core/measure)
// like a geologist's taps on the tablet, and the block analysis runs on the
// measured traces and joint planes, not on the synthetic truth.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/photogrammetry/preset.h"
#include "core/photogrammetry/reconstruction.h"
#include "firmware-app/measure_picks.h"
#include "storage/scene.h"

namespace rockface::app {

struct ReplayPicks {
  MeasuredPicks measured;
  // The scene to analyse: its traces are the measured ones (the picks lifted
  // onto the 3D image), each joint that has traces gets their common plane.
  storage::Scene analysed;
  std::vector<std::string> notes;  // joints whose plane stays unknown, and why
};

// Throws InputError naming the scene file and the pick (picks.traces[2]...).
ReplayPicks measure_replay_picks(const storage::Scene& scene,
                                 const photogrammetry::ReconstructionResult& rec,
                                 const photogrammetry::CameraIntrinsics& intrinsics,
                                 const photogrammetry::ReconstructionPreset& preset,
                                 const cv::Mat& left_image, const cv::Mat& right_image);

}  // namespace rockface::app
