#include "core/photogrammetry/targets/cloud_range_pole.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/photogrammetry/targets/circular_target.h"

namespace rockface::photogrammetry {

namespace {

// The cloud drawn along the line of sight: each pixel a point of the surface
// nearest the viewer (the one nearest the pixel's centre). Pixel (i, j)'s centre is origin + i
// pixel right + j pixel down.
struct CloudPicture {
  Eigen::Vector3d origin, right, down, toward;
  double pixel = 0;
  cv::Mat image;             // BGR
  std::vector<int> nearest;  // point index per pixel, -1: none
  int width = 0, height = 0;
};

// A pixel's front surface: its points within this many pixels of its
// nearest to the viewer. 2: a surface seen 60 degrees off its normal spans
// 1.7 pixels of depth across a pixel, with a scanner's scatter; a plate
// stands metres (at least several spacings) in front of the rock.
constexpr double kFrontSurfacePixels = 2;

// Where no point is drawn: grey, as the virtual view's holes, so that an
// island of bright rock amid no data is not a white disk in a black ring.
constexpr std::uint8_t kNoData = 128;

// Axes of the picture: looking against `toward`, the cloud's up drawn up.
void picture_axes(CloudPicture& p, const Eigen::Vector3d& toward, const Eigen::Vector3d& up) {
  p.toward = toward.normalized();
  Eigen::Vector3d upright = up - up.dot(p.toward) * p.toward;
  // 1e-6: up along the line of sight: any direction across it will do.
  if (upright.norm() < 1e-6) upright = p.toward.unitOrthogonal();
  p.down = -upright.normalized();
  p.right = p.down.cross(-p.toward);  // x right, y down, z forward: a camera's axes
}

CloudPicture draw_cloud(const std::vector<Eigen::Vector3d>& points,
                        const std::vector<std::array<std::uint8_t, 3>>& colours,
                        const Eigen::Vector3d& toward, const Eigen::Vector3d& up, double spacing,
                        const CloudPoleOptions& o) {
  CloudPicture p;
  picture_axes(p, toward, up);
  const Eigen::Vector3d c = points.front();  // coordinates relative to it: no precision lost
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto& q : points) {
    const Eigen::Vector2d uv((q - c).dot(p.right), (q - c).dot(p.down));
    lo = lo.cwiseMin(uv);
    hi = hi.cwiseMax(uv);
  }
  const Eigen::Vector2d extent = hi - lo;
  p.pixel = std::max(o.pixel_to_spacing * spacing, extent.maxCoeff() / (o.max_side_px - 1));
  p.width = static_cast<int>(std::floor(extent.x() / p.pixel)) + 1;
  p.height = static_cast<int>(std::floor(extent.y() / p.pixel)) + 1;
  p.origin = c + lo.x() * p.right + lo.y() * p.down;
  const auto size = static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height);
  p.nearest.assign(size, -1);
  std::vector<float> height_toward(size, -std::numeric_limits<float>::infinity());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d d = points[k] - p.origin;
    const auto i = static_cast<int>(std::lround(d.dot(p.right) / p.pixel));
    const auto j = static_cast<int>(std::lround(d.dot(p.down) / p.pixel));
    if (i < 0 || j < 0 || i >= p.width || j >= p.height) continue;
    const auto at = static_cast<std::size_t>(j) * static_cast<std::size_t>(p.width) +
                    static_cast<std::size_t>(i);
    const auto h = static_cast<float>(d.dot(p.toward));
    if (h > height_toward[at]) {
      height_toward[at] = h;
      p.nearest[at] = static_cast<int>(k);
    }
  }
  // Of the points on the front surface of each pixel (within two pixels of
  // its nearest to the viewer: the plate, not the rock behind it), the one
  // nearest the pixel's centre gives its colour. The nearest to the viewer
  // alone was biased on a plate tilted to the line of sight: its nearer
  // edge lies to one side of each pixel, so the picture showed the plate
  // shifted by a fifth of a pixel (a lower target facing up came out 0.17 to
  // 0.28 px up the pole, the pole 0.09 to 0.35 % short).
  const auto window = static_cast<float>(kFrontSurfacePixels * p.pixel);
  std::vector<float> off_centre(size, std::numeric_limits<float>::infinity());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d d = points[k] - p.origin;
    const double x = d.dot(p.right) / p.pixel, y = d.dot(p.down) / p.pixel;
    const auto i = static_cast<int>(std::lround(x));
    const auto j = static_cast<int>(std::lround(y));
    if (i < 0 || j < 0 || i >= p.width || j >= p.height) continue;
    const auto at = static_cast<std::size_t>(j) * static_cast<std::size_t>(p.width) +
                    static_cast<std::size_t>(i);
    if (static_cast<float>(d.dot(p.toward)) < height_toward[at] - window) continue;
    const auto d2 = static_cast<float>((x - i) * (x - i) + (y - j) * (y - j));
    if (d2 < off_centre[at]) {
      off_centre[at] = d2;
      p.nearest[at] = static_cast<int>(k);
    }
  }
  // A pixel the sampling left empty takes its nearest-to-the-viewer
  // neighbour's point: one pass closes the one-pixel gaps of an uneven
  // sampling, and grows a hole's edge by a pixel at most.
  std::vector<int> shown = p.nearest;
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i) {
      const auto at = static_cast<std::size_t>(j) * static_cast<std::size_t>(p.width) +
                      static_cast<std::size_t>(i);
      if (p.nearest[at] >= 0) continue;
      float best = -std::numeric_limits<float>::infinity();
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ni = i + di, nj = j + dj;
          if (ni < 0 || nj < 0 || ni >= p.width || nj >= p.height) continue;
          const auto n = static_cast<std::size_t>(nj) * static_cast<std::size_t>(p.width) +
                         static_cast<std::size_t>(ni);
          if (p.nearest[n] >= 0 && height_toward[n] > best) {
            best = height_toward[n];
            shown[at] = p.nearest[n];
          }
        }
    }
  p.image.create(p.height, p.width, CV_8UC3);
  for (int j = 0; j < p.height; ++j) {
    auto* row = p.image.ptr<cv::Vec3b>(j);
    for (int i = 0; i < p.width; ++i) {
      const int k = shown[static_cast<std::size_t>(j) * static_cast<std::size_t>(p.width) +
                          static_cast<std::size_t>(i)];
      if (k < 0) {
        row[i] = cv::Vec3b(kNoData, kNoData, kNoData);
      } else {
        const auto& rgb = colours[static_cast<std::size_t>(k)];
        row[i] = cv::Vec3b(rgb[2], rgb[1], rgb[0]);
      }
    }
  }
  return p;
}

