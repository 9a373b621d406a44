// The cues' image work over stripes of rows (proposals/row_stripes.h,
// issue 45): the surface drawn, its folds and the dark lines on two or
// three threads are, pixel for pixel and value for value, those of one
// thread (ROCKFACE_THREADS=1: the one call over the whole image), on
// images whose width is odd (stripes that would cut OpenCV's vectors) and
// on a mesh with triangles taller than a stripe's margin. The faces are
// made here with folds and dark lines in them, so that each cue has pixels
// to compare.
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/measure/proposals/line_evidence.h"
#include "core/measure/proposals/row_stripes.h"

namespace {

namespace pr = rockface::measure::proposals;
using rockface::photogrammetry::SurfaceMesh;

// ROCKFACE_THREADS set for a scope, the former value back after.
class Threads {
 public:
  explicit Threads(const char* n) {
    if (const char* was = std::getenv("ROCKFACE_THREADS")) was_ = was;
    ::setenv("ROCKFACE_THREADS", n, 1);
  }
  ~Threads() {
    if (was_)
      ::setenv("ROCKFACE_THREADS", was_->c_str(), 1);
    else
      ::unsetenv("ROCKFACE_THREADS");
  }
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;

 private:
  std::optional<std::string> was_;
};

// Elements that differ (NaN equal to NaN), over all channels.
int differing(const cv::Mat& a, const cv::Mat& b) {
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(a.type(), b.type());
  if (a.size() != b.size() || a.type() != b.type()) return -1;
  const cv::Mat a1 = a.reshape(1), b1 = b.reshape(1);
  int n = 0;
  for (int r = 0; r < a1.rows; ++r)
    for (int c = 0; c < a1.cols; ++c) {
      if (a1.depth() == CV_8U) {
        n += a1.at<std::uint8_t>(r, c) != b1.at<std::uint8_t>(r, c);
      } else {
        const float x = a1.at<float>(r, c), y = b1.at<float>(r, c);
        n += !(x == y || (std::isnan(x) && std::isnan(y)));
      }
    }
  return n;
}

// A face seen square from the origin along +z, 10 m away, one vertex per
// 1.37 photograph pixels (the working image a fraction of it): two folds
// running obliquely across it, of 25 and 15 degrees.
SurfaceMesh folded_face(int columns, int rows) {
  SurfaceMesh mesh;
  const double f = 1000, step = 1.37;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const double u = 0.3 + step * i, v = 0.45 + step * j;
      const double s = 0.8 * u + 0.6 * v;  // across the folds, px
      // 0.01 m on the face per photograph pixel at 10 m.
      const double depth = 10 + 0.01 * std::abs(s - 250) * std::tan(0.22) -
                           0.01 * std::max(0.0, s - 420) * std::tan(0.26);
      mesh.vertices.emplace_back(u / f * depth, v / f * depth, depth);
      mesh.pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
    }
  for (int j = 0; j + 1 < rows; ++j)
    for (int i = 0; i + 1 < columns; ++i) {
      const int a = j * columns + i, b = a + 1, c = a + columns, d = c + 1;
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, c});
    }
  return mesh;
}

struct Cues {
  pr::SurfaceImage surface;
  pr::Folds folds;
};

Cues cues_on(const SurfaceMesh& mesh, cv::Size size, const char* threads) {
  const Threads t(threads);
  Cues out;
  out.surface = pr::draw_surface(mesh, size, 0.8, Eigen::Vector3d::Zero(), 10.0, 3.0);
  pr::FoldSettings settings;
  settings.smoothing_px = 3.0;
  out.folds = pr::find_folds(out.surface, settings);
  return out;
}

void expect_same_cues(const Cues& one, const Cues& many) {
  EXPECT_EQ(differing(one.surface.mask, many.surface.mask), 0);
  EXPECT_EQ(differing(one.surface.normals, many.surface.normals), 0);
  EXPECT_EQ(differing(one.surface.points, many.surface.points), 0);
  EXPECT_EQ(differing(one.folds.lines, many.folds.lines), 0);
  EXPECT_EQ(differing(one.folds.angle, many.folds.angle), 0);
  EXPECT_EQ(differing(one.folds.ridge, many.folds.ridge), 0);
}

