#include "core/measure/proposals/line_evidence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include <opencv2/imgproc.hpp>

#include "core/measure/proposals/disc_morphology.h"
#include "core/measure/proposals/line_thinning.h"
#include "core/measure/proposals/row_stripes.h"
#include "core/measure/proposals/triangle_index_raster.h"

namespace rockface::measure::proposals {

namespace {

// Bilinear sample of a single-channel float image; NaN off the image.
float sample(const cv::Mat& m, double x, double y) {
  if (m.cols < 2 || m.rows < 2 || !(x >= 0 && y >= 0 && x <= m.cols - 1 && y <= m.rows - 1))
    return std::numeric_limits<float>::quiet_NaN();
  const int x0 = std::min(static_cast<int>(x), m.cols - 2);
  const int y0 = std::min(static_cast<int>(y), m.rows - 2);
  const int x1 = x0 + 1, y1 = y0 + 1;
  const double fx = x - x0, fy = y - y0;
  const double top = (1 - fx) * m.at<float>(y0, x0) + fx * m.at<float>(y0, x1);
  const double bottom = (1 - fx) * m.at<float>(y1, x0) + fx * m.at<float>(y1, x1);
  return static_cast<float>((1 - fy) * top + fy * bottom);
}

cv::Vec3f sample3(const cv::Mat& m, double x, double y) {
  const int xi = static_cast<int>(std::lround(x)), yi = static_cast<int>(std::lround(y));
  if (xi < 0 || yi < 0 || xi >= m.cols || yi >= m.rows)
    return cv::Vec3f(std::nanf(""), std::nanf(""), std::nanf(""));
  return m.at<cv::Vec3f>(yi, xi);
}

bool masked_in(const cv::Mat& mask, double x, double y) {
  const int xi = static_cast<int>(std::lround(x)), yi = static_cast<int>(std::lround(y));
  return xi >= 0 && yi >= 0 && xi < mask.cols && yi < mask.rows && mask.at<std::uint8_t>(yi, xi);
}

// Median and robust sigma (1.4826 MAD) of a float image over the mask,
// from a sample of at most ~200,000 pixels.
std::pair<double, double> robust_level(const cv::Mat& values, const cv::Mat& mask) {
  std::vector<float> v;
  const std::size_t total = static_cast<std::size_t>(values.rows) * values.cols;
  const int stride = static_cast<int>(std::max<std::size_t>(1, total / 200000));
  for (int r = 0; r < values.rows; ++r)
    for (int c = (r * 7) % stride; c < values.cols; c += stride)
      if (mask.at<std::uint8_t>(r, c)) v.push_back(values.at<float>(r, c));
  if (v.empty()) return {0, 1};
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  const double median = *mid;
  for (float& x : v) x = std::abs(x - static_cast<float>(median));
  std::nth_element(v.begin(), mid, v.end());
  return {median, std::max(1.4826 * *mid, 1e-6)};
}

// Each pixel of `shown` (CV_32S, -1 where nothing is drawn) set to the
// index of the last of the mesh's triangles, in the mesh's order, that
// reaches its square, of the ones `drawn(t)` is true for, at `scale`
// of the mesh's lattice pixels (core/measure/proposals/
// triangle_index_raster.h). Each stripe of rows draws the triangles that
// reach its rows, into its rows only: the rule gives a pixel the same
// triangle wherever the image is cut.
template <class Drawn>
void draw_triangle_indices(const photogrammetry::SurfaceMesh& mesh, double scale, cv::Mat& shown,
                           const Drawn& drawn) {
  // The corners in fixed point once, not once a stripe for each of the
  // six triangles a lattice vertex is a corner of.
  std::vector<cv::Point> fixed(mesh.pixels.size());
  const double to_fixed = scale * (1 << kRasterShift);
  cv::parallel_for_(cv::Range(0, static_cast<int>(fixed.size())), [&](const cv::Range& range) {
    for (int i = range.start; i < range.end; ++i) {
      const Eigen::Vector2f& p = mesh.pixels[static_cast<std::size_t>(i)];
      fixed[static_cast<std::size_t>(i)] =
          cv::Point(cvRound(p.x() * to_fixed), cvRound(p.y() * to_fixed));
    }
  });
  for_row_stripes(shown.size(), [&](cv::Range rows) {
    cv::Mat own = shown.rowRange(rows);
    // The rows a triangle may reach: within half a pixel of its corners'.
    constexpr int kHalf = 1 << (kRasterShift - 1);
    const int from = (rows.start << kRasterShift) - kHalf;
    const int to = ((rows.end - 1) << kRasterShift) + kHalf;
    cv::Point corners[3];
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const auto& t = mesh.triangles[i];
      for (int k = 0; k < 3; ++k) corners[k] = fixed[static_cast<std::size_t>(t[k])];
      if (std::max({corners[0].y, corners[1].y, corners[2].y}) < from ||
          std::min({corners[0].y, corners[1].y, corners[2].y}) > to)
        continue;
      if (!drawn(t)) continue;
      draw_triangle_index(own, rows.start, corners, static_cast<int>(i));
    }
  });
}

}  // namespace

