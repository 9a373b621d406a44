// The mock camera's tunnel effects, each alone: it changes the render only
// where and as much as it should, and nothing is simulated unasked.
#include <cmath>

#include <gtest/gtest.h>

#include "camera/synthetic_renderer.h"
#include "camera/tunnel_lighting.h"
#include "core/measure/least_cost_trace.h"
#include "tests/support/lit_face.h"

using namespace rockface;
using namespace rockface::testing;
using Eigen::Vector3d;

namespace {

camera::SyntheticRender render(const camera::SyntheticScene& s) {
  NoProgress quiet;
  return camera::render_scene(s, quiet);
}

double mean_green(const cv::Mat& image, const cv::Rect& r) {
  return cv::mean(image(r))[1];
}

// A region on the middle facet, 1.2 m wide and 1.6 m high, about its centre.
camera::SyntheticRegion middle_region(const std::string& id) {
  const FacetTruth& f = synthetic_facets()[1];
  camera::SyntheticRegion r{id, {}};
  for (auto [x, z] : {std::pair{-0.6, -0.3}, {0.6, -0.3}, {0.6, 1.3}, {-0.6, 1.3}})
    r.polygon.emplace_back(x, facet_y(f, x, z), z);
  return r;
}

}  // namespace

TEST(LitRender, NothingIsSimulatedUnasked) {
  const camera::SyntheticScene plain = lit_face({});
  EXPECT_TRUE(plain.effects.simulated().empty());
  // Regions that lie off the face go through the tunnel's shading path and
  // must leave every pixel as the plain render has it.
  camera::SyntheticScene off = plain;
  camera::SyntheticRegion away{"far", {{50, 50, 0}, {51, 50, 0}, {51, 50, 1}}};
  off.effects.wet.push_back({away});
  off.effects.shotcrete.push_back({away});
  EXPECT_EQ((std::vector<std::string>{"wet", "shotcrete"}), off.effects.simulated());
  const auto a = render(plain), b = render(off);
  EXPECT_EQ(cv::norm(a.images[0], b.images[0], cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(a.images[1], b.images[1], cv::NORM_INF), 0.0);
}

TEST(LitRender, VignettingDarkensTheCornersNotTheCentre) {
  camera::SyntheticEffects e;
  e.vignetting = 1.0;
  const auto base = render(lit_face({})), vig = render(lit_face(e));
  const cv::Mat &a = base.images[0], &b = vig.images[0];
  const cv::Rect centre(590, 390, 20, 20);
  // At the centre cos^4 of < 0.01 rad is 1 to 1e-4: the same to a grey level.
  EXPECT_NEAR(mean_green(b, centre), mean_green(a, centre), 0.5);
  // A corner block of the face (lower left, on a facet): the cos^4 law at
  // its ray, x = -0.42, y = 0.26 in normalised coordinates: 0.64; rounding
  // to whole grey levels moves the ratio by < 1 %.
  const cv::Rect corner(90, 690, 20, 20);
  const double x = (100 - base.intrinsics.cx) / base.intrinsics.fx;
  const double y = (700 - base.intrinsics.cy) / base.intrinsics.fy;
  const double expected = camera::vignetting_factor(x, y, 1.0);
  EXPECT_LT(expected, 0.8);
  EXPECT_NEAR(mean_green(b, corner) / mean_green(a, corner), expected, 0.02);
}

TEST(LitRender, DustFollowsKoschmieder) {
  camera::SyntheticEffects e;
  e.dust = camera::SyntheticDust{0.05, 0.35};
  const auto base = render(lit_face({})), dusty = render(lit_face(e));
  const auto& cam = base.intrinsics;
  int checked = 0;
  for (int v = 100; v < 800; v += 97)
    for (int u = 100; u < 1200; u += 101) {
      const float z = base.depth_left.at<float>(v, u);
      if (z <= 0) continue;
      const double x = (u - cam.cx) / cam.fx, y = (v - cam.cy) / cam.fy;
      const double range = z * std::sqrt(1 + x * x + y * y);
      const double t = std::exp(-0.05 * range);
      // The airlight is neutral grey, whatever the surface's colour.
      const double expected = base.images[0].at<cv::Vec3b>(v, u)[1] * t + 255 * 0.35 * (1 - t);
      // Rounding of the two renders: 0.5 + 0.5 t grey levels at most.
      EXPECT_NEAR(dusty.images[0].at<cv::Vec3b>(v, u)[1], expected, 1.0) << u << "," << v;
      ++checked;
    }
  EXPECT_GT(checked, 40);
}

TEST(LitRender, FlashFallsOffWithDistanceAndIncidence) {
  // One wall face-on to the left station, 6 m away: under the flash a point
  // at angle theta off the axis is at 6 / cos(theta) and lit at incidence
  // theta: cos^3(theta) of the centre, which the flash exposes to full white.
  camera::SyntheticScene s = lit_face({});
  s.patches = {{"wall", {{-20, 6, -20}, {20, 6, -20}, {20, 6, 20}, {-20, 6, 20}}}};
  s.joints.clear();
  s.range_pole.reset();
  s.reference_line.reset();
  s.stations[0] = {{0, 0, 0}, {0, 6, 0}};
  s.stations[1] = {{1, 0, 0}, {1, 6, 0}};
  camera::SyntheticScene lit = s;
  lit.effects.flash = camera::SyntheticFlash{0.5};  // half: nothing clips
  const auto base = render(s), flash = render(lit);
  const auto& cam = base.intrinsics;
  const Vector3d lamp(0.5, 0, 0);  // the default headlamp: between the stations
  for (auto [u, v] : {std::pair{600, 400}, {100, 100}, {1100, 700}, {300, 650}}) {
    const double x = (u - cam.cx) / cam.fx, y = (v - cam.cy) / cam.fy;
    const Vector3d q(6 * x, 6, -6 * y);  // camera y points down, world z up
    const double cos_t = 1 / std::sqrt(1 + x * x + y * y);
    const double headlamp = 0.3 + 0.7 * std::max(0.0, -(lamp - q).normalized().y());
    const double expected =
        base.images[0].at<cv::Vec3b>(v, u)[1] * 0.5 * std::pow(cos_t, 3) / headlamp;
    // Both renders round to whole grey levels: 1 level on either.
    EXPECT_NEAR(flash.images[0].at<cv::Vec3b>(v, u)[1], expected, 1.5) << u << "," << v;
  }
}

TEST(LitRender, SensorNoiseAtIso3200IsShotAndReadNoise) {
  camera::SyntheticEffects a, b;
  a.sensor = camera::SyntheticSensor{3200};
  b.sensor = a.sensor;
  b.sensor->seed = 2;
  const auto ra = render(lit_face(a)), rb = render(lit_face(b));
  // Two renders that differ only in the noise: their difference has twice
  // the noise variance. At a grey level g the noise is sqrt(g k + r^2) / k,
  // k = 40000 / 32 / 255 = 4.9 e- per level, r = 3 e-: at g 128, 5.1 levels.
  const double k = 40000.0 / 32 / 255;
  double sum2 = 0, expected2 = 0;
  int n = 0;
  for (int v = 0; v < 800; ++v)
    for (int u = 0; u < 1200; ++u) {
      const int ga = ra.images[0].at<cv::Vec3b>(v, u)[1], gb = rb.images[0].at<cv::Vec3b>(v, u)[1];
      const double g = 0.5 * (ga + gb);
      if (g < 60 || g > 200) continue;  // away from the clip and the dark
      sum2 += (ga - gb) * (ga - gb) / 2.0;
      expected2 += (g * k + 9) / (k * k) + 1.0 / 12;  // + rounding
      ++n;
    }
  ASSERT_GT(n, 10000);
  // ~10^5 pixels: the variance is estimated to < 1 %; 5 % allows the mean
  // level standing in for each pixel's true level.
  EXPECT_NEAR(sum2 / expected2, 1.0, 0.05);
}

TEST(LitRender, JpegQualityLeavesBlocksNotAnotherPicture) {
  camera::SyntheticEffects e;
  e.jpeg_quality = 80;
  const auto base = render(lit_face({})), jpeg = render(lit_face(e));
  const double diff = cv::norm(base.images[0], jpeg.images[0], cv::NORM_L1) /
                      static_cast<double>(base.images[0].total() * 3);
  EXPECT_GT(diff, 0.2);  // it did run
  EXPECT_LT(diff, 3.0);  // JPEG 80 of a textured 8-bit image: ~1-2 levels mean error
}

TEST(LitRender, ShotcreteHidesTheTracesAndChangesOnlyItsRegion) {
  camera::SyntheticScene base = lit_face({});
  // A joint whose trace runs across the middle facet, through the region.
  base.joints.push_back({"J1", geometry::plane_normal_deg(80, 95), Vector3d(0, 10, 0.5)});
  camera::SyntheticScene sprayed = base;
  sprayed.effects.shotcrete.push_back({middle_region("S1")});
  const auto a = render(base), b = render(sprayed);

  // Truth traces: the joint's trace on the middle facet is cut where the
  // shotcrete is, and no remaining piece has a point inside the region.
  const camera::PreparedRegion region(middle_region("S1"), "test");
  int pieces_a = 0, pieces_b = 0;
  for (const auto& t : a.traces) pieces_a += t.joint == "J1";
  for (const auto& t : b.traces) {
    if (t.joint != "J1") continue;
    ++pieces_b;
    for (int k = 1; k < 20; ++k)
      EXPECT_FALSE(region.contains(t.world[0] + (t.world[1] - t.world[0]) * (k / 20.0)));
  }
  EXPECT_EQ(pieces_b, pieces_a + 1);  // one trace split in two around the region

  // Pixels: outside the region's image, the renders agree exactly.
  const auto& pose = a.poses[0];
  std::vector<cv::Point2f> outline;
  for (const auto& p : middle_region("S1").polygon) {
    const Eigen::Vector2d px = pixel_of(p, pose, a.intrinsics);
    outline.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
  }
  int inside_changed = 0, inside = 0;
  for (int v = 0; v < 800; v += 3)
    for (int u = 0; u < 1200; u += 3) {
      const double d = cv::pointPolygonTest(outline, cv::Point2f(u, v), true);
      const bool same = a.images[0].at<cv::Vec3b>(v, u) == b.images[0].at<cv::Vec3b>(v, u);
      if (d < -2) {
        EXPECT_TRUE(same) << u << "," << v;
      }
      if (d > 2) {
        ++inside;
        inside_changed += !same;
      }
    }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(inside_changed, 0.95 * inside);

  // Semi-automatic tracing along the joint's line across the region: on the
  // bare rock it follows a dark line (low cost), on the shotcrete there is
  // none to follow.
  const auto line_of = [&](const camera::SyntheticRender& r) {
    for (const auto& t : r.traces)
      if (t.joint == "J1" && t.patch == "facet") {
        // The middle facet's piece: the one nearest the image centre.
        const Eigen::Vector2d mid = 0.5 * (t.left_image.front() + t.left_image.back());
        if (std::abs(mid.x() - 600) < 200) return t;
      }
    return camera::TraceTruth{};
  };
  const camera::TraceTruth whole = line_of(a);
  ASSERT_GE(whole.left_image.size(), 2u);
  // Ends 0.1 m outside the region along the trace, where both images show rock.
  measure::TraceRequest request;
  Eigen::Vector2d from, to;
  {
    const Vector3d w0 = whole.world[0], w1 = whole.world[1];
    const Vector3d dir = (w1 - w0).normalized();
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k <= 400; ++k) {
      const Vector3d p = w0 + (w1 - w0) * (k / 400.0);
      if (region.contains(p)) {
        lo = std::min(lo, (p - w0).dot(dir));
        hi = std::max(hi, (p - w0).dot(dir));
      }
    }
    ASSERT_LT(lo, hi);
    from = pixel_of(w0 + (lo - 0.1) * dir, pose, a.intrinsics);
    to = pixel_of(w0 + (hi + 0.1) * dir, pose, a.intrinsics);
  }
  request.from = from;
  request.to = to;
  const auto on_rock = measure::trace_between(a.images[0], nullptr, request, "rock");
  const auto on_shotcrete = measure::trace_between(b.images[0], nullptr, request, "shotcrete");
  std::printf("mean cost per step: on the rock %.3f, across the shotcrete %.3f\n",
              on_rock.mean_cost, on_shotcrete.mean_cost);
  // least_cost_trace_test: a path on a dark line costs < 0.3 per step.
  EXPECT_LT(on_rock.mean_cost, 0.3);
  // Across the shotcrete the path finds no dark line: at least twice the
  // cost of following one.
  EXPECT_GT(on_shotcrete.mean_cost, 2 * on_rock.mean_cost);
}