// The target in the cloud: the plane of the points drawn in its white disk
// (those within the disk's major radius whose grey is above the middle of
// the disk's white and the ring's black: the disk seen obliquely is
// narrower across), fitted twice (points beyond 3 robust sigmas of the
// first fit left out: rock seen through a gap of the plate's sampling), cut
// by the line of sight through the disk's centre.
std::optional<CloudTarget> target_in_cloud(const CloudPicture& p,
                                           const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<std::array<std::uint8_t, 3>>& colours,
                                           const TargetObservation& seen) {
  const double cx = seen.ellipse_centre.x(), cy = seen.ellipse_centre.y();
  const double radius = 0.5 * seen.white_diameter_px;
  const double white_from = seen.white_level - 0.5 * seen.contrast;
  std::vector<Eigen::Vector3d> disk;
  for (int j = static_cast<int>(std::floor(cy - radius)); j <= static_cast<int>(cy + radius); ++j)
    for (int i = static_cast<int>(std::floor(cx - radius)); i <= static_cast<int>(cx + radius);
         ++i) {
      if (i < 0 || j < 0 || i >= p.width || j >= p.height) continue;
      if (std::hypot(i - cx, j - cy) > radius) continue;
      const int k = p.nearest[static_cast<std::size_t>(j) * static_cast<std::size_t>(p.width) +
                              static_cast<std::size_t>(i)];
      if (k < 0) continue;
      const auto& rgb = colours[static_cast<std::size_t>(k)];
      // ITU-R BT.601 luma, as OpenCV's BGR to grey that the detector saw.
      const double grey = 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2];
      if (grey >= white_from) disk.push_back(points[static_cast<std::size_t>(k)]);
    }
  // 6: a plane through a handful of noisy points is no plane.
  if (disk.size() < 6) return std::nullopt;
  Eigen::Vector3d centroid, normal;
  auto fit = [&](const std::vector<Eigen::Vector3d>& q) {
    centroid = Eigen::Vector3d::Zero();
    for (const auto& x : q) centroid += x;
    centroid /= static_cast<double>(q.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& x : q) cov += (x - centroid) * (x - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    normal = es.eigenvectors().col(0);
    if (normal.dot(p.toward) < 0) normal = -normal;
  };
  fit(disk);
  std::vector<double> residual;
  for (const auto& x : disk) residual.push_back(std::abs((x - centroid).dot(normal)));
  std::vector<double> sorted = residual;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double sigma = 1.4826 * sorted[sorted.size() / 2];  // the median's sigma of a normal law
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t k = 0; k < disk.size(); ++k)
    if (residual[k] <= 3 * sigma) kept.push_back(disk[k]);
  if (kept.size() >= 6) fit(kept);
  // 0.2: a plate seen more than 78 degrees off its normal gives no centre.
  const double facing = normal.dot(p.toward);
  if (facing < 0.2) return std::nullopt;
  const Eigen::Vector3d on_sight = p.origin + cx * p.pixel * p.right + cy * p.pixel * p.down;
  CloudTarget t;
  t.centre = on_sight + normal.dot(centroid - on_sight) / facing * p.toward;
  t.normal = normal;
  t.white_diameter = seen.white_diameter_px * p.pixel;  // the major axis: the disk across
  t.disk_points = static_cast<int>(kept.size() >= 6 ? kept.size() : disk.size());
  return t;
}

