// Several 3D images of one face: the synthetic face (synthetic_face.h) is
// photographed as three stereo pairs from stations 2 m apart along it, each
// seeing ~5.4 m of the 8.4 m face. The middle pair (the master) is
// registered by range pole and compass; the two others are reconstructed
// unscaled and registered to it by tie points and ICP. Checked against the
// truth: the merged surface, traces that run across the photographs, ground
// control residuals, and a pair of another face refused by name.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>

#include "core/common/error.h"
#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/surface/face_traces.h"
#include "core/photogrammetry/surface/pixel_lookup.h"
#include "tests/support/multi_image_face.h"

namespace rp = rockface::photogrammetry;
namespace cam = rockface::camera;
using rockface::testing::facet_y;
using rockface::testing::pixel_of;
using rockface::testing::synthetic_facets;

namespace {

constexpr double kStationOffsets[3] = {0.0, -2.0, 2.0};  // master first

using Pair = rockface::testing::FacePair;
using rockface::testing::distance_to_face;
using rockface::testing::face_image;
using rockface::testing::photograph_and_reconstruct;

cam::SyntheticScene face_from(double x_offset) {
  return rockface::testing::multi_image_face(x_offset);
}

class MultiImage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    pairs_ = new std::vector<Pair>();
    for (int k = 0; k < 3; ++k)
      pairs_->push_back(photograph_and_reconstruct(face_from(kStationOffsets[k]), k == 0));
  }
  static void TearDownTestSuite() {
    delete pairs_;
    pairs_ = nullptr;
  }
  static std::vector<rp::FaceImage> images() {
    std::vector<rp::FaceImage> out;
    const char* names[3] = {"pair 1 (middle)", "pair 2 (west)", "pair 3 (east)"};
    for (int k = 0; k < 3; ++k) out.push_back(face_image((*pairs_)[k], names[k]));
    return out;
  }
  // Face frame -> scene frame (multi_image_face.h).
  static Eigen::Vector3d origin() { return rockface::testing::face_origin((*pairs_)[0]); }
  static std::vector<Pair>* pairs_;
};
std::vector<Pair>* MultiImage::pairs_ = nullptr;

}  // namespace

TEST_F(MultiImage, MergedSurfaceMatchesTheTruth) {
  rockface::NoProgress progress;
  const auto imgs = images();
  const rp::FaceRegistration face =
      rp::register_face_images(imgs, {}, rp::preset_standard(), {}, progress);
  ASSERT_EQ(face.images.size(), 3u);
  const double sigma_z = (*pairs_)[0].result.accuracy.sigma_z;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = face.images[i];
    double sum2 = 0;
    std::size_t n = 0, far = 0;
    double west = 1e9, east = -1e9;
    for (std::size_t v = 0; v < imgs[i].mesh.size(); v += 5) {
      const Eigen::Vector3d w = r.to_face.apply(imgs[i].mesh.vertices[v]) + origin();
      const auto d = distance_to_face(w);
      if (!d) continue;
      // The pole stands 3 m in front of the face: its points are not face.
      if (*d > 0.5) {
        ++far;
        continue;
      }
      sum2 += *d * *d;
      ++n;
      west = std::min(west, w.x());
      east = std::max(east, w.x());
    }
    const double rms = std::sqrt(sum2 / static_cast<double>(n));
    std::printf(
        "%s: ref %d, %d tie points (rms %.4f m), overlap %.2f, surface rms %.4f m (before ICP "
        "%.4f), scale %.4f; to truth rms %.4f m over %zu points, x %.2f..%.2f\n",
        r.name.c_str(), r.reference, r.tie_points, r.tie_rms_m, r.overlap, r.surface_rms_m,
        r.surface_rms_before_icp_m, r.to_face.scale, rms, n, west, east);
    EXPECT_LT(static_cast<double>(far), 0.1 * static_cast<double>(n));
    // The stated error: each point's depth noise (sigma_Z ~ 7 mm, the
    // prediction is conservative) plus the master's pole and compass
    // registration, which moves every image alike (~5 mm over the face). A
    // slave turned by 0.3 deg or scaled 0.5 % by its tie points would add
    // 1.5 cm at its far end.
    EXPECT_LT(rms, 1.5 * sigma_z + 0.005) << r.name;
    if (i > 0) {
      EXPECT_EQ(r.reference, 0);
      EXPECT_GE(r.tie_points, 100);
      // Surfaces agree where they overlap to about two depth noises.
      EXPECT_LT(r.surface_rms_m, 3 * sigma_z);
      // Neighbours at 2 m of 5.4 m wide views share ~60 % of their frames,
      // less the strip dense matching leaves at the frame edges and the pole.
      EXPECT_GT(r.overlap, 0.25);
      EXPECT_LT(r.overlap, 0.9);
    }
  }
  // Together the images reach further along the face than the master alone.
  const rp::SurfaceMesh merged = rp::merged_surface(imgs, face);
  double west = 1e9, east = -1e9;
  for (const auto& v : merged.vertices) {
    const Eigen::Vector3d w = v + origin();
    if (!distance_to_face(w) || *distance_to_face(w) > 0.5) continue;
    west = std::min(west, w.x());
    east = std::max(east, w.x());
  }
  EXPECT_LT(west, -3.8);
  EXPECT_GT(east, 3.8);
}

