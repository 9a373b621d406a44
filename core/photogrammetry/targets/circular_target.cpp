#include "core/photogrammetry/targets/circular_target.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "core/photogrammetry/matching/feature_matching.h"
#include "core/photogrammetry/reconstruction/preset.h"
#include "core/photogrammetry/targets/target_pair.h"

namespace rockface::photogrammetry {

Eigen::Matrix3d ellipse_conic(const cv::RotatedRect& e) {
  const double a = 0.5 * e.size.width, b = 0.5 * e.size.height;
  const double th = deg_to_rad(e.angle), c = std::cos(th), s = std::sin(th);
  // Points x = centre + R diag(a, b) (cos u, sin u).
  Eigen::Matrix3d T;  // maps a pixel to the unit-circle frame
  T << c / a, s / a, -(c * e.center.x + s * e.center.y) / a,   //
      -s / b, c / b, -(-s * e.center.x + c * e.center.y) / b,  //
      0, 0, 1;
  const Eigen::Matrix3d unit = Eigen::Vector3d(1, 1, -1).asDiagonal();
  return T.transpose() * unit * T;
}

CircleFromConic circle_from_conic(const Eigen::Matrix3d& Qin) {
  Eigen::Matrix3d Q = 0.5 * (Qin + Qin.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(Q);
  Eigen::Vector3d lambda = es.eigenvalues();
  Eigen::Matrix3d E = es.eigenvectors();
  const int positive = (lambda.array() > 0).count();
  if (positive == 1) {  // a real cone has signature (2, 1); fix the overall sign
    Q = -Q;
    lambda = -lambda;
  }
  // Order: l1 >= l2 > 0 > l3.
  std::array<int, 3> idx{0, 1, 2};
  std::sort(idx.begin(), idx.end(), [&](int i, int j) { return lambda(i) > lambda(j); });
  const double l1 = lambda(idx[0]), l2 = lambda(idx[1]), l3 = lambda(idx[2]);
  const Eigen::Vector3d e1 = E.col(idx[0]), e3 = E.col(idx[2]);
  const double g1 = std::sqrt(std::max(0.0, (l1 - l2) / (l1 - l3)));
  const double g3 = std::sqrt(std::max(0.0, (l2 - l3) / (l1 - l3)));
  CircleFromConic out;
  const Eigen::Matrix3d Qinv = Q.inverse();
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector3d n = g1 * e1 + (k == 0 ? 1.0 : -1.0) * g3 * e3;
    n.normalize();
    Eigen::Vector3d c = Qinv * n;
    if (c.z() < 0) c = -c;
    if (n.dot(c) > 0) n = -n;  // toward the camera
    out.normal[k] = n;
    out.centre[k] = c.head<2>() / c.z();
  }
  return out;
}

Eigen::Vector3d triangulate_normalised(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  // DLT with P1 = [I | 0], P2 = [R | t].
  Eigen::Matrix<double, 4, 4> A;
  Eigen::Matrix<double, 3, 4> P1 = Eigen::Matrix<double, 3, 4>::Zero(), P2;
  P1.leftCols<3>().setIdentity();
  P2.leftCols<3>() = R;
  P2.col(3) = t;
  A.row(0) = a.x() * P1.row(2) - P1.row(0);
  A.row(1) = a.y() * P1.row(2) - P1.row(1);
  A.row(2) = b.x() * P2.row(2) - P2.row(0);
  A.row(3) = b.y() * P2.row(2) - P2.row(1);
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d X = svd.matrixV().col(3);
  return X.head<3>() / X(3);
}

namespace {

constexpr std::array<int, 4> kThresholds{80, 120, 160, 200};

double bilinear(const cv::Mat& g, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= g.cols || y0 + 1 >= g.rows) return -1;
  const double fx = x - x0, fy = y - y0;
  const uchar* r0 = g.ptr<uchar>(y0);
  const uchar* r1 = g.ptr<uchar>(y0 + 1);
  return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) +
         fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

// A point of the ellipse scaled radially by f, at parameter u.
cv::Point2d on_ellipse(const cv::RotatedRect& e, double f, double u) {
  const double th = deg_to_rad(e.angle);
  const double x = f * 0.5 * e.size.width * std::cos(u), y = f * 0.5 * e.size.height * std::sin(u);
  return {e.center.x + x * std::cos(th) - y * std::sin(th),
          e.center.y + x * std::sin(th) + y * std::cos(th)};
}

// The dark ring around a white-disk candidate, measured along rays from its
// centre. Printed targets differ in the ring's width (outer diameter 1.3 to
// 3 times the disk's and more) and stand in front of light or dark rock, so
// no ring width is assumed: on each ray the ring's black is the darkest
// sample within kRingSearch white radii (where every ring has its ink), and
// the ring's outer edge is looked for further out, where the profile rises
// again (not at all in front of dark rock). A ray is "printed-like" when its
// white is even, its contrast sufficient and its black a small fraction of
// its white: printed black reflects a few percent of what printed white
// does, under sun and in shadow alike, whereas rock texture, however
// contrasty, does not get near that ratio on (nearly) every side of a blob.
constexpr int kRingRays = 48;
constexpr double kRingSearch = 1.35;   // white radii searched for the ring's black
constexpr double kMaxRingRatio = 4.0;  // outer edge looked for up to here
constexpr double kMinPrintedRays = 0.9;
constexpr double kPlateauRise = 0.03;    // of the ray's range, per pixel: the disk's white is flat
constexpr double kPlateauRiseMin = 3.0;  // grey levels per pixel: sensor noise  // fraction of
                                         // printed-like rays (dirt, a pole in front)

struct RingStats {
  double white = 0, black = 0;  // medians over the rays
  double printed_rays = 0;      // fraction of printed-like rays
  double ring_ratio = 0;        // outer / white diameter; 0 where the outer edge is not seen
  bool inside_image = true;
};

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  auto m = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), m, v.end());
  return *m;
}

