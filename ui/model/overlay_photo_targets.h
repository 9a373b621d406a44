#pragma once
// The range pole's targets where the detector found them in the left
// photograph (the registration's stored result: each target's centre and
// its diameter in pixels), drawn as rings on that photograph: the geologist
// sees at a glance that the scale came from the pole and not from a dark
// knot in the rock.
#include <optional>
#include <string>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "storage/project/project_records.h"
#include "ui/widgets/picture_texture.h"

namespace rockface::ui {

struct DetectedTarget {
  std::string which;                                // "lower" | "upper"
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // left photograph, full size
  double diameter_px = 0;
};

// From the model's registration parameters (registration.range_pole.targets);
// empty when the model was not scaled by a range pole.
std::vector<DetectedTarget> detected_targets(const storage::Model& model);

class PhotoTargetsView {
 public:
  // Draws the model's photograph fitted into `size` at the cursor, with the
  // targets' rings and labels; uploads the photograph when the model changed.
  void draw(storage::RecordId model_id, const storage::Model& model, const cv::Mat& photo_bgr,
            ImVec2 size, float scale);
  // Where the last draw put each ring (screen px, centre and radius), for tests.
  const std::vector<std::pair<ImVec2, float>>& rings() const { return rings_; }
  // Where the last draw put the photograph's top left corner (screen px), and
  // screen px per photograph px: a photograph pixel p (OpenCV:
  // centres at whole numbers) is at min + (p + 0.5) * scale.
  ImVec2 image_min() const { return image_min_; }
  float screen_px_per_photo_px() const { return photo_px_; }

 private:
  PictureTexture texture_;
  storage::RecordId model_id_ = 0;
  int photo_width_ = 0;
  std::vector<std::pair<ImVec2, float>> rings_;
  ImVec2 image_min_{0, 0};
  float photo_px_ = 0;
};

}  // namespace rockface::ui