// How far a pair is from a pole's: its worst criterion over its limit
// (<= 1: a pole's pair), and that criterion in words.
struct PairScore {
  double score = 0;
  std::string worst;
};

PairScore pole_pair_score(const CloudTarget& a, const CloudTarget& b, const CloudPoleOptions& o) {
  PairScore s;
  auto take = [&](double value, const std::string& words) {
    if (value > s.score) {
      s.score = value;
      s.worst = words;
    }
  };
  const double ratio =
      std::max(a.white_diameter, b.white_diameter) / std::min(a.white_diameter, b.white_diameter);
  take((ratio - 1) / (o.max_size_ratio - 1),
       "sizes " + format_significant(ratio, 3) + " times apart");
  const double facing = rad_to_deg(std::acos(std::clamp(a.normal.dot(b.normal), -1.0, 1.0)));
  take(facing / o.max_normal_angle_deg, "facing " + format_significant(facing, 3) + " deg apart");
  const Eigen::Vector3d along = b.centre - a.centre;
  const Eigen::Vector3d axis = along.normalized();
  const double off_plane = rad_to_deg(std::asin(
      std::min(1.0, std::max(std::abs(axis.dot(a.normal)), std::abs(axis.dot(b.normal))))));
  take(off_plane / o.max_pole_to_plane_deg,
       "the line between them " + format_significant(off_plane, 3) + " deg out of their planes");
  const double apart = along.norm() / (0.5 * (a.white_diameter + b.white_diameter));
  take(std::max(o.min_separation_diameters / apart, apart / o.max_separation_diameters),
       format_significant(apart, 3) + " diameters apart");
  return s;
}

std::string words_of(const Eigen::Vector3d& p) {
  return "(" + format_significant(p.x(), 7) + ", " + format_significant(p.y(), 7) + ", " +
         format_significant(p.z(), 7) + ")";
}

}  // namespace

