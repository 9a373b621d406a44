#include "core/measure/least_cost_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/measure/tolerances.h"

namespace rockface::measure {

namespace {

// Every step costs at least this (of the [0, 1] feature cost): without it a
// path could wander through a long dark region for free.
constexpr float kStepFloor = 0.05f;

// The value at the given quantile of a float image (over finite pixels).
float quantile(const cv::Mat& m, double q) {
  std::vector<float> v;
  v.reserve(m.total());
  for (int r = 0; r < m.rows; ++r) {
    const float* p = m.ptr<float>(r);
    for (int c = 0; c < m.cols; ++c)
      if (std::isfinite(p[c])) v.push_back(p[c]);
  }
  if (v.empty()) return 0;
  auto it = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), it, v.end());
  return *it;
}

// Feature strength in [0, 1] -> cost in [0, 1] (strong feature, low cost),
// normalised by robust extremes of the corridor so that one trace's contrast
// does not depend on the exposure.
cv::Mat cost_from_strength(const cv::Mat& strength) {
  const float lo = quantile(strength, 0.01), hi = quantile(strength, 0.99);
  cv::Mat cost;
  strength.convertTo(cost, CV_32F, -1.0 / std::max(hi - lo, 1e-6f), hi / std::max(hi - lo, 1e-6f));
  cv::min(cv::max(cost, 0.0), 1.0, cost);
  return cost;
}

cv::Mat grey_of(const cv::Mat& image) {
  cv::Mat grey;
  if (image.channels() == 3)
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else
    grey = image;
  cv::Mat f;
  grey.convertTo(f, CV_32F, 1.0 / 255);
  // Sensor noise would make single dark pixels attractive; a trace is wider.
  cv::GaussianBlur(f, f, cv::Size(0, 0), 1.0);
  return f;
}

// Surface curvature seen in the photograph: the mesh's triangle normals
// drawn into the region, and how fast they change from pixel to pixel.
cv::Mat curvature_strength(const photogrammetry::SurfaceMesh& mesh, const cv::Rect& roi) {
  cv::Mat normals(roi.size(), CV_32FC3, cv::Scalar(0, 0, 0));
  for (const auto& t : mesh.triangles) {
    cv::Point corners[3];
    bool inside = false;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2f p = mesh.pixels[t[k]];
      corners[k] = cv::Point(static_cast<int>(std::lround(p.x())) - roi.x,
                             static_cast<int>(std::lround(p.y())) - roi.y);
      inside = inside || roi.contains(cv::Point(corners[k].x + roi.x, corners[k].y + roi.y));
    }
    if (!inside) continue;
    Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                            .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                            .normalized();
    if (n.z() < 0) n = -n;
    cv::fillConvexPoly(normals, corners, 3, cv::Scalar(n.x(), n.y(), n.z()));
  }
  cv::GaussianBlur(normals, normals, cv::Size(0, 0), 1.5);
  cv::Mat gx, gy;
  cv::Sobel(normals, gx, CV_32F, 1, 0);
  cv::Sobel(normals, gy, CV_32F, 0, 1);
  cv::Mat g = gx.mul(gx) + gy.mul(gy);
  std::vector<cv::Mat> ch;
  cv::split(g, ch);
  cv::Mat strength;
  cv::sqrt(ch[0] + ch[1] + ch[2], strength);
  return strength;
}

bool in_image(const cv::Mat& image, const Eigen::Vector2d& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && p.x() >= -0.5 && p.y() >= -0.5 &&
         p.x() <= image.cols - 0.5 && p.y() <= image.rows - 0.5;
}

}  // namespace

TraceCost trace_cost_by_name(const std::string& name, const std::string& where) {
  if (name == "darkness") return TraceCost::Darkness;
  if (name == "gradient") return TraceCost::Gradient;
  if (name == "curvature") return TraceCost::Curvature;
  throw InputError(where, "unknown trace cost '" + name + "' (darkness, gradient or curvature)");
}

const char* trace_cost_name(TraceCost cost) {
  switch (cost) {
    case TraceCost::Darkness:
      return "darkness";
    case TraceCost::Gradient:
      return "gradient";
    case TraceCost::Curvature:
      return "curvature";
  }
  return "darkness";
}

