#include "ui/view3d/overlay_targets.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "ui/view3d/model_view.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/widgets.h"

namespace rockface::ui {

namespace {

// Points on the ring: a segment of 10° stays within 0.4 % of the radius of
// the circle (1 - cos 5°), under a pixel for any ring on the screen.
constexpr int kRingPoints = 36;

// The target's disc is ringed this much wider than itself: the ring does not
// cover the target's own picture, and clears the hole it leaves in the mesh
// (dense matching's window widens it by a few pixels).
constexpr double kRingOverTarget = 1.6;

// The face around a target left out of the mesh: points within this many
// target diameters of its pixel, at least this many of them.
constexpr double kFaceAround = 2.5;
constexpr std::size_t kLeastPlanePoints = 20;

std::string target_name(const DetectedTarget& t) {
  return (t.which.empty() ? std::string("range-pole") : t.which) + " target";
}

// Screen px per metre at `p` across the view (0 when it is behind the camera).
double px_per_metre(const ModelView& view, const Eigen::Vector3d& p) {
  const auto a = view.to_screen(p);
  if (!a) return 0;
  const Eigen::Vector3d across = view.ray_at(*a).direction.unitOrthogonal();
  const double step = 0.01 * std::max(view.display_mesh().radius, 1e-3);
  const auto b = view.to_screen(p + across * step);
  if (!b) return 0;
  return std::hypot(b->x - a->x, b->y - a->y) / step;
}

}  // namespace

std::vector<TargetOnModel> locate_targets(const storage::Model& model,
                                          const std::optional<measure::PhotoView>& left,
                                          const photogrammetry::SurfaceMesh& surface,
                                          const measure::MeshPicker& picker) {
  std::vector<TargetOnModel> out;
  const auto detected = detected_targets(model);
  if (detected.empty()) return out;
  // The mesh as the left camera sees it, once for all targets.
  const std::vector<Eigen::Vector2d> seen =
      left ? measure::project_to_view(*left, surface.vertices) : std::vector<Eigen::Vector2d>{};
  for (const DetectedTarget& d : detected) {
    TargetOnModel t{d, std::nullopt, false, 0, 0, {}};
    if (!left) {
      t.why_not = "the left camera's pose is not stored with this 3D image";
    } else if (!measure::pixel_in_image(*left, d.pixel)) {
      t.why_not = "its pixel lies outside the left photograph";
    } else if (const auto hit = picker.pick(*left, d.pixel, "target")) {
      t.point = hit->point;
      t.on_surface = true;
    } else {
      // The face around the hole: the mesh points the camera sees within
      // kFaceAround target diameters of the pixel.
      const double reach = kFaceAround * std::max(d.diameter_px, 10.0);
      std::vector<Eigen::Vector3d> near;
      for (std::size_t i = 0; i < seen.size(); ++i)
        if (seen[i].allFinite() && (seen[i] - d.pixel).norm() <= reach)
          near.push_back(surface.vertices[i]);
      if (near.size() < kLeastPlanePoints) {
        t.why_not = "no 3D image around it (past the face's edge)";
      } else {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (const auto& p : near) c += p;
        c /= static_cast<double>(near.size());
        Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
        for (const auto& p : near) scatter += (p - c) * (p - c).transpose();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
        const Eigen::Vector3d normal = eig.eigenvectors().col(0);
        const measure::Ray ray = measure::ray_through_pixel(*left, d.pixel, "target");
        const double along = ray.direction.dot(normal);
        const double s = std::abs(along) > 1e-9 ? (c - ray.origin).dot(normal) / along : -1;
        if (s <= 0) {
          t.why_not = "the face around it is seen edge-on";
        } else {
          t.point = ray.origin + s * ray.direction;
          t.plane_points = static_cast<int>(near.size());
          t.plane_rms_m =
              std::sqrt(std::max(eig.eigenvalues()(0), 0.0) / static_cast<double>(near.size()));
        }
      }
    }
    out.push_back(std::move(t));
  }
  return out;
}

double target_ring_radius(const ModelView& view, const TargetOnModel& target, float scale) {
  if (!target.point) return 0;
  double radius = 0;
  if (view.left_view() && target.detected.diameter_px > 0) {
    const auto& lv = *view.left_view();
    const double distance = (*target.point - lv.pose.centre).norm();
    radius = kRingOverTarget * 0.5 * target.detected.diameter_px * distance / lv.camera.fx;
  }
  const double k = px_per_metre(view, *target.point);
  if (k > 0) radius = std::max(radius, 12.0 * scale / k);
  return radius;
}

void add_targets_to_overlay(ModelView& view, float scale) {
  const SurfaceDrape* drape = view.drape();
  if (!drape) return;
  const Eigen::Vector3d n = drape->direction();
  const Eigen::Vector3d u = n.unitOrthogonal(), w = n.cross(u);
  for (const TargetOnModel& t : view.targets()) {
    if (!t.point) continue;
    const double r = target_ring_radius(view, t, scale);
    if (!(r > 0)) continue;
    const Eigen::Vector3d& c = *t.point;
    std::vector<Eigen::Vector3d> ring;
    for (int k = 0; k < kRingPoints; ++k) {
      const double a = 2 * M_PI * k / kRingPoints;
      ring.push_back(c + r * (std::cos(a) * u + std::sin(a) * w));
    }
    const std::string what = "target " + t.detected.which;
    OverlayScene& scene = view.overlay();
    // A dark rim under the yellow: the ring reads on pale rock and on dark.
    for (const auto& run : drape->drape(ring, true)) {
      scene.lines.push_back({what + " ring", run, IM_COL32(0, 0, 0, 255), 5 * scale, false});
      scene.lines.push_back({what + " ring", run, kTargetColour, 3 * scale, false});
    }
    // Four ticks outward from the ring: the target's centre is where they point.
    for (const Eigen::Vector3d& d : {u, w, Eigen::Vector3d(-u), Eigen::Vector3d(-w)})
      for (const auto& run : drape->drape({c + r * d, c + 1.8 * r * d}, false))
        scene.lines.push_back({what + " tick", run, kTargetColour, 3 * scale, false});
  }
}

void draw_target_labels(ModelView& view, float scale) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const TextArea area = view.text_area();
  for (const TargetOnModel& t : view.targets()) {
    if (!t.point) continue;
    const auto at = view.to_screen(*t.point);
    if (!at) continue;
    const std::string name = target_name(t.detected);
    const ImVec2 size = ImGui::CalcTextSize(name.c_str());
    const float r =
        static_cast<float>(1.8 * target_ring_radius(view, t, scale) * px_per_metre(view, *t.point));
    const auto place = label_beside(*at, r, size, area);
    if (!place) continue;
    draw_text(draw, *place, kTargetColour, name, area, TextHalo::dark);
    view.add_flat_mark("target " + t.detected.which, *place,
                       ImVec2(place->x + size.x, place->y + size.y));
  }
}

}  // namespace rockface::ui