TEST_F(MultiImage, TracesAcrossPhotographsBecomeOneTrace) {
  rockface::NoProgress progress;
  const auto imgs = images();
  const rp::FaceRegistration face =
      rp::register_face_images(imgs, {}, rp::preset_standard(), {}, progress);
  // Each pair's true traces as the geologist would mark them on its left
  // photograph: the part inside the frame.
  std::vector<rp::ImageTrace> marked;
  std::map<std::string, std::array<Eigen::Vector3d, 2>> truth;  // joint/patch -> segment
  std::map<std::string, int> images_per_trace;
  for (int k = 0; k < 3; ++k) {
    const auto& render = (*pairs_)[k].render;
    for (std::size_t t = 0; t < render.traces.size(); ++t) {
      const auto& tr = render.traces[t];
      rp::ImageTrace piece{
          "pair" + std::to_string(k) + "/" + tr.joint + "/" + std::to_string(t), tr.joint, k, {}};
      for (const auto& px : tr.left_image)
        if (px.x() > 10 && px.y() > 10 && px.x() < 1190 && px.y() < 790) piece.pixels.push_back(px);
      if (piece.pixels.size() < 20) continue;
      // Only a piece on the reconstructed surface counts (J2 runs along the
      // edge of the master's surface).
      if (rp::traces_in_face_frame(imgs, face, {piece}).empty()) continue;
      const std::string key = tr.joint + "/" + std::to_string(t);
      truth[key] = tr.world;
      ++images_per_trace[key];
      marked.push_back(piece);
    }
  }
  int most = 0;
  for (const auto& [key, count] : images_per_trace) most = std::max(most, count);
  ASSERT_EQ(most, 3);
  const auto traces = rp::traces_in_face_frame(imgs, face, marked);
  // One face trace per true (joint, patch) trace, holding every piece of it.
  EXPECT_EQ(traces.size(), truth.size());
  for (const auto& t : traces) {
    std::set<std::string> keys;
    for (const auto& p : t.pieces) keys.insert(p.substr(p.find('/') + 1));
    ASSERT_EQ(keys.size(), 1u) << t.label << " joins pieces of different traces";
    const std::string key = *keys.begin();
    EXPECT_EQ(static_cast<int>(t.pieces.size()), images_per_trace[key]) << key;
    // Its points lie on the true segment to the surface error: ~2 cm from
    // the master's registration (see above), ~1 cm depth noise, the 2 cm
    // wide drawn trace. A few single points are dense-matching blunders (at
    // the folds of the face, at frame edges): 90 % of the points are held to it.
    const auto& seg = truth[key];
    const Eigen::Vector3d d = (seg[1] - seg[0]).normalized();
    std::vector<double> off;
    for (const auto& p : t.points) {
      const Eigen::Vector3d w = p + origin();
      off.push_back((w - seg[0] - d * d.dot(w - seg[0])).norm());
    }
    std::sort(off.begin(), off.end());
    const double p90 = off[off.size() * 9 / 10];
    std::printf("trace %s (%s): %zu pieces, %zu points, 90 %% within %.4f m of the truth\n",
                t.label.c_str(), key.c_str(), t.pieces.size(), t.points.size(), p90);
    EXPECT_LT(p90, 0.03) << key;
  }
}