// Outer edge of the ring along one ray, as a fraction of the white radius
// (0 when not found): beyond the darkest point, the first rise of the
// profile by `rise` grey levels, then the mid-level between the black and
// the level reached a few pixels further.
double ring_outer_edge(const cv::Mat& g, const cv::RotatedRect& e, double u, double f_black,
                       double black, double rise, double step, double ray_radius) {
  const double plateau_px = 3.0;  // past the rise, where the background level is read
  auto sample = [&](double f) {
    const cv::Point2d p = on_ellipse(e, f, u);
    return bilinear(g, p.x, p.y);
  };
  for (double f = f_black + step; f <= kMaxRingRatio; f += step) {
    const double v = sample(f);
    if (v < 0) return 0;
    if (v < black + rise) continue;
    const double plateau = std::max(v, sample(f + plateau_px / ray_radius));
    const double mid = 0.5 * (black + plateau);
    double prev_f = f_black, prev_v = black;
    for (double h = f_black + step; h <= f + plateau_px / ray_radius; h += step) {
      const double hv = sample(h);
      if (hv < 0) return 0;
      if (hv >= mid) return prev_f + (mid - prev_v) / (hv - prev_v) * (h - prev_f);
      prev_f = h;
      prev_v = hv;
    }
    return f;
  }
  return 0;
}

RingStats ring_stats(const cv::Mat& g, const cv::RotatedRect& e, const TargetDetectorOptions& o) {
  RingStats s;
  struct Ray {
    double u, white, black, f_black, step, radius;
  };
  std::vector<Ray> rays;
  int printed = 0;
  for (int k = 0; k < kRingRays; ++k) {
    Ray r{2 * kPi * k / kRingRays, 0, 255, 1.0, 0, 0};
    double w_min = 255;
    for (double f : {0.2, 0.45, 0.7}) {
      const cv::Point2d p = on_ellipse(e, f, r.u);
      const double v = bilinear(g, p.x, p.y);
      if (v < 0) {
        s.inside_image = false;
        return s;
      }
      r.white += v / 3;
      w_min = std::min(w_min, v);
    }
    // Half-pixel steps along the ray (the ray's own radius sets the step in f).
    const cv::Point2d edge = on_ellipse(e, 1.0, r.u);
    r.radius = std::max(1.0, std::hypot(edge.x - e.center.x, edge.y - e.center.y));
    r.step = std::min(0.05, 0.5 / r.radius);
    for (double f = 1.0; f <= kRingSearch; f += r.step) {
      const cv::Point2d p = on_ellipse(e, f, r.u);
      const double v = bilinear(g, p.x, p.y);
      if (v < 0) {
        s.inside_image = false;
        return s;
      }
      if (v < r.black) {
        r.black = v;
        r.f_black = f;
      }
    }
    // Judged by the ray's darkest white: a shadow edge across the disk
    // leaves both sides printed-like, an uneven bright blob of rock does not.
    if (w_min - r.black >= o.min_contrast && r.black <= o.max_black_to_white * w_min) ++printed;
    rays.push_back(r);
  }
  std::vector<double> whites, blacks;
  for (const Ray& r : rays) {
    whites.push_back(r.white);
    blacks.push_back(r.black);
  }
  s.white = median_of(whites);
  s.black = median_of(blacks);
  s.printed_rays = static_cast<double>(printed) / kRingRays;
  if (s.printed_rays < kMinPrintedRays) return s;  // no target: its ring's width is moot
  std::vector<double> outers;
  for (const Ray& r : rays) {
    const double contrast = r.white - r.black;
    const double rise = std::max(0.5 * o.min_contrast, 0.25 * contrast);
    const double outer = ring_outer_edge(g, e, r.u, r.f_black, r.black, rise, r.step, r.radius);
    if (outer > 0) outers.push_back(outer);
  }
  if (outers.size() >= kRingRays / 2) s.ring_ratio = median_of(outers);
  return s;
}