cv::Mat hysteresis(const cv::Mat& keep, const cv::Mat& seed) {
  // Grown from the seeds over the kept pixels only (the lines are a few
  // thousandths of the image): the groups a labelling of every group of
  // the whole image finds, without labelling the ones no seed is in.
  cv::Mat out(keep.size(), CV_8U, cv::Scalar(0));
  const int w = keep.cols, h = keep.rows;
  std::vector<cv::Point> queue;
  for (int r = 0; r < h; ++r) {
    const std::uint8_t* k = keep.ptr<std::uint8_t>(r);
    const std::uint8_t* s = seed.ptr<std::uint8_t>(r);
    std::uint8_t* o = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < w; ++c)
      if (s[c] && k[c] && !o[c]) {
        o[c] = 255;
        queue.emplace_back(c, r);
      }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const cv::Point p = queue[head];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = p.x + dx, y = p.y + dy;
        if (x < 0 || y < 0 || x >= w || y >= h) continue;
        if (!keep.at<std::uint8_t>(y, x) || out.at<std::uint8_t>(y, x)) continue;
        out.at<std::uint8_t>(y, x) = 255;
        queue.emplace_back(x, y);
      }
  }
  return out;
}

DarkLines find_dark_lines(const cv::Mat& grey, const cv::Mat& mask,
                          const DarkLineSettings& settings) {
  const cv::Size size = grey.size();
  cv::Mat best(size, CV_32F, cv::Scalar(-1e30)), angle(size, CV_32F, cv::Scalar(0)),
      width(size, CV_32F, cv::Scalar(0));
  cv::Mat g(size, CV_32F);
  for (double w : settings.widths_px) {
    // A bar of width w answers the second derivative best at a Gaussian
    // of about half its width; sigma^2 makes the scales comparable.
    const double sigma = std::max(0.8, 0.5 * w);
    for_row_stripes(size, [&](cv::Range rows) {
      cv::Mat g_rows = g.rowRange(rows);
      cv::GaussianBlur(grey.rowRange(rows), g_rows, cv::Size(0, 0), sigma);
    });
    for_row_stripes(size, [&](cv::Range rows) {
      cv::Mat dxx, dyy, dxy;
      cv::Sobel(g.rowRange(rows), dxx, CV_32F, 2, 0, 3, 0.25);
      cv::Sobel(g.rowRange(rows), dyy, CV_32F, 0, 2, 3, 0.25);
      cv::Sobel(g.rowRange(rows), dxy, CV_32F, 1, 1, 3, 0.25);
      // Largest Hessian eigenvalue: positive across a valley of brightness;
      // its eigenvector's angle, doubled. One pass over the derivatives,
      // the angle by cv::phase a row at a time (issue 45: whole-stripe
      // temporaries cost more than the arithmetic).
      std::vector<float> diff(static_cast<std::size_t>(size.width)),
          twice(static_cast<std::size_t>(size.width)),
          response(static_cast<std::size_t>(size.width)),
          across(static_cast<std::size_t>(size.width));
      cv::Mat across_row(1, size.width, CV_32F, across.data());
      const float scale = static_cast<float>(sigma * sigma);
      for (int r = rows.start; r < rows.end; ++r) {
        const int k = r - rows.start;
        const float* xx = dxx.ptr<float>(k);
        const float* yy = dyy.ptr<float>(k);
        const float* xy = dxy.ptr<float>(k);
        for (int c = 0; c < size.width; ++c) {
          const auto i = static_cast<std::size_t>(c);
          const float half_diff = 0.5f * (xx[c] - yy[c]);
          const float root = std::sqrt(half_diff * half_diff + xy[c] * xy[c]);
          response[i] = (0.5f * (xx[c] + yy[c]) + root) * scale;
          diff[i] = xx[c] - yy[c];
          twice[i] = 2 * xy[c];
        }
        cv::phase(cv::Mat(1, size.width, CV_32F, diff.data()),
                  cv::Mat(1, size.width, CV_32F, twice.data()), across_row);
        float* b = best.ptr<float>(r);
        float* a = angle.ptr<float>(r);
        float* wd = width.ptr<float>(r);
        for (int c = 0; c < size.width; ++c) {
          const auto i = static_cast<std::size_t>(c);
          if (response[i] > b[c]) {
            b[c] = response[i];
            a[c] = 0.5f * across[i];
            wd[c] = static_cast<float>(w);
          }
        }
      }
    });
  }
  const auto [median, noise] = robust_level(best, mask);
  // The brightness the sides are compared with: lightly smoothed (noise).
  cv::Mat smooth(size, CV_32F);
  for_row_stripes(size, [&](cv::Range rows) {
    cv::Mat smooth_rows = smooth.rowRange(rows);
    cv::GaussianBlur(grey.rowRange(rows), smooth_rows, cv::Size(0, 0), 0.8);
  });

  DarkLines out;
  out.noise = noise;
  out.sigmas = cv::Mat(size, CV_32F, cv::Scalar(0));
  out.contrast = cv::Mat(size, CV_32F, cv::Scalar(0));
  cv::Mat keep(size, CV_8U, cv::Scalar(0)), seed(size, CV_8U, cv::Scalar(0));
  const double keep_level = median + settings.keep_sigmas * noise;
  const double seed_level = median + settings.seed_sigmas * noise;
  for_row_stripes(size, [&](cv::Range rows) {
    for (int r = rows.start; r < rows.end; ++r)
      for (int c = 0; c < size.width; ++c) {
        const float v = best.at<float>(r, c);
        if (v < keep_level || !mask.at<std::uint8_t>(r, c)) continue;
        const double nx = std::cos(angle.at<float>(r, c)), ny = std::sin(angle.at<float>(r, c));
        // Non-maximum suppression across the line.
        const float a = sample(best, c + nx, r + ny), b = sample(best, c - nx, r - ny);
        if ((std::isfinite(a) && a > v) || (std::isfinite(b) && b >= v)) continue;
        // Darker than both sides: a line, not the dark side of a step.
        const double d = width.at<float>(r, c) + 1.0;
        const float side_a = sample(smooth, c + d * nx, r + d * ny);
        const float side_b = sample(smooth, c - d * nx, r - d * ny);
        if (!std::isfinite(side_a) || !std::isfinite(side_b)) continue;
        const double contrast = std::min(side_a, side_b) - smooth.at<float>(r, c);
        if (contrast < settings.min_contrast_grey) continue;
        keep.at<std::uint8_t>(r, c) = 255;
        if (v >= seed_level) seed.at<std::uint8_t>(r, c) = 255;
        out.sigmas.at<float>(r, c) = static_cast<float>((v - median) / noise);
        out.contrast.at<float>(r, c) = static_cast<float>(contrast);
      }
  });
  out.lines = zhang_suen_thinning(hysteresis(keep, seed));
  return out;
}

