#pragma once
// The block's motion after failure played on the Blocks screen: its
// outline at the playback time, interpolated between the report's sampled
// poses, drawn on the model view; a Play / Pause button and a time slider
// (scrub) beside the block's report. Only blocks whose stored analysis has
// `dynamics` (analysis.dynamics) have it.
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/analysis/report.h"

namespace rockface::ui {

struct AppState;
struct BlockView;

struct MotionPlayback {
  std::optional<std::size_t> block;  // the block being played (index into the session's blocks)
  double time = 0;                   // s after failure
  bool playing = false;
};

// The block's corners (datum-relative) at time t of its motion: position
// linear and rotation spherical-linear between the two samples around t.
std::vector<Eigen::Vector3d> posed_at(const std::vector<Eigen::Vector3d>& vertices,
                                      const analysis::ReportDynamics& d, double t);

// On the model view (inside its clip rectangle): the selected block's
// outline at the playback time, and its path so far.
void draw_motion_on_model(AppState& app);
// In the block report panel: events, Play / Pause and the time slider.
void draw_motion_controls(AppState& app, const BlockView& block);

}  // namespace rockface::ui