struct Candidate {
  cv::RotatedRect ellipse;
  RingStats ring;
};

// Sub-pixel edge points of the white disk: along rays from the centre, the
// crossing of the mid grey level between this ray's white (inside the disk)
// and black (the darkest point of the ring), interpolated. Levels per ray,
// because a shadow across the target changes both. Also the width of the
// edge (from 75 % to 25 % of the contrast) along each ray: a printed target
// has a step edge a pixel or two wide, a bright blob of rock texture a
// gradual one.
struct Edge {
  std::vector<cv::Point2d> points;
  double median_width_px = 0;
};

Edge subpixel_edge(const cv::Mat& g, const Candidate& c, const TargetDetectorOptions& o) {
  const double perimeter = kPi * 0.5 * (c.ellipse.size.width + c.ellipse.size.height);
  const int rays = std::clamp(static_cast<int>(perimeter * 2), 48, 720);
  Edge edge;
  std::vector<double> widths;
  std::vector<double> profile;
  for (int k = 0; k < rays; ++k) {
    const double u = 2 * kPi * k / rays;
    const double f_inner = 0.6;
    const cv::Point2d inner = on_ellipse(c.ellipse, f_inner, u),
                      outer = on_ellipse(c.ellipse, kRingSearch, u);
    const double len = std::hypot(outer.x - inner.x, outer.y - inner.y);
    const int steps = std::max(8, static_cast<int>(len / 0.1));
    profile.clear();
    for (int i = 0; i <= steps; ++i) {
      const double f = static_cast<double>(i) / steps;
      const double v =
          bilinear(g, inner.x + f * (outer.x - inner.x), inner.y + f * (outer.y - inner.y));
      if (v < 0) break;
      profile.push_back(v);
    }
    if (profile.size() < static_cast<std::size_t>(steps) + 1) continue;
    // Black: the darkest of the ring (or of dark rock beyond it). White: the
    // plateau reached walking inward from there, past the dark (ring, rock)
    // and up the edge until the profile flattens (rises by less than
    // kPlateauRise of the ray's range over a pixel): so on the edge's side of
    // a shadow line that crosses the disk.
    const auto darkest = std::min_element(profile.begin(), profile.end());
    const double black = *darkest;
    const double range = *std::max_element(profile.begin(), darkest + 1) - black;
    const double rise = std::max(kPlateauRiseMin, kPlateauRise * range);
    const auto per_px = std::max<std::ptrdiff_t>(1, static_cast<std::ptrdiff_t>(steps / len));
    auto white_end = darkest - profile.begin();
    while (white_end > 0 && profile[white_end] < black + 0.25 * range) --white_end;
    while (white_end - per_px >= 0 && profile[white_end - per_px] > profile[white_end] + rise)
      --white_end;
    const double white = profile[std::max<std::ptrdiff_t>(0, white_end - per_px)];
    const double contrast = white - black;
    if (contrast < 0.5 * o.min_contrast) continue;  // a dirty or occluded ray
    const double mid = black + 0.5 * contrast;
    const double high = black + 0.75 * contrast, low = black + 0.25 * contrast;
    double at_high = -1, at_low = -1;
    bool found_mid = false;
    for (auto i = white_end + 1; i <= steps; ++i) {
      const double prev = profile[i - 1], v = profile[i];
      const double f = static_cast<double>(i) / steps;
      if (at_high < 0 && prev >= high && v < high) at_high = f * len;
      if (!found_mid && prev >= mid && v < mid) {
        const double w = (prev - mid) / (prev - v);  // linear interpolation between samples
        const double fe = (i - 1 + w) / steps;
        edge.points.emplace_back(inner.x + fe * (outer.x - inner.x),
                                 inner.y + fe * (outer.y - inner.y));
        found_mid = true;
      }
      if (prev >= low && v < low) {
        at_low = f * len;
        break;
      }
    }
    if (found_mid && at_high >= 0 && at_low >= 0) widths.push_back(at_low - at_high);
  }
  edge.median_width_px = widths.empty() ? 1e9 : median_of(widths);
  return edge;
}