TEST(RowStripes, StartAtMultiplesOf64ElementsAndCoverTheImage) {
  for (const cv::Size size : {cv::Size(613, 411), cv::Size(640, 480), cv::Size(2283, 1522),
                              cv::Size(7, 40), cv::Size(1, 1)}) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
      const std::vector<int> starts = pr::row_stripe_starts(size, threads);
      ASSERT_FALSE(starts.empty());
      EXPECT_EQ(starts.front(), 0);
      EXPECT_LE(starts.size(), threads);
      for (std::size_t i = 0; i < starts.size(); ++i) {
        EXPECT_EQ((static_cast<long>(starts[i]) * size.width) % 64, 0)
            << size << " stripe " << i << " of " << threads;
        if (i > 0) {
          EXPECT_GT(starts[i], starts[i - 1]);
        }
        EXPECT_LT(starts[i], size.height);
      }
    }
  }
  // Two threads on the tablet's 24 Mpx working image: two stripes, the
  // first within 64 rows (one step of 64 rows) of half.
  const std::vector<int> starts = pr::row_stripe_starts(cv::Size(2283, 1522), 2);
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_NEAR(starts[1], 761, 64);
}

TEST(RowStripes, TheSurfaceAndItsFoldsAreThoseOfOneThread) {
  const SurfaceMesh mesh = folded_face(560, 430);
  const cv::Size size(613, 471);  // 0.8 of the lattice's pixels; odd width
  const Cues one = cues_on(mesh, size, "1");
  ASSERT_GT(cv::countNonZero(one.surface.mask), size.area() / 2);
  ASSERT_GT(cv::countNonZero(one.folds.lines), 300) << "the face's two folds";
  ASSERT_GT(cv::countNonZero(one.folds.ridge), 100) << "the ridge";
  expect_same_cues(one, cues_on(mesh, size, "2"));
  expect_same_cues(one, cues_on(mesh, size, "3"));
}

TEST(RowStripes, TrianglesTallerThanAStripesMarginAreDrawnAsByOneThread) {
  SurfaceMesh mesh = folded_face(560, 430);
  // Long thin triangles over the lattice, across every stripe's edge
  // (drawn last: they show over the lattice's): an imported mesh's coarse
  // triangles are like them.
  cv::RNG rng(4545);
  const auto vertex = [](int row, int column) { return row * 560 + column; };
  for (int k = 0; k < 40; ++k) {
    const int row = rng.uniform(0, 100), column = rng.uniform(0, 500);
    const int low_row = rng.uniform(row + 100, 430), low_column = rng.uniform(0, 560);
    mesh.triangles.push_back({vertex(row, column), vertex(row, column + rng.uniform(2, 60)),
                              vertex(low_row, low_column)});
  }
  const cv::Size size(613, 471);
  expect_same_cues(cues_on(mesh, size, "1"), cues_on(mesh, size, "2"));
}

TEST(RowStripes, TheDarkLinesAreThoseOfOneThread) {
  const cv::Size size(613, 411);
  cv::Mat grey(size, CV_32F, cv::Scalar(150));
  cv::RNG rng(45);
  for (int k = 0; k < 14; ++k) {
    const cv::Point a(rng.uniform(0, size.width), rng.uniform(0, size.height));
    const cv::Point b(rng.uniform(0, size.width), rng.uniform(0, size.height));
    cv::line(grey, a, b, cv::Scalar(rng.uniform(60, 120)), rng.uniform(1, 5), cv::LINE_AA);
  }
  cv::Mat noise(size, CV_32F);
  rng.fill(noise, cv::RNG::NORMAL, 0, 4);
  grey += noise;
  cv::Mat mask(size, CV_8U, cv::Scalar(255));
  cv::circle(mask, {400, 200}, 60, cv::Scalar(0), cv::FILLED);
  pr::DarkLineSettings settings;
  settings.widths_px = {2.0, 3.5, 6.0};
  pr::DarkLines one, two, three;
  {
    const Threads t("1");
    one = pr::find_dark_lines(grey, mask, settings);
  }
  {
    const Threads t("2");
    two = pr::find_dark_lines(grey, mask, settings);
  }
  {
    const Threads t("3");
    three = pr::find_dark_lines(grey, mask, settings);
  }
  ASSERT_GT(cv::countNonZero(one.lines), 1000) << "the fourteen lines";
  for (const pr::DarkLines* many : {&two, &three}) {
    EXPECT_EQ(one.noise, many->noise);
    EXPECT_EQ(differing(one.lines, many->lines), 0);
    EXPECT_EQ(differing(one.sigmas, many->sigmas), 0);
    EXPECT_EQ(differing(one.contrast, many->contrast), 0);
  }
}

}  // namespace
