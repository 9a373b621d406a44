// The phases of the merge of several 3D images
// (multi_image_registration_phases.h), each on its own: which images form a
// wave (a station waits for a neighbour that overlaps it clearly better and
// is no farther from being placed; none left gives an empty wave), the tie
// points' RMS counts only those within the distance, the residuals follow
// the ground control's scale (the master's stays), and the coarse overlaps
// are one measurement per pair, the reverse shift mirrored.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include <opencv2/core.hpp>

#include "core/photogrammetry/reconstruction/multi_image_registration_phases.h"

namespace {

namespace rp = rockface::photogrammetry;
namespace phases = rockface::photogrammetry::registration_phases;

// Symmetric overlaps of n images with the given responses (i < j).
phases::CoarseOverlaps overlaps(std::size_t n,
                                const std::vector<std::tuple<int, int, double>>& responses) {
  phases::CoarseOverlaps c(n, std::vector<rp::CoarseOverlap>(n));
  for (const auto& [i, j, r] : responses) {
    c[i][j].response = r;
    c[j][i].response = r;
  }
  return c;
}

TEST(MultiImagePhases, TheMastersNeighboursOnBothSidesFormTheFirstWave) {
  // A row of stations 3 1 0 2 4: the master's neighbours 1 and 2 go
  // together; 3 and 4 overlap only 1 and 2 and have no placed neighbour yet.
  const auto c = overlaps(5, {{0, 1, 0.5}, {0, 2, 0.5}, {1, 3, 0.5}, {2, 4, 0.5}, {0, 3, 0.1}});
  const std::vector<bool> placed = {true, false, false, false, false};
  const std::vector<char> failed(5, 0);
  EXPECT_EQ(phases::next_wave(c, placed, failed, 0.8), (std::vector<std::size_t>{1, 2}));
}

TEST(MultiImagePhases, AnImageWaitsForANeighbourThatOverlapsItClearlyBetter) {
  // 2 overlaps the master weakly (0.1) and 1 strongly (0.5); 1 overlaps the
  // master well: 2 waits for 1.
  const auto c = overlaps(3, {{0, 1, 0.6}, {0, 2, 0.1}, {1, 2, 0.5}});
  const std::vector<char> failed(3, 0);
  EXPECT_EQ(phases::next_wave(c, {true, false, false}, failed, 0.8), (std::vector<std::size_t>{1}));
  // Once 1 has failed, 2 no longer waits for it.
  EXPECT_EQ(phases::next_wave(c, {true, false, false}, {0, 1, 0}, 0.8),
            (std::vector<std::size_t>{2}));
}

TEST(MultiImagePhases, WithoutAnyOverlapTheBestImageGoesAloneAndNoneLeftIsAnEmptyWave) {
  const auto c = overlaps(3, {});
  EXPECT_EQ(phases::next_wave(c, {true, false, false}, {0, 0, 0}, 0.8),
            (std::vector<std::size_t>{1}));
  EXPECT_TRUE(phases::next_wave(c, {true, false, false}, {0, 1, 1}, 0.8).empty());
  EXPECT_TRUE(phases::next_wave(c, {true, true, true}, {0, 0, 0}, 0.8).empty());
}

TEST(MultiImagePhases, TheTiePointRmsCountsOnlyThePointsWithinTheDistance) {
  rp::TiePoints tie;
  tie.slave = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  // After a shift of +1 in x: off by 0.3, 0.4 and 5 (an outlier).
  tie.reference = {{1.3, 0, 0}, {2, 0.4, 0}, {3, 5, 0}};
  rp::Similarity shift;
  shift.t = Eigen::Vector3d(1, 0, 0);
  EXPECT_NEAR(phases::tie_point_rms(tie, shift, 1.0), std::sqrt((0.09 + 0.16) / 2), 1e-12);
  EXPECT_EQ(phases::tie_point_rms(tie, shift, 0.1), 0.0);
}

TEST(MultiImagePhases, TheResidualsFollowTheGroundControlsScaleTheMastersStays) {
  rp::FaceRegistration face;
  face.images.resize(2);
  for (auto& r : face.images) {
    r.surface_rms_before_icp_m = 2;
    r.surface_rms_m = 1;
    r.tie_rms_m = 0.5;
  }
  rp::FaceRegistration without = face;
  phases::scale_residuals(without);
  EXPECT_EQ(without.images[1].surface_rms_m, 1.0);
  face.control_points.emplace();
  face.control_points->transform.scale = 3;
  phases::scale_residuals(face);
  EXPECT_EQ(face.images[0].surface_rms_m, 1.0);
  EXPECT_EQ(face.images[1].surface_rms_before_icp_m, 6.0);
  EXPECT_EQ(face.images[1].surface_rms_m, 3.0);
  EXPECT_EQ(face.images[1].tie_rms_m, 1.5);
}

TEST(MultiImagePhases, TheCoarseOverlapsAreOneMeasurementPerPairTheReverseMirrored) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> grey(0, 255);
  cv::Mat rock(240, 320, CV_8UC1);
  for (int y = 0; y < rock.rows; ++y)
    for (int x = 0; x < rock.cols; ++x) rock.at<unsigned char>(y, x) = grey(rng);
  cv::Mat shifted = cv::Mat::zeros(rock.size(), rock.type());
  rock(cv::Rect(40, 0, 280, 240)).copyTo(shifted(cv::Rect(0, 0, 280, 240)));
  const std::vector<rp::Thumbnail> thumbnails = {rp::make_thumbnail(rock),
                                                 rp::make_thumbnail(shifted)};
  const phases::CoarseOverlaps c = phases::coarse_overlaps(thumbnails);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0][1].response, c[1][0].response);
  EXPECT_EQ(c[0][1].shift_px, Eigen::Vector2d(-c[1][0].shift_px));
  EXPECT_GT(c[0][1].response, 0.3);
  EXPECT_EQ(c[0][0].response, 0.0);
}

}  // namespace