// Distance (about) of a point from the ellipse, pixels.
double ellipse_residual(const cv::Point2f& p, const cv::RotatedRect& e) {
  const double a = 0.5 * e.size.width, b = 0.5 * e.size.height, th = deg_to_rad(e.angle);
  const double dx = p.x - e.center.x, dy = p.y - e.center.y;
  const double x = dx * std::cos(th) + dy * std::sin(th),
               y = -dx * std::sin(th) + dy * std::cos(th);
  return std::abs(std::hypot(x / a, y / b) - 1) * std::sqrt(a * b);
}

struct EllipseFit {
  cv::RotatedRect ellipse;
  double rms_px = 1e9;  // over the inliers
  double inlier_fraction = 0;
};

// Ellipse through the edge points, once more without the points far off the
// first fit: where a shadow line or dirt crosses the disk's edge, a few rays
// find their mid-level crossing elsewhere.
EllipseFit robust_ellipse_fit(const std::vector<cv::Point2f>& points) {
  constexpr double kOutlierPx = 0.5;      // at least: sub-pixel edges scatter a tenth of it
  constexpr double kOutlierFactor = 3.0;  // times the median residual
  EllipseFit fit;
  fit.ellipse = cv::fitEllipse(points);
  std::vector<double> residuals;
  for (const auto& p : points) residuals.push_back(ellipse_residual(p, fit.ellipse));
  const double limit = std::max(kOutlierPx, kOutlierFactor * median_of(residuals));
  std::vector<cv::Point2f> inliers;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (residuals[i] <= limit) inliers.push_back(points[i]);
  if (inliers.size() < 6) return fit;
  fit.ellipse = cv::fitEllipse(inliers);
  double sum2 = 0;
  for (const auto& p : inliers) sum2 += std::pow(ellipse_residual(p, fit.ellipse), 2);
  fit.rms_px = std::sqrt(sum2 / inliers.size());
  fit.inlier_fraction = static_cast<double>(inliers.size()) / points.size();
  return fit;
}

bool is_printed_target(const RingStats& ring, const TargetDetectorOptions& o) {
  return ring.inside_image && ring.white - ring.black >= o.min_contrast &&
         ring.printed_rays >= kMinPrintedRays;
}

}  // namespace

