#include "storage/field_report/field_report_pictures.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "core/common/units.h"
#include "core/measure/joint_sets.h"
#include "core/measure/stereonet_image.h"
#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::storage {

std::optional<Eigen::Vector2d> photograph_pixel(const FieldReport& r, const Eigen::Vector3d& p) {
  const Eigen::Vector3d model =
      r.model_rotation.transpose() * (p - r.model_translation) / r.model_scale;
  if (model.z() <= 0) return std::nullopt;
  return photogrammetry::project({model}, r.intrinsics)[0];
}

cv::Scalar block_colour(const analysis::ReportBlock& b) {
  if (!b.finite) return {150, 150, 150};
  if (b.marginal) return {0, 140, 255};
  return b.removable ? cv::Scalar(40, 40, 230) : cv::Scalar(60, 180, 60);
}

namespace {
constexpr int kTraceSamples = 32;  // per straight trace piece
}  // namespace

cv::Mat face_picture(const FieldReport& r) {
  if (r.photograph.empty()) return {};
  cv::Mat out = r.photograph.clone();
  // Line widths and text scale follow the photograph's size.
  const int thick = std::max(2, out.cols / 500);
  const double font = std::max(0.6, out.cols / 1500.0);
  auto to_cv = [](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
  };
  // Blocks first, traces on top (the block fill would tint them).
  for (const auto& b : r.blocks) {
    if (!b.finite || b.vertices.empty()) continue;  // an infinite block has no outline
    std::vector<cv::Point> projected;
    for (const auto& v : b.vertices)
      if (const auto px = photograph_pixel(r, v - r.datum)) projected.push_back(to_cv(*px));
    if (projected.size() < 3) continue;
    std::vector<cv::Point> hull;
    cv::convexHull(projected, hull);
    const cv::Scalar colour = block_colour(b);
    cv::Mat overlay = out.clone();
    cv::fillConvexPoly(overlay, hull, colour, cv::LINE_AA);
    cv::addWeighted(overlay, 0.3, out, 0.7, 0, out);
    cv::polylines(out, hull, true, colour, thick, cv::LINE_AA);
    const cv::Moments m = cv::moments(hull);
    if (m.m00 > 0)
      cv::putText(out, b.id,
                  cv::Point(static_cast<int>(m.m10 / m.m00), static_cast<int>(m.m01 / m.m00)),
                  cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(255, 255, 255), thick, cv::LINE_AA);
  }
  for (const auto& [label, points] : r.traces) {
    // Each straight piece is sampled, so the line bends with the lens
    // distortion as the photographed trace does.
    std::vector<cv::Point> line;
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
      for (int step = 0; step <= kTraceSamples; ++step) {
        const Eigen::Vector3d p =
            points[k] + (points[k + 1] - points[k]) * (static_cast<double>(step) / kTraceSamples);
        if (const auto px = photograph_pixel(r, p)) line.push_back(to_cv(*px));
      }
    if (line.size() < 2) continue;
    cv::polylines(out, line, false, kTraceColour, thick, cv::LINE_AA);
    cv::putText(out, label, line.front() + cv::Point(thick, -thick), cv::FONT_HERSHEY_SIMPLEX, font,
                kTraceColour, thick, cv::LINE_AA);
  }
  return out;
}

std::optional<double> stereonet_friction_deg(const FieldReport& r) {
  std::optional<double> lowest;
  for (const auto& j : r.joints)
    if (j.friction_deg && (!lowest || *j.friction_deg < *lowest)) lowest = j.friction_deg;
  return lowest;
}

const ReportedFacePlane* stereonet_face(const FieldReport& r) {
  const auto phi = stereonet_friction_deg(r);
  if (!phi) return nullptr;
  const ReportedFacePlane* largest = nullptr;
  for (const auto& f : r.face_planes)
    if (f.oriented && f.dip_deg > *phi && (!largest || f.area_m2 > largest->area_m2)) largest = &f;
  return largest;
}

cv::Mat stereonet_picture(const FieldReport& r, int size_px) {
  if (r.poles.empty()) return {};
  measure::StereonetPicture pic;
  pic.title = "joints, visit " + std::to_string(r.visit_id);
  pic.poles = r.poles;
  pic.pole_sets = r.pole_sets;
  pic.plane_great_circles = true;
  for (const auto& s : r.sets) {
    measure::StereonetSet set;
    set.label = s.label;
    set.mean = {deg_to_rad(s.dip_deg), deg_to_rad(s.dipdir_deg)};
    // A stored set keeps its K and count, not its poles: its cone from them.
    set.alpha95 = s.alpha95_deg
                      ? deg_to_rad(*s.alpha95_deg)
                      : measure::alpha95_from(s.fisher_k, static_cast<std::size_t>(s.count));
    if (set.alpha95 >= kPi) set.alpha95 = 0;
    const double cone = measure::fisher_cone(s.fisher_k);
    set.variability = cone < kPi ? cone : 0.0;
    pic.sets.push_back(set);
  }
  // The friction circle of the weakest joint (the first to slide), and the
  // kinematic check on the largest face plane, where the visit has one.
  if (const auto phi = stereonet_friction_deg(r)) pic.friction = deg_to_rad(*phi);
  for (const auto& f : r.face_planes)
    pic.faces.push_back({f.label, {deg_to_rad(f.dip_deg), deg_to_rad(f.dipdir_deg)}});
  const ReportedFacePlane* largest = stereonet_face(r);
  if (largest && pic.friction) {
    measure::KinematicOverlay k;
    k.face = {deg_to_rad(largest->dip_deg), deg_to_rad(largest->dipdir_deg)};
    k.friction = *pic.friction;
    pic.kinematics = k;
  }
  // A handful of poles make no density worth contouring.
  pic.density_contours = r.poles.size() >= 10;
  pic.size_px = size_px;
  return measure::render_stereonet(pic);
}

}  // namespace rockface::storage
