#include "storage/field_report/wedge_pictures.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/blocks/mass_properties.h"
#include "core/common/number_format.h"
#include "storage/field_report/picture_style.h"

namespace rockface::storage {

namespace {

const cv::Scalar kRock{200, 200, 200};

cv::Scalar place_colour(tunnel::WedgePlace p, int k) {
  static const cv::Scalar roof[] = {{60, 60, 220}, {40, 120, 240}, {90, 90, 200}};
  static const cv::Scalar wall[] = {{200, 120, 40}, {170, 150, 60}, {220, 90, 90}};
  static const cv::Scalar floor[] = {{60, 170, 60}, {90, 190, 120}};
  switch (p) {
    case tunnel::WedgePlace::roof:
      return roof[k % 3];
    case tunnel::WedgePlace::floor:
      return floor[k % 2];
    case tunnel::WedgePlace::face:
      return {150, 60, 160};
    default:
      return wall[k % 3];
  }
}

cv::Scalar set_colour(int index) {
  static const cv::Scalar c[] = {{50, 50, 210},  {200, 110, 30}, {40, 160, 40}, {170, 60, 170},
                                 {30, 160, 200}, {140, 140, 30}, {90, 90, 90},  {200, 60, 100}};
  return c[((index % 8) + 8) % 8];
}

void dashed(cv::Mat& img, cv::Point2d a, cv::Point2d b, const cv::Scalar& c) {
  const double len = cv::norm(b - a);
  const int n = std::max(1, static_cast<int>(len / 8));
  for (int i = 0; i < n; i += 2) {
    const cv::Point2d p = a + (b - a) * (static_cast<double>(i) / n);
    const cv::Point2d q = a + (b - a) * (std::min(i + 1.0, static_cast<double>(n)) / n);
    cv::line(img, p, q, c, 2, cv::LINE_AA);
  }
}

}  // namespace

cv::Mat wedge_section_picture(const tunnel::WedgeAnalysis& a, int width_px) {
  // The extent: the section and every perimeter wedge's apex.
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  auto grow = [&](const Eigen::Vector2d& p) {
    umin = std::min(umin, p.x());
    umax = std::max(umax, p.x());
    vmin = std::min(vmin, p.y());
    vmax = std::max(vmax, p.y());
  };
  for (const auto& v : a.section.vertices) grow(v.p);
  for (const auto& w : a.wedges)
    for (const auto& p : w.outline) grow(p);
  const int margin = 40, top = 50;
  const double span = std::max(umax - umin, 1e-3);
  const double px = (width_px - 2 * margin) / span;
  const int height =
      std::clamp(static_cast<int>((vmax - vmin) * px) + top + margin + 30, 200, 1400);
  const double scale = std::min(px, (height - top - margin - 30) / std::max(vmax - vmin, 1e-3));
  cv::Mat img(height, width_px, CV_8UC3, kPaper);
  const double cx = 0.5 * (umin + umax), cy = 0.5 * (vmin + vmax);
  auto to_px = [&](const Eigen::Vector2d& p) {
    return cv::Point2d(width_px / 2.0 + (p.x() - cx) * scale,
                       top + (height - top - 30) / 2.0 - (p.y() - cy) * scale);
  };
  img.setTo(kRock);
  std::vector<cv::Point> hole;
  for (const auto& v : a.section.vertices) hole.push_back(to_px(v.p));
  cv::fillPoly(img, std::vector<std::vector<cv::Point>>{hole}, kPaper, cv::LINE_AA);
  int k = 0;
  for (const auto& w : a.wedges) {
    if (w.place == tunnel::WedgePlace::face || w.outline.size() < 3) continue;
    std::vector<cv::Point> poly;
    for (const auto& p : w.outline) poly.push_back(to_px(p));
    cv::fillPoly(img, std::vector<std::vector<cv::Point>>{poly}, place_colour(w.place, k++),
                 cv::LINE_AA);
    cv::polylines(img, std::vector<std::vector<cv::Point>>{poly}, true, kInk, 1, cv::LINE_AA);
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (const auto& p : w.outline) c += p;
    c /= static_cast<double>(w.outline.size());
    draw_label(img, w.id, to_px(c) + cv::Point2d(-10, 5), 0.5);
  }
  cv::polylines(img, std::vector<std::vector<cv::Point>>{hole}, true, kInk, 2, cv::LINE_AA);
  for (const auto& w : a.wedges) {
    if (w.place != tunnel::WedgePlace::face || w.outline.size() != 3) continue;
    for (int i = 0; i < 3; ++i)
      dashed(img, to_px(w.outline[i]), to_px(w.outline[(i + 1) % 3]), place_colour(w.place, 0));
    const Eigen::Vector2d c = (w.outline[0] + w.outline[1] + w.outline[2]) / 3.0;
    draw_label(img, w.id, to_px(c) + cv::Point2d(-10, 5), 0.45, place_colour(w.place, 0));
  }
  cv::rectangle(img, {0, 0}, {width_px, top - 10}, kPaper, cv::FILLED);
  draw_label(img, "Wedges around the excavation, looking along the drive (face wedges dashed)",
             {12, 26}, 0.55);
  // A one- or five-metre scale bar.
  const double bar_m = span > 12 ? 5 : 1;
  const cv::Point b0(margin, height - 14),
      b1(margin + static_cast<int>(bar_m * scale), height - 14);
  cv::line(img, b0, b1, kInk, 3);
  draw_label(img, std::to_string(static_cast<int>(bar_m)) + " m", b1 + cv::Point(8, 4), 0.45);
  if (a.wedges.empty()) draw_label(img, "no removable wedge", {margin, top + 20}, 0.6);
  return img;
}

cv::Mat wedge_perspective_picture(const tunnel::WedgeAnalysis& a, int count, int width_px) {
  std::vector<const tunnel::Wedge*> largest;
  for (const auto& w : a.wedges) largest.push_back(&w);
  std::sort(largest.begin(), largest.end(),
            [](const auto* x, const auto* y) { return x->mass.volume > y->mass.volume; });
  if (static_cast<int>(largest.size()) > count) largest.resize(count);
  const int n = std::max(1, static_cast<int>(largest.size()));
  const int cell = width_px / n, height = cell + 40;
  cv::Mat img(height, width_px, CV_8UC3, kPaper);
  draw_label(img, "The largest wedges in perspective (joint faces by set, excavation face grey)",
             {12, 24}, 0.5);
  const tunnel::TunnelFrame& f = a.frame;
  // Seen from behind, below and to the left of the wedge, looking at it.
  const Eigen::Vector3d view =
      (0.75 * f.along + 0.35 * f.right + 0.45 * f.up).normalized();  // toward the scene
  const Eigen::Vector3d side = view.cross(f.up).normalized();
  const Eigen::Vector3d upv = side.cross(view).normalized();
  for (int c = 0; c < static_cast<int>(largest.size()); ++c) {
    const tunnel::Wedge& w = *largest[c];
    const auto& verts = w.block.vertices();
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& v : verts) centre += v;
    centre /= static_cast<double>(verts.size());
    double size = 0;
    for (const auto& v : verts) size = std::max(size, (v - centre).norm());
    size = std::max(size, 1e-3);
    const Eigen::Vector3d eye = centre - 4 * size * view;
    const double focal = 0.42 * cell / std::tan(0.25);
    auto project = [&](const Eigen::Vector3d& x) {
      const Eigen::Vector3d d = x - eye;
      const double z = std::max(d.dot(view), 1e-6);
      return cv::Point2d(c * cell + cell / 2.0 + focal * d.dot(side) / z,
                         40 + cell / 2.0 - focal * d.dot(upv) / z);
    };
    // Faces far to near (painter's algorithm on the face centres).
    std::vector<std::pair<double, int>> order;
    for (int fi = 0; fi < static_cast<int>(w.block.faces().size()); ++fi)
      order.emplace_back((blocks::face_centroid(w.block, fi) - eye).dot(view), fi);
    std::sort(order.begin(), order.end(), [](auto& x, auto& y) { return x.first > y.first; });
    for (const auto& [depth, fi] : order) {
      (void)depth;
      const auto& face = w.block.faces()[fi];
      const auto& plane = w.block.planes()[face.plane];
      std::vector<cv::Point> poly;
      for (int v : face.loop) poly.push_back(project(verts[v]));
      const bool free = plane.kind == blocks::PlaneKind::FreeFace;
      // Faces turned toward the eye drawn full, the others lighter.
      const bool front = plane.outward_normal().dot(view) < 0;
      cv::Scalar colour = free ? kRock : set_colour(plane.index);
      if (!front) colour = 0.45 * colour + 0.55 * kPaper;
      cv::fillPoly(img, std::vector<std::vector<cv::Point>>{poly}, colour, cv::LINE_AA);
      cv::polylines(img, std::vector<std::vector<cv::Point>>{poly}, true, kInk, 1, cv::LINE_AA);
    }
    const std::string label = w.id + " " + tunnel::wedge_place_name(w.place) + ", " +
                              format_fixed(w.mass.volume, 2, " m3");
    draw_label(img, label, {c * cell + 10, height - 12}, 0.45);
  }
  if (largest.empty()) draw_label(img, "no removable wedge", {12, 70}, 0.6);
  return img;
}

cv::Mat wedges_picture(const tunnel::WedgeAnalysis& a, int width_px) {
  cv::Mat top = wedge_section_picture(a, width_px);
  cv::Mat bottom = wedge_perspective_picture(a, 3, width_px);
  cv::Mat out;
  cv::vconcat(top, bottom, out);
  return out;
}

}  // namespace rockface::storage