namespace {

std::vector<TargetObservation> detect_targets_at(const cv::Mat& image,
                                                 const CameraIntrinsics& camera,
                                                 const TargetDetectorOptions& o,
                                                 const std::vector<int>& thresholds) {
  const cv::Mat g = to_grey(image);
  // Candidates are searched on a copy at most kSearchWidth px wide (bounded
  // time on 24 Mpx frames); the edge is then located on the full image.
  constexpr int kSearchWidth = 2400;
  const double scale = working_scale(g.cols, kSearchWidth);
  cv::Mat small;
  if (scale < 1)
    cv::resize(g, small, cv::Size(), scale, scale, cv::INTER_AREA);
  else
    small = g;
  const double max_d = o.max_white_diameter_fraction * small.rows;
  const double min_d = std::max(3.0, o.min_white_diameter_px * scale);
  std::vector<Candidate> candidates;
  cv::Mat binary;
  for (int t : thresholds) {
    cv::threshold(small, binary, t, 255, cv::THRESH_BINARY);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(binary, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
    for (const auto& c : contours) {
      if (c.size() < 8) continue;
      const cv::Rect box = cv::boundingRect(c);
      if (std::max(box.width, box.height) < min_d || std::max(box.width, box.height) > max_d)
        continue;
      // Cheap shape test before the ellipse fit: a disk's outline is compact.
      const double area = cv::contourArea(c);
      const double perimeter = cv::arcLength(c, true);
      if (4 * kPi * area < 0.5 * perimeter * perimeter / o.max_axis_ratio) continue;
      const cv::RotatedRect e = cv::fitEllipse(c);
      const double major = std::max(e.size.width, e.size.height);
      const double minor = std::min(e.size.width, e.size.height);
      if (!(minor > 0) || major / minor > o.max_axis_ratio) continue;
      // Pixelated small disks fill their ellipse less exactly.
      const double fill = area / (kPi * 0.25 * e.size.width * e.size.height);
      if (std::abs(fill - 1) > (major < 12 ? 0.35 : 0.12)) continue;
      const RingStats ring = ring_stats(small, e, o);
      if (!is_printed_target(ring, o)) continue;
      bool duplicate = false;
      for (auto& k : candidates)
        if (std::hypot(k.ellipse.center.x - e.center.x, k.ellipse.center.y - e.center.y) <
            0.25 * minor) {
          duplicate = true;
          break;
        }
      if (!duplicate) candidates.push_back({e, ring});
    }
  }
  if (scale < 1)
    for (auto& c : candidates) {
      c.ellipse.center.x = static_cast<float>((c.ellipse.center.x + 0.5) / scale - 0.5);
      c.ellipse.center.y = static_cast<float>((c.ellipse.center.y + 0.5) / scale - 0.5);
      c.ellipse.size.width = static_cast<float>(c.ellipse.size.width / scale);
      c.ellipse.size.height = static_cast<float>(c.ellipse.size.height / scale);
      c.ring = ring_stats(g, c.ellipse, o);
    }

  std::vector<TargetObservation> out;
  const cv::Matx33d K = camera_matrix(camera);
  const cv::Mat D = distortion_vector(camera);
  for (const auto& c : candidates) {
    if (!is_printed_target(c.ring, o)) continue;
    const Edge found = subpixel_edge(g, c, o);
    const std::vector<cv::Point2d>& edge = found.points;
    if (edge.size() < 24) continue;
    // Step edge: at most the blur (~2 px) plus a little, or a small fraction
    // of the radius for big targets seen slightly out of focus.
    const double radius = 0.25 * (c.ellipse.size.width + c.ellipse.size.height);
    if (found.median_width_px > std::max(o.max_edge_width_px, 0.15 * radius)) continue;
    // Undistorted ("ideal") pixels: the ellipse is a conic only without distortion.
    std::vector<cv::Point2d> ideal;
    cv::undistortPoints(edge, ideal, K, D, cv::noArray(), K);
    std::vector<cv::Point2f> ideal_f(ideal.begin(), ideal.end());
    const EllipseFit fit = robust_ellipse_fit(ideal_f);
    if (fit.rms_px > o.max_fit_rms_px || fit.inlier_fraction < kMinPrintedRays) continue;
    const cv::RotatedRect& e = fit.ellipse;
    TargetObservation obs;
    obs.fit_rms_px = fit.rms_px;
    const Eigen::Matrix3d Kinv = camera.K().inverse();
    const Eigen::Matrix3d C = ellipse_conic(e);
    const Eigen::Matrix3d Kd = camera.K();
    const CircleFromConic circle = circle_from_conic(Kd.transpose() * C * Kd);
    obs.normal_camera = circle.normal;
    obs.centre_normalised = circle.centre;
    const Eigen::Vector3d ec = Kinv * Eigen::Vector3d(e.center.x, e.center.y, 1.0);
    obs.ellipse_centre = pixel_of_normalised(ec.head<2>(), camera);
    obs.centre_px = pixel_of_normalised(0.5 * (circle.centre[0] + circle.centre[1]), camera);
    obs.white_diameter_px = std::max(e.size.width, e.size.height);
    obs.ring_ratio = c.ring.ring_ratio;
    obs.diameter_px = obs.white_diameter_px * std::max(1.0, obs.ring_ratio);
    obs.contrast = c.ring.white - c.ring.black;
    obs.white_level = c.ring.white;
    out.push_back(obs);
  }
  std::sort(out.begin(), out.end(),
            [](const auto& a, const auto& b) { return a.contrast > b.contrast; });
  return out;
}

}  // namespace

std::vector<TargetObservation> detect_targets(const cv::Mat& image, const CameraIntrinsics& camera,
                                              const TargetDetectorOptions& o) {
  return detect_targets_at(image, camera, o,
                           std::vector<int>(kThresholds.begin(), kThresholds.end()));
}

std::vector<TargetObservation> detect_targets_in_the_dark(const cv::Mat& image,
                                                          const CameraIntrinsics& camera,
                                                          const TargetDetectorOptions& o) {
  return detect_targets_at(image, camera, o, {30, 45, 60, 80, 120, 160, 200});
}

namespace {

std::string where_looked(const cv::Mat& image, const TargetDetectorOptions& o) {
  std::ostringstream s;
  s << "searched the whole " << image.cols << "x" << image.rows << " px image for a white disk "
    << o.min_white_diameter_px << " to "
    << static_cast<int>(o.max_white_diameter_fraction * image.rows)
    << " px across inside a black ring of any width (contrast >= " << o.min_contrast
    << " grey levels, ring darker than " << o.max_black_to_white
    << " of the disk's white on nine rays in ten) at thresholds 80, 120, 160, 200";
  return s.str();
}

std::string position(const TargetObservation& t) {
  return "(" + format_fixed(t.centre_px.x(), 1) + ", " + format_fixed(t.centre_px.y(), 1) + ")";
}

// Why a target of the pole was not found, when a look with relaxed limits
// finds it: too little light on it (its white is dark), a veil over it
// (dust, glare: its black is raised), or too much light (its white clipped
// and its ring bright). Empty when nothing target-like is there at all
// (the pole is out of view or hidden): the caller says where it looked.
std::string why_targets_missed(const cv::Mat& image, const CameraIntrinsics& camera,
                               const std::vector<TargetObservation>& found,
                               const TargetDetectorOptions& o, const std::string& where) {
  // Relaxed: a quarter of the contrast (10 grey levels still outline a
  // disk in an 8-bit image with a few levels of noise), a ring up to 0.75
  // of the white, thresholds down into the shadows and up to the clip.
  TargetDetectorOptions relaxed = o;
  relaxed.min_contrast = 10;
  relaxed.max_black_to_white = 0.75;
  const auto near =
      detect_targets_at(image, camera, relaxed, {20, 35, 50, 65, 80, 120, 160, 200, 235});
  std::vector<TargetObservation> missed;
  for (const auto& t : near) {
    bool known = false;
    for (const auto& f : found)
      if ((f.centre_px - t.centre_px).norm() < 0.5 * f.white_diameter_px) known = true;
    if (!known) missed.push_back(t);
  }
  if (missed.empty()) return {};
  // The pole's other target: below the one found is the lower, above it the
  // upper; with none found, the lowest in the image is the lower.
  std::sort(missed.begin(), missed.end(),
            [](const auto& a, const auto& b) { return a.centre_px.y() > b.centre_px.y(); });
  std::ostringstream s;
  for (std::size_t k = 0; k < missed.size() && k < 2; ++k) {
    const TargetObservation& t = missed[k];
    std::string name = "target";
    if (found.size() == 1)
      name = t.centre_px.y() > found[0].centre_px.y() ? "lower target" : "upper target";
    else if (missed.size() >= 2)
      name = k == 0 ? "lower target" : "upper target";
    const double black = t.white_level - t.contrast;
    std::string state;
    // Printed white under good light is > 150 grey levels; under 100 the
    // ring's edge is lost in noise before the contrast limit is reached.
    if (t.white_level >= 250 && black > o.max_black_to_white * t.white_level)
      state = "over-exposed (its white clipped at " + std::to_string(int(t.white_level)) +
              " and its black ring at " + std::to_string(int(black)) +
              "): too much flash or lamp on the pole, or the pole too near the light";
    else if (t.white_level < 100)
      state =
          "under-exposed (its white at " + std::to_string(int(t.white_level)) + " grey levels, " +
          std::to_string(int(t.contrast)) + " above its black ring, where the detector needs " +
          std::to_string(int(o.min_contrast)) + "): light the pole (flash, lamp) or expose longer";
    else
      state = "veiled (its black ring at " + std::to_string(int(black)) + " under a white of " +
              std::to_string(int(t.white_level)) + ", " + std::to_string(int(t.contrast)) +
              " grey levels of contrast where the detector needs " +
              std::to_string(int(o.min_contrast)) +
              "): dust haze or glare between the camera and the pole; wait for the dust to "
              "settle or come closer";
    s << (k ? "; " : "") << name << " " << state << ", in the " << where << " at " << position(t)
      << " px";
  }
  return s.str();
}

}  // namespace

RangePoleTargets find_range_pole(const cv::Mat& left_image, const cv::Mat& right_image,
                                 const CameraIntrinsics& left, const CameraIntrinsics& right,
                                 const RelativeOrientation& ro, const TargetDetectorOptions& o) {
  // A pole in the dark (a tunnel lit by a flash or lamps): its white below
  // the usual thresholds, its contrast still enough; looked for again with
  // thresholds down into the shadows when the usual ones miss a target.
  auto detect = [&](const cv::Mat& image, const CameraIntrinsics& camera) {
    auto found = detect_targets(image, camera, o);
    if (found.size() < 2) {
      auto dark = detect_targets_in_the_dark(image, camera, o);
      if (dark.size() > found.size()) found = std::move(dark);
    }
    return found;
  };
  const auto tl = detect(left_image, left);
  const auto tr = detect(right_image, right);
  for (int side = 0; side < 2; ++side) {
    const auto& found = side == 0 ? tl : tr;
    const cv::Mat& img = side == 0 ? left_image : right_image;
    const std::string which = side == 0 ? "left" : "right";
    if (found.size() < 2) {
      const std::string why =
          why_targets_missed(img, side == 0 ? left : right, found, o, which + " image");
      if (!why.empty()) throw InputError("range pole", why);
    }
    if (found.empty())
      throw InputError("range pole",
                       "no target found in the " + which + " image: " + where_looked(img, o));
    if (found.size() == 1)
      throw InputError("range pole", "only one target found in the " + which + " image, at " +
                                         position(found[0]) + " px: " + where_looked(img, o) +
                                         "; both targets of the pole must be in view");
  }

  const double focal = 0.5 * (left.fx + right.fx);
  auto best_partner = [&](const TargetObservation& a, double& err) {
    return epipolar_partner(a, tr, ro, focal, kTargetEpipolarPx, err);
  };

  double best_score = 1e300;
  std::array<int, 4> choice{-1, -1, -1, -1};  // left lower, left upper, right lower, right upper
  for (std::size_t i = 0; i < tl.size(); ++i)
    for (std::size_t j = 0; j < tl.size(); ++j) {
      if (i == j) continue;
      const auto& lo = tl[i];
      const auto& up = tl[j];
      const Eigen::Vector2d d = up.centre_px - lo.centre_px;
      if (d.y() >= 0) continue;  // upper must be higher in the image
      if (std::abs(d.x()) > 0.5 * std::abs(d.y()))
        continue;  // a vertical pole, camera without roll
      const double ratio = up.white_diameter_px / lo.white_diameter_px;
      if (ratio < 0.5 || ratio > 2.0) continue;
      double e_lo = 0, e_up = 0;
      const int rl = best_partner(lo, e_lo), ru = best_partner(up, e_up);
      if (rl < 0 || ru < 0 || rl == ru) continue;
      const double score = e_lo + e_up;
      if (score < best_score) {
        best_score = score;
        choice = {static_cast<int>(i), static_cast<int>(j), rl, ru};
      }
    }
  if (choice[0] < 0) {
    std::ostringstream s;
    s << "found " << tl.size() << " target(s) in the left image and " << tr.size()
      << " in the right, but no two in the left image stand one above the other with partners "
         "on their epipolar lines (within "
      << kTargetEpipolarPx << " px) in the right image; left image targets at";
    for (const auto& t : tl) s << " " << position(t);
    throw InputError("range pole", s.str());
  }

  RangePoleTargets out;
  out.smallest_diameter_px = 1e300;
  for (int k = 0; k < 2; ++k) {
    const TargetPair pair =
        triangulate_target_pair(tl[choice[k]], tr[choice[2 + k]], left, right, ro);
    out.left[k] = pair.left;
    out.right[k] = pair.right;
    out.model[k] = pair.model;
    out.smallest_diameter_px =
        std::min({out.smallest_diameter_px, pair.left.diameter_px, pair.right.diameter_px});
  }
  return out;
}

}  // namespace rockface::photogrammetry
