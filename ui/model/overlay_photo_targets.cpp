#include "ui/model/overlay_photo_targets.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "core/common/number_format.h"
#include "storage/project/model_registration.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/widgets.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// The largest side uploaded (GLES 3 guarantees 2048 texels).
constexpr int kMaxSide = 2048;

}  // namespace

std::vector<DetectedTarget> detected_targets(const storage::Model& model) {
  std::vector<DetectedTarget> out;
  for (const auto& t : storage::read_model_registration(model.registration).pole_targets) {
    DetectedTarget d;
    d.which = t.which;
    d.pixel = {t.left_px.x(), t.left_px.y()};
    if (t.diameter_px) d.diameter_px = *t.diameter_px;
    out.push_back(d);
  }
  return out;
}

void PhotoTargetsView::draw(storage::RecordId model_id, const storage::Model& model,
                            const cv::Mat& photo_bgr, ImVec2 size, float scale) {
  rings_.clear();
  if (photo_bgr.empty()) {
    paragraph("This 3D image has no photograph stored with it.");
    return;
  }
  if (model_id != model_id_ || texture_.empty()) {
    const double shrink =
        std::min(1.0, static_cast<double>(kMaxSide) / std::max(photo_bgr.cols, photo_bgr.rows));
    cv::Mat small;
    cv::resize(photo_bgr, small, cv::Size(), shrink, shrink, cv::INTER_AREA);
    texture_.set(small);
    model_id_ = model_id;
    photo_width_ = photo_bgr.cols;
  }
  const float aspect = static_cast<float>(photo_bgr.cols) / static_cast<float>(photo_bgr.rows);
  texture_.draw(std::min(size.x, size.y * aspect));
  const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
  const float k = (hi.x - lo.x) / static_cast<float>(photo_width_);  // screen px per photo px
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const TextArea area{lo, hi, "photograph"};
  image_min_ = lo;
  photo_px_ = k;
  const auto targets = detected_targets(model);
  for (const auto& t : targets) {
    // OpenCV's pixel coordinates name pixel centres: pixel (0, 0) covers
    // [-0.5, 0.5] and its left edge is the picture's.
    const ImVec2 c(lo.x + static_cast<float>(t.pixel.x() + 0.5) * k,
                   lo.y + static_cast<float>(t.pixel.y() + 0.5) * k);
    // The target's own size, but never smaller than a fingertip's mark.
    const float r = std::max(static_cast<float>(t.diameter_px) * k * 0.5f + 4 * scale, 10 * scale);
    draw->AddCircle(c, r + 2 * scale, IM_COL32(0, 0, 0, 255), 32, 2 * scale);
    draw->AddCircle(c, r, kTargetColour, 32, 3 * scale);
    rings_.emplace_back(c, r);
    const std::string label = t.which + " target (" + format_fixed(t.pixel.x(), 0) + ", " +
                              format_fixed(t.pixel.y(), 0) + ") px";
    const char* text = label.c_str();
    // Beside the ring, on the side with room for the words.
    if (const auto at = label_beside(c, r + 2 * scale, ImGui::CalcTextSize(text), area))
      draw_text(draw, *at, kTargetColour, text, area, TextHalo::dark);
  }
  if (targets.empty())
    draw_text(draw, ImVec2(lo.x + 8 * scale, lo.y + 8 * scale), kTargetColour,
              "no range-pole targets stored with this 3D image", area, TextHalo::dark);
}

}  // namespace rockface::ui