SurfaceImage draw_surface(const photogrammetry::SurfaceMesh& mesh, cv::Size size, double scale,
                          const Eigen::Vector3d& camera_centre, double max_edge_m,
                          double smoothing_px) {
  SurfaceImage out;
  if (!mesh.empty()) out.origin = mesh.vertices[0];
  // A triangle's normal turned toward the camera and its centre; false for
  // one left out (across a depth jump, or without area).
  const auto facing = [&](const std::array<int, 3>& t, Eigen::Vector3d& n,
                          Eigen::Vector3d& centre) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    if ((b - a).norm() > max_edge_m || (c - b).norm() > max_edge_m || (a - c).norm() > max_edge_m)
      return false;
    n = (b - a).cross(c - a);
    if (n.squaredNorm() == 0) return false;
    n.normalize();
    centre = (a + b + c) / 3.0;
    if (n.dot(camera_centre - centre) < 0) n = -n;
    return true;
  };
  // Each pixel shows the last triangle drawn over it. The triangles are
  // rasterised once, as their indices, and the normals, points and mask
  // filled from them: the pixels and values three fills per triangle gave,
  // at a third of the fills (at 24 Mpx, a triangle covers a pixel or two
  // and each fill's own overhead was most of the stage).
  cv::Mat shown(size, CV_32S, cv::Scalar(-1));
  draw_triangle_indices(mesh, scale, shown, [&](const std::array<int, 3>& t) {
    Eigen::Vector3d n, centre;
    return facing(t, n, centre);
  });
  cv::Mat normals(size, CV_32FC3);
  out.points.create(size, CV_32FC3);
  out.mask = cv::Mat(size, CV_8U);
  for_row_stripes(size, [&](cv::Range rows) {
    // A triangle shows in a pixel or a few side by side: its values are
    // worked out once for a run of pixels.
    int last = -1;
    Eigen::Vector3d n, centre;
    cv::Vec3f last_normal, last_point;
    for (int r = rows.start; r < rows.end; ++r) {
      const int* index = shown.ptr<int>(r);
      auto* normal = normals.ptr<cv::Vec3f>(r);
      auto* point = out.points.ptr<cv::Vec3f>(r);
      std::uint8_t* in = out.mask.ptr<std::uint8_t>(r);
      for (int c = 0; c < size.width; ++c) {
        const int i = index[c];
        if (i < 0) {
          normal[c] = cv::Vec3f(0, 0, 0);
          point[c] = cv::Vec3f(0, 0, 0);
          in[c] = 0;
          continue;
        }
        if (i != last) {
          facing(mesh.triangles[static_cast<std::size_t>(i)], n, centre);
          const Eigen::Vector3d rel = centre - out.origin;
          last_normal = cv::Vec3f(static_cast<float>(n.x()), static_cast<float>(n.y()),
                                  static_cast<float>(n.z()));
          last_point = cv::Vec3f(static_cast<float>(rel.x()), static_cast<float>(rel.y()),
                                 static_cast<float>(rel.z()));
          last = i;
        }
        normal[c] = last_normal;
        point[c] = last_point;
        in[c] = 255;
      }
    }
  });
  // Only the normals are smoothed. Unit normals summed over the Gaussian
  // are as long as the surface's share of it (less where they spread), so
  // their length says how much surface is near: beyond the surface's edge
  // the zeros are not pulled in, they only shorten the sum, which is
  // normalised away (the normalised convolution without a weight image of
  // its own). The points were smoothed too once; their one use is the side
  // of a fold the normal turns to (find_folds), decided 2 x smoothing_px
  // apart where the surface's own noise is millimetres: the drawn
  // triangle's centre serves, and the two blurs (weight, points) were 4 of
  // the 7 channels of the stage's costliest work (issue 45).
  out.normals.create(size, CV_32FC3);
  for_row_stripes(size, [&](cv::Range rows) {
    cv::Mat bn = out.normals.rowRange(rows);
    cv::GaussianBlur(normals.rowRange(rows), bn, cv::Size(0, 0), smoothing_px);
    for (int r = rows.start; r < rows.end; ++r) {
      auto* normal = out.normals.ptr<cv::Vec3f>(r);
      for (int c = 0; c < size.width; ++c) {
        cv::Vec3f& n = normal[c];
        const float len = static_cast<float>(cv::norm(n));
        // 1e-3: the share of surface below which the old weight image
        // left a pixel without normal.
        if (len > 1e-3f)
          n /= len;
        else
          n = cv::Vec3f(0, 0, 0);
      }
    }
  });
  return out;
}