TEST_F(MultiImage, GroundControlResidualsAgainstKnownPoints) {
  rockface::NoProgress progress;
  const auto imgs = images();
  // Survey coordinates of 10^6 m: the datum keeps millimetres.
  const Eigen::Vector3d datum(512340.0, 5211870.0, 410.0);
  struct Known {
    std::string id;
    int image;
    double x, z;
  };
  // Spread over all three photographs, away from the pole; "CHK" is a check
  // point, not used by the registration.
  const std::vector<Known> known = {{"G1", 1, -3.4, -0.6}, {"G2", 0, -0.8, 1.4},
                                    {"G3", 0, -0.3, -1.0}, {"G4", 2, 3.4, 1.2},
                                    {"G5", 2, 2.8, -1.0},  {"CHK", 1, -2.6, 1.5}};
  std::vector<rp::FaceControlPoint> gcps;
  std::map<std::string, Eigen::Vector3d> truth;
  for (const auto& k : known) {
    const auto& f = k.x < -1.4 ? synthetic_facets()[0]
                               : (k.x < 1.4 ? synthetic_facets()[1] : synthetic_facets()[2]);
    const Eigen::Vector3d w(k.x, facet_y(f, k.x, k.z), k.z);
    truth[k.id] = w + datum;
    const auto& render = (*pairs_)[k.image].render;
    const Eigen::Vector2d px = pixel_of(w, render.poses[0], render.intrinsics);
    if (k.id != "CHK") gcps.push_back({k.id, k.image, px, w + datum});
  }
  const rp::FaceRegistration face =
      rp::register_face_images(imgs, gcps, rp::preset_standard(), {}, progress);
  ASSERT_TRUE(face.control_points);
  ASSERT_EQ(face.control_points->residuals.size(), gcps.size());
  // Each residual is the picked surface point against its surveyed position:
  // depth noise (~7 mm) and the pick (half a lattice cell, ~3 mm) and what is
  // left of the tie-point registration of its image.
  for (const auto& r : face.control_points->residuals) {
    std::printf("%s residual %.4f m\n", r.id.c_str(), r.distance);
    EXPECT_LT(r.distance, 0.03) << r.id;
    EXPECT_NEAR(r.distance, r.residual.norm(), 1e-12);
  }
  EXPECT_LT(face.control_points->rms_m, 0.02);
  // The check point, picked on the western image, lands on its survey.
  const Known& chk = known.back();
  const auto& render = (*pairs_)[chk.image].render;
  const Eigen::Vector3d w = truth["CHK"] - datum;
  const rp::PixelLookup lookup(imgs[chk.image].mesh);
  const int v = lookup.nearest(pixel_of(w, render.poses[0], render.intrinsics));
  ASSERT_GE(v, 0);
  const Eigen::Vector3d placed =
      face.images[chk.image].to_face.apply(imgs[chk.image].mesh.vertices[v]) + face.datum;
  std::printf("check point error %.4f m\n", (placed - truth["CHK"]).norm());
  EXPECT_LT((placed - truth["CHK"]).norm(), 0.04);
}

TEST_F(MultiImage, PairOfAnotherFaceIsRefusedByName) {
  // Another face: one plane of another strike with another rock texture.
  cam::SyntheticScene other = face_from(0.0);
  other.patches.resize(1);
  other.patches[0].polygon = {{-5, 12, -3}, {5, 11, -3}, {5, 11.5, 4}, {-5, 12.5, 4}};
  other.joints.clear();
  other.range_pole.reset();
  other.reference_line.reset();
  other.texture_seed = 97;
  const Pair stranger = photograph_and_reconstruct(other, false);
  auto imgs = images();
  imgs.push_back(face_image(stranger, "pair 4 (face 121)"));
  rockface::NoProgress progress;
  try {
    rp::register_face_images(imgs, {}, rp::preset_standard(), {}, progress);
    FAIL() << "a pair of another face was registered";
  } catch (const rockface::InputError& e) {
    EXPECT_EQ(e.where(), "pair 4 (face 121)");
    EXPECT_NE(std::string(e.what()).find("does not overlap"), std::string::npos) << e.what();
  }
}