TracedPath trace_between(const cv::Mat& image, const photogrammetry::SurfaceMesh* mesh,
                         const TraceRequest& request, const std::string& where) {
  if (image.empty()) throw InputError(where, "no photograph to trace on");
  if (!in_image(image, request.from))
    throw InputError(where + ".from", "pixel is outside the image or not a number");
  if (!in_image(image, request.to))
    throw InputError(where + ".to", "pixel is outside the image or not a number");
  const double length = (request.to - request.from).norm();
  if (length < 1.0) throw InputError(where, "the two ends are the same pixel");
  if (request.cost == TraceCost::Curvature && (mesh == nullptr || mesh->pixels.empty()))
    throw InputError(where + ".cost", "a curvature cost needs the 3D image of this photograph");

  const double half_width = request.corridor_px > 0
                                ? request.corridor_px
                                : std::max(kMinCorridorPx, kCorridorFraction * length);
  const Eigen::Vector2d lo = request.from.cwiseMin(request.to).array() - half_width;
  const Eigen::Vector2d hi = request.from.cwiseMax(request.to).array() + half_width;
  const cv::Rect roi = cv::Rect(cv::Point(static_cast<int>(std::floor(lo.x())),
                                          static_cast<int>(std::floor(lo.y()))),
                                cv::Point(static_cast<int>(std::ceil(hi.x())) + 1,
                                          static_cast<int>(std::ceil(hi.y())) + 1)) &
                       cv::Rect(0, 0, image.cols, image.rows);

  cv::Mat cost;
  switch (request.cost) {
    case TraceCost::Darkness: {
      cv::Mat bright = grey_of(image(roi));
      cost = cost_from_strength(1.0f - bright);
      break;
    }
    case TraceCost::Gradient: {
      const cv::Mat grey = grey_of(image(roi));
      cv::Mat gx, gy, mag;
      cv::Sobel(grey, gx, CV_32F, 1, 0);
      cv::Sobel(grey, gy, CV_32F, 0, 1);
      cv::magnitude(gx, gy, mag);
      cost = cost_from_strength(mag);
      break;
    }
    case TraceCost::Curvature:
      cost = cost_from_strength(curvature_strength(*mesh, roi));
      break;
  }

  // Dijkstra over the 8-connected pixels of the corridor.
  const int w = roi.width, h = roi.height;
  const Eigen::Vector2d origin(roi.x, roi.y);
  const Eigen::Vector2d a = request.from - origin, b = request.to - origin;
  const Eigen::Vector2d axis = (b - a) / length;
  auto in_corridor = [&](int x, int y) {
    const Eigen::Vector2d d(x - a.x(), y - a.y());
    const double along = std::clamp(d.dot(axis), 0.0, length);
    return (d - along * axis).norm() <= half_width;
  };
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  const int sx = std::clamp(static_cast<int>(std::lround(a.x())), 0, w - 1);
  const int sy = std::clamp(static_cast<int>(std::lround(a.y())), 0, h - 1);
  const int tx = std::clamp(static_cast<int>(std::lround(b.x())), 0, w - 1);
  const int ty = std::clamp(static_cast<int>(std::lround(b.y())), 0, h - 1);
  std::vector<float> dist(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity());
  std::vector<std::int32_t> from(dist.size(), -1);
  using Entry = std::pair<float, std::int32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  dist[at(sx, sy)] = 0;
  queue.push({0.0f, static_cast<std::int32_t>(at(sx, sy))});
  const std::size_t target = at(tx, ty);
  constexpr int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  constexpr int dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  const float diagonal = std::sqrt(2.0f);
  while (!queue.empty()) {
    const auto [d, k] = queue.top();
    queue.pop();
    if (d > dist[k]) continue;
    if (static_cast<std::size_t>(k) == target) break;
    const int x = k % w, y = k / w;
    const float ck = kStepFloor + cost.at<float>(y, x);
    for (int n = 0; n < 8; ++n) {
      const int nx = x + dx[n], ny = y + dy[n];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h || !in_corridor(nx, ny)) continue;
      const float step =
          (n < 4 ? 1.0f : diagonal) * 0.5f * (ck + kStepFloor + cost.at<float>(ny, nx));
      const std::size_t m = at(nx, ny);
      if (d + step < dist[m]) {
        dist[m] = d + step;
        from[m] = k;
        queue.push({dist[m], static_cast<std::int32_t>(m)});
      }
    }
  }
  if (!std::isfinite(dist[target])) throw Error(where + ": no path between the two ends");

  TracedPath path;
  for (std::int32_t k = static_cast<std::int32_t>(target); k >= 0; k = from[k])
    path.pixels.emplace_back(roi.x + k % w, roi.y + k / w);
  std::reverse(path.pixels.begin(), path.pixels.end());
  if (path.pixels.size() < 2) path.pixels.push_back(request.to);  // ends round to one pixel
  path.pixels.front() = request.from;
  path.pixels.back() = request.to;
  double steps = 0;
  for (std::size_t i = 1; i < path.pixels.size(); ++i)
    steps += (path.pixels[i] - path.pixels[i - 1]).norm();
  path.mean_cost = steps > 0 ? std::max(0.0, dist[target] / steps - kStepFloor) : 0.0;
  return path;
}

}  // namespace rockface::measure
