#pragma once
// The replay's traces when the scene gives picks (docs/scene-extensions.md,
// `picks`): they are measured on the reconstructed 3D image (core/measure)
// like a geologist's taps on the tablet, and the block analysis runs on the
// measured traces and joint planes, not on the synthetic truth.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/measure/pick_measurement.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/reconstruction/reconstruction.h"
#include "core/photogrammetry/surface/face_traces.h"
#include "firmware-app/replay/replay_more_pairs.h"
#include "storage/project/project_records.h"
#include "storage/scene/scene.h"

namespace rockface::app {

struct ReplayPicks {
  measure::MeasuredPicks measured;  // each pick, on its own pair's 3D image in the face frame
  std::vector<measure::JoinedTrace> joined;  // pieces tapped in different pairs' photographs
  // What the analysis takes from the picks, as values: the measured traces
  // (the picks lifted onto the 3D image, absolute), and the scene's joints,
  // each with its traces' common plane where they give one.
  std::vector<analysis::SceneTrace> traces;
  std::vector<analysis::SceneJoint> joints;
  std::vector<std::string> notes;  // joints whose plane stays unknown, and why
};

// `more`: the visit's further pairs, registered (replay_more_pairs.h); null
// for a visit of one pair. A pick (trace, area or point) naming pair k > 1
// (picks.h) is measured on that pair's 3D image moved into the face frame,
// through its left camera (its photograph named pair_photo(k, "left"));
// the analysed traces are the joined ones where pieces were joined.
// Throws InputError naming the scene file and the pick (picks.traces[2]...),
// also for a pick naming a pair the visit does not have.
ReplayPicks measure_replay_picks(const storage::Scene& scene,
                                 const photogrammetry::ReconstructionResult& rec,
                                 const photogrammetry::CameraIntrinsics& intrinsics,
                                 const photogrammetry::ReconstructionPreset& preset,
                                 const cv::Mat& left_image, const cv::Mat& right_image,
                                 const MorePairsOutcome* more = nullptr);

// The pair named by every pick (trace, area, point) exists: `pairs` stereo
// pairs. Throws InputError naming the scene file and the pick's `pair` field.
void check_pick_pairs(const storage::Scene& scene, std::size_t pairs);

// Everything about the scene's picks that is known before anything is
// captured: the pairs they name (check_pick_pairs) and their pixels inside
// the photographs of imaging.camera (measure::check_picks_in_photographs).
// Throws InputError naming the scene file and the pick's field.
void check_picks_before_capture(const storage::Scene& scene, std::size_t pairs);

}  // namespace rockface::app
