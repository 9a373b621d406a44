// A visit placed by the chainage the geologist typed: its 3D image, made in
// the frame of its range pole, is moved so that the pole's lower target
// stands at the typed chainage, offset and height, and the visit is placed
// from the moved surface.
#include "firmware-app/tunnel/typed_placement.h"

#include <unistd.h>
#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "camera/synthetic_tunnel.h"
#include "core/common/error.h"
#include "firmware-app/tunnel/visit_placement.h"
#include "storage/project/project_store.h"

namespace rockface::app {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;

class TypedPlacement : public ::testing::Test {
 protected:
  void SetUp() override { make("range_pole_compass"); }
  // `kind` "ground_control": the 3D image registered to monitoring targets
  // lies in the project frame already (not in the pole's frame).
  void make(const std::string& kind) {
    dir_ = fs::temp_directory_path() / ("rockface-typed-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    storage::ProjectInfo info;
    info.name = "typed";
    info.datum = {1000, 2000, 300};
    store_.emplace(storage::ProjectStore::create(dir_ / "t.rockface", info));
    storage::TunnelRecord tunnel;
    tunnel.name = "drive";
    tunnel.stations = {{0, {1000, 2000, 300}}, {100, {1000, 2100, 300}}};
    tunnel.radii = {0};
    tunnel.profile = tunnel::circle_profile(3.0);
    store_->save_tunnel(tunnel);
    visit_ = store_->begin_visit("tablet");
    // The round as the reconstruction gives it: in the pole's frame (its
    // lower target at the origin), the pole truly at chainage 12, 1 m right
    // and 1.5 m below the axis.
    const tunnel::Alignment alignment = tunnel.alignment(info.datum);
    pole_ = alignment.frame_at(12).to_local(1.0, -1.5);
    camera::RenderedTunnelSpec spec;
    spec.chainage_from = 6;
    spec.face_chainage = 14;
    storage::Model model;
    for (const auto& patch :
         camera::rendered_tunnel_patches(spec, alignment, tunnel.profile, "test")) {
      const int base = static_cast<int>(model.mesh.vertices.size());
      for (const auto& v : patch.polygon)
        model.mesh.vertices.push_back(kind == "ground_control" ? v : Vector3d(v - pole_));
      for (int k = 1; k + 1 < static_cast<int>(patch.polygon.size()); ++k)
        model.mesh.faces.push_back({base, base + k, base + k + 1});
    }
    model.registration.kind = kind;
    if (kind == "ground_control") {
      model.registration.rms_m = 0.006;
      model.residuals = {{"P1", {0.004, 0.002, -0.003}},
                         {"P2", {-0.005, 0.001, 0.004}},
                         {"P3", {0.001, -0.006, 0.002}}};
    }
    model.registration.parameters_json = R"({"targets": [[0, 0, 0], [0, 0, 2]]})";
    model.preset = "fast";
    storage::Capture capture;
    capture.visit_id = visit_;
    std::vector<unsigned char> png;
    cv::imencode(".png", cv::Mat(8, 8, CV_8UC3, cv::Scalar(90, 90, 90)), png);
    capture.left.bytes = capture.right.bytes = png;
    model.capture_id = store_->save_capture(capture);
    store_->save_model(model);
  }
  void TearDown() override {
    store_.reset();
    fs::remove_all(dir_);
  }
  void remake(const std::string& kind) {
    TearDown();
    make(kind);
  }
  fs::path dir_;
  std::optional<storage::ProjectStore> store_;
  storage::RecordId visit_ = 0;
  Vector3d pole_;
};

TEST_F(TypedPlacement, TheImageMovesToTheTypedPoleAndTheVisitIsPlaced) {
  const storage::VisitPlacement p = place_by_typed_chainage(*store_, visit_, {12.0, 1.0, -1.5});
  EXPECT_EQ(p.method, storage::VisitPlacement::Method::chainage_compass);
  EXPECT_NE(p.note.find("chainage 12.00"), std::string::npos) << p.note;
  // A flat face at chainage 14: the rays along the axis meet it there
  // (1e-6: rounding of the move and of the ray casting).
  EXPECT_NEAR(p.chainage, 14.0, 1e-6);
  EXPECT_NEAR(p.offset_m, 0.0, 0.05);
  // The stored placement and the moved model (a new model of the capture;
  // the original stays).
  ASSERT_TRUE(store_->load_visit_placement(visit_));
  const auto models = store_->list_visit_models(visit_);
  ASSERT_EQ(models.size(), 1u);
  const storage::Model moved = store_->load_model(models.front().id);
  EXPECT_TRUE(moved.registration.parameters_json.find("targets") != std::string::npos);
  EXPECT_EQ(store_->list_models().size(), 2u);
}

TEST_F(TypedPlacement, OffTheAlignmentOrAfterMappingIsRefusedByName) {
  try {
    place_by_typed_chainage(*store_, visit_, {250.0, 0, 0});
    FAIL() << "a chainage beyond the alignment was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("off the alignment"), std::string::npos) << e.what();
  }
  storage::Measurement m;
  m.visit_id = visit_;
  m.kind = storage::Measurement::Kind::trace;
  m.label = "T1";
  m.points = {{0, 0, 0}, {1, 0, 0}};
  store_->save_measurements(visit_, {m});
  try {
    place_by_typed_chainage(*store_, visit_, {12.0, 1.0, -1.5});
    FAIL() << "placing moved a 3D image already mapped on";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("measurements"), std::string::npos) << e.what();
  }
}

TEST_F(TypedPlacement, AVisitRegisteredToMonitoringTargetsIsPlacedFromThem) {
  remake("ground_control");
  // Not stored: `rockface reconstruct --gcp` made the 3D image; the profile
  // and the report read the placement from it.
  EXPECT_FALSE(store_->load_visit_placement(visit_));
  const auto tunnel = store_->load_tunnel();
  ASSERT_TRUE(tunnel);
  const auto p = known_placement(*store_, *tunnel, visit_);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->method, storage::VisitPlacement::Method::ground_control);
  EXPECT_EQ(p->residuals.size(), 3u);
  ASSERT_TRUE(p->rms_m);
  EXPECT_DOUBLE_EQ(*p->rms_m, 0.006);
  EXPECT_NEAR(p->chainage, 14.0, 1e-6);  // the flat face at chainage 14
  // The range pole's frame is never asked for: nothing is moved.
  EXPECT_EQ(store_->list_models().size(), 1u);
  EXPECT_FALSE(store_->load_visit_placement(visit_));
}

}  // namespace
}  // namespace rockface::app
