#include "ui/blocks/motion_playback.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>
#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "storage/report/report_dynamics_json.h"
#include "ui/app/app_state.h"
#include "ui/blocks/block_view.h"
#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

namespace {

const BlockView* selected_with_motion(const AppState& app) {
  if (!app.session || !app.blocks.selected_block) return nullptr;
  const auto& blocks = app.session->blocks();
  if (*app.blocks.selected_block >= blocks.size()) return nullptr;
  const BlockView& b = blocks[*app.blocks.selected_block];
  return b.dynamics && !b.dynamics->path.empty() ? &b : nullptr;
}

Eigen::Quaterniond quaternion(const analysis::ReportMotionSample& s) {
  return Eigen::Quaterniond(s.orientation(0), s.orientation(1), s.orientation(2), s.orientation(3))
      .normalized();
}

}  // namespace

std::vector<Eigen::Vector3d> posed_at(const std::vector<Eigen::Vector3d>& vertices,
                                      const analysis::ReportDynamics& d, double t) {
  std::vector<Eigen::Vector3d> out;
  if (d.path.empty()) return out;
  const auto& path = d.path;
  size_t k = 0;
  while (k + 1 < path.size() && path[k + 1].time_s <= t) ++k;
  const analysis::ReportMotionSample& a = path[k];
  const analysis::ReportMotionSample& b = path[std::min(k + 1, path.size() - 1)];
  const double span = b.time_s - a.time_s;
  const double f = span > 0 ? std::clamp((t - a.time_s) / span, 0.0, 1.0) : 0.0;
  const Eigen::Vector3d c = (1 - f) * a.position + f * b.position;
  const Eigen::Quaterniond q = quaternion(a).slerp(f, quaternion(b));
  const Eigen::Vector3d c0 = path.front().position;
  for (const auto& v : vertices) out.push_back(c + q * (v - c0));
  return out;
}

void draw_motion_on_model(AppState& app) {
  const BlockView* b = selected_with_motion(app);
  if (!b || !app.blocks.motion.block || *app.blocks.motion.block != *app.blocks.selected_block)
    return;
  const analysis::ReportDynamics& d = *b->dynamics;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  // The centroid's path so far, then the block's outline now.
  std::vector<ImVec2> trail;
  for (const auto& p : d.path) {
    if (p.time_s > app.blocks.motion.time) break;
    if (const auto q = app.model_view.to_screen(p.position)) trail.emplace_back(q->x, q->y);
  }
  if (trail.size() >= 2)
    draw->AddPolyline(trail.data(), static_cast<int>(trail.size()), IM_COL32(255, 230, 0, 255), 0,
                      3.0f * s);
  std::vector<cv::Point2f> projected;
  for (const auto& v : posed_at(b->vertices, d, app.blocks.motion.time))
    if (const auto p = app.model_view.to_screen(v)) projected.emplace_back(p->x, p->y);
  if (projected.size() < 3) return;
  std::vector<cv::Point2f> hull;
  cv::convexHull(projected, hull);
  std::vector<ImVec2> poly;
  for (const auto& p : hull) poly.emplace_back(p.x, p.y);
  draw->AddConvexPolyFilled(poly.data(), static_cast<int>(poly.size()), IM_COL32(255, 80, 40, 90));
  draw->AddPolyline(poly.data(), static_cast<int>(poly.size()), IM_COL32(255, 80, 40, 255),
                    ImDrawFlags_Closed, 4.0f * s);
}

void draw_motion_controls(AppState& app, const BlockView& block) {
  if (!block.dynamics || block.dynamics->path.empty() || !app.blocks.selected_block) return;
  const analysis::ReportDynamics& d = *block.dynamics;
  MotionPlayback& m = app.blocks.motion;
  if (m.block != app.blocks.selected_block) {
    m = MotionPlayback{};
    m.block = app.blocks.selected_block;
  }
  const double end = d.path.back().time_s;
  if (m.playing) {
    m.time += ImGui::GetIO().DeltaTime;
    if (m.time >= end) {
      m.time = end;
      m.playing = false;
    }
  }
  ImGui::Separator();
  paragraph("Motion after failure (" + d.trigger + ")");
  if (app.targets.button(m.playing ? "Pause motion" : "Play motion")) {
    if (!m.playing && m.time >= end) m.time = 0;
    m.playing = !m.playing;
  }
  ImGui::SameLine();
  float t = static_cast<float>(m.time);
  if (slider(app.targets, "motion time", &t, 0.0f, static_cast<float>(end), "%.2f s")) {
    m.time = t;
    m.playing = false;
  }
  for (const auto& e : d.events) bullet(analysis::event_text(e));
}

}  // namespace rockface::ui