CloudRangePole find_range_pole_in_cloud(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<std::array<std::uint8_t, 3>>& colours,
                                        const Eigen::Vector3d& toward_viewer, double point_spacing,
                                        const Eigen::Vector3d& up, const CloudPoleOptions& o) {
  if (points.empty() || colours.size() != points.size())
    throw InputError("range pole",
                     "the cloud has no colours: its targets cannot be found in it (pick them)");
  if (!(point_spacing > 0) || !(toward_viewer.norm() > 0) || !(up.norm() > 0))
    throw InputError("range pole", "no point spacing or viewing direction to draw the cloud by");
  const CloudPicture picture = draw_cloud(points, colours, toward_viewer, up, point_spacing, o);

  // A camera so long that its perspective vanishes: the detector's
  // normalised coordinates are then the picture's, and its centre
  // correction nil.
  CameraIntrinsics parallel;
  parallel.width = picture.width;
  parallel.height = picture.height;
  parallel.fx = parallel.fy = 1e6;
  parallel.cx = 0.5 * (picture.width - 1);
  parallel.cy = 0.5 * (picture.height - 1);
  const std::vector<TargetObservation> seen = detect_targets(picture.image, parallel);
  std::vector<CloudTarget> targets;
  for (const auto& s : seen)
    if (const auto t = target_in_cloud(picture, points, colours, s)) targets.push_back(*t);

  CloudRangePole pole;
  pole.targets_seen = targets.size();
  pole.pixel = picture.pixel;
  const std::string drawn = "the cloud's colours drawn " + std::to_string(picture.width) + " x " +
                            std::to_string(picture.height) + " px at " +
                            format_significant(picture.pixel, 3) + " a pixel";
  if (targets.empty())
    throw InputError("range pole", "no circular target (a white disk in a black ring) in " + drawn +
                                       " (a white disk needs 3 px, " +
                                       format_significant(3 * picture.pixel, 3) +
                                       ", across or more)");
  if (targets.size() == 1)
    throw InputError("range pole", "one target found in " + drawn + ", at " +
                                       words_of(targets[0].centre) + ": the pole has two");

  // Every pair scored; the best must qualify and no other come near.
  struct Pair {
    std::size_t a, b;
    PairScore s;
  };
  std::vector<Pair> pairs;
  for (std::size_t a = 0; a < targets.size(); ++a)
    for (std::size_t b = a + 1; b < targets.size(); ++b)
      pairs.push_back({a, b, pole_pair_score(targets[a], targets[b], o)});
  std::sort(pairs.begin(), pairs.end(),
            [](const Pair& x, const Pair& y) { return x.s.score < y.s.score; });
  const Pair& best = pairs.front();
  if (best.s.score > 1)
    throw InputError("range pole", std::to_string(targets.size()) + " targets found in " + drawn +
                                       ", no two of them a pole's (one size, facing one way, the "
                                       "pole in their planes, " +
                                       format_significant(o.min_separation_diameters, 3) + " to " +
                                       format_significant(o.max_separation_diameters, 3) +
                                       " diameters apart); the nearest pair: " + best.s.worst);
  if (pairs.size() > 1 && pairs[1].s.score <= o.ambiguity_margin)
    throw InputError("range pole", "two pairs of targets could be the pole's: at " +
                                       words_of(targets[best.a].centre) + " and " +
                                       words_of(targets[best.b].centre) + ", or at " +
                                       words_of(targets[pairs[1].a].centre) + " and " +
                                       words_of(targets[pairs[1].b].centre) + " (pick them)");

  CloudTarget lower = targets[best.a], upper = targets[best.b];
  const Eigen::Vector3d axis = (upper.centre - lower.centre).normalized();
  const double rise = rad_to_deg(std::asin(std::min(1.0, std::abs(axis.dot(up.normalized())))));
  if (rise < kMinPoleRiseDeg)
    throw InputError("range pole",
                     "the pole found (targets at " + words_of(lower.centre) + " and " +
                         words_of(upper.centre) + ") lies " + format_significant(rise, 3) +
                         " deg from the cloud's horizontal: which target is the lower is not "
                         "known below " +
                         format_significant(kMinPoleRiseDeg, 3) + " deg (pick them)");
  if (axis.dot(up) < 0) std::swap(lower, upper);
  pole.targets = {lower, upper};
  return pole;
}

}  // namespace rockface::photogrammetry
