#include "core/photogrammetry/targets/control_targets.h"

#include <algorithm>

#include "core/photogrammetry/targets/circular_target.h"

namespace rockface::photogrammetry {

namespace {

// The observation nearest `pick` within the search distance; -1 when none.
int target_at_pick(const std::vector<TargetObservation>& found, const Eigen::Vector2d& pick,
                   const ControlTargetOptions& o) {
  int best = -1;
  double best_d = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    const double d = (found[k].centre_px - pick).norm();
    if (d > std::max(o.min_search_px, 0.5 * found[k].diameter_px)) continue;
    if (best < 0 || d < best_d) {
      best = static_cast<int>(k);
      best_d = d;
    }
  }
  return best;
}

// The targets of the usual thresholds, and those only the thresholds in
// the shadows find (a target away from the lamps) where none lies within
// 2 px of one already found.
std::vector<TargetObservation> targets_in(const cv::Mat& image, const CameraIntrinsics& camera) {
  std::vector<TargetObservation> found = detect_targets(image, camera);
  for (TargetObservation& t : detect_targets_in_the_dark(image, camera)) {
    const bool known = std::any_of(found.begin(), found.end(), [&](const TargetObservation& f) {
      return (f.centre_px - t.centre_px).norm() < 2.0;
    });
    if (!known) found.push_back(std::move(t));
  }
  return found;
}

}  // namespace

std::vector<std::optional<TargetPair>> measure_control_targets(
    const cv::Mat& left_image, const cv::Mat& right_image, const CameraIntrinsics& left,
    const CameraIntrinsics& right, const RelativeOrientation& ro,
    const std::vector<Eigen::Vector2d>& picks, const ControlTargetOptions& o) {
  std::vector<std::optional<TargetPair>> out(picks.size());
  if (picks.empty()) return out;
  const std::vector<TargetObservation> tl = targets_in(left_image, left);
  if (tl.empty()) return out;
  const std::vector<TargetObservation> tr = targets_in(right_image, right);
  const double focal = 0.5 * (left.fx + right.fx);
  for (std::size_t k = 0; k < picks.size(); ++k) {
    const int i = target_at_pick(tl, picks[k], o);
    if (i < 0) continue;
    double err = 0;
    const int j =
        epipolar_partner(tl[static_cast<std::size_t>(i)], tr, ro, focal, kTargetEpipolarPx, err);
    if (j < 0) continue;
    out[k] = triangulate_target_pair(tl[static_cast<std::size_t>(i)],
                                     tr[static_cast<std::size_t>(j)], left, right, ro);
  }
  return out;
}

}  // namespace rockface::photogrammetry