Folds find_folds(const SurfaceImage& surface, const FoldSettings& settings) {
  const cv::Size size = surface.normals.size();
  cv::Mat strength(size, CV_32F), across(size, CV_32F);
  for_row_stripes(size, [&](cv::Range rows) {
    cv::Mat gx, gy;
    cv::Sobel(surface.normals.rowRange(rows), gx, CV_32F, 1, 0, 3, 0.125);
    cv::Sobel(surface.normals.rowRange(rows), gy, CV_32F, 0, 1, 3, 0.125);
    // Structure tensor of the normal field: how fast, and across which
    // direction, the normal turns. One pass over the gradients (issue 45:
    // a dozen whole-stripe temporaries, each megabytes to fault in afresh,
    // were most of the stage's CPU); the doubled angle by cv::phase a row
    // at a time, as before.
    std::vector<float> diff(static_cast<std::size_t>(size.width)),
        twice(static_cast<std::size_t>(size.width));
    for (int r = rows.start; r < rows.end; ++r) {
      const int k = r - rows.start;
      const auto* x = gx.ptr<cv::Vec3f>(k);
      const auto* y = gy.ptr<cv::Vec3f>(k);
      float* out_strength = strength.ptr<float>(r);
      for (int c = 0; c < size.width; ++c) {
        const cv::Vec3f& a = x[c];
        const cv::Vec3f& b = y[c];
        const float jxx = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        const float jyy = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
        const float jxy = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        const float half_diff = 0.5f * (jxx - jyy);
        const float root = std::sqrt(half_diff * half_diff + jxy * jxy);
        out_strength[c] = std::sqrt(std::max(0.5f * (jxx + jyy) + root, 0.0f));
        diff[static_cast<std::size_t>(c)] = jxx - jyy;
        twice[static_cast<std::size_t>(c)] = 2 * jxy;
      }
      cv::Mat across_row = across.row(r);
      cv::phase(cv::Mat(1, size.width, CV_32F, diff.data()),
                cv::Mat(1, size.width, CV_32F, twice.data()), across_row);
    }
  });

  // The two sides are read two smoothing widths out, where the smoothed
  // normal is within 2 % of each side's own; both must be on the surface.
  const double reach = 2.0 * settings.smoothing_px;
  const cv::Mat inner = erode_disc(surface.mask, static_cast<int>(std::ceil(reach)) + 1);

  Folds out;
  out.angle = cv::Mat(size, CV_32F, cv::Scalar(0));
  out.ridge = cv::Mat(size, CV_8U, cv::Scalar(0));
  cv::Mat keep(size, CV_8U, cv::Scalar(0)), seed(size, CV_8U, cv::Scalar(0));
  const double keep_cos = std::cos(settings.keep_deg * M_PI / 180);
  for_row_stripes(size, [&](cv::Range rows) {
    for (int r = rows.start; r < rows.end; ++r)
      for (int c = 0; c < size.width; ++c) {
        if (!inner.at<std::uint8_t>(r, c)) continue;
        const float v = strength.at<float>(r, c);
        if (v <= 0) continue;
        const double ux = std::cos(0.5 * across.at<float>(r, c));
        const double uy = std::sin(0.5 * across.at<float>(r, c));
        const float a = sample(strength, c + ux, r + uy), b = sample(strength, c - ux, r - uy);
        if ((std::isfinite(a) && a > v) || (std::isfinite(b) && b >= v)) continue;
        if (!masked_in(surface.mask, c + reach * ux, r + reach * uy) ||
            !masked_in(surface.mask, c - reach * ux, r - reach * uy))
          continue;
        const cv::Vec3f na = sample3(surface.normals, c - reach * ux, r - reach * uy);
        const cv::Vec3f nb = sample3(surface.normals, c + reach * ux, r + reach * uy);
        const double cosine = std::clamp(static_cast<double>(na.dot(nb)), -1.0, 1.0);
        if (cosine > keep_cos) continue;
        const double deg = std::acos(cosine) * 180 / M_PI;
        const cv::Vec3f pa = sample3(surface.points, c - reach * ux, r - reach * uy);
        const cv::Vec3f pb = sample3(surface.points, c + reach * ux, r + reach * uy);
        keep.at<std::uint8_t>(r, c) = 255;
        if (deg >= settings.seed_deg) seed.at<std::uint8_t>(r, c) = 255;
        out.angle.at<float>(r, c) = static_cast<float>(deg);
        // Convex when the normal turns the way one walks across: a ridge.
        if ((nb - na).dot(pb - pa) > 0) out.ridge.at<std::uint8_t>(r, c) = 255;
      }
  });
  out.lines = zhang_suen_thinning(hysteresis(keep, seed));
  return out;
}

}  // namespace rockface::measure::proposals
