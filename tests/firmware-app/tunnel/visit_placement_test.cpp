#include "firmware-app/tunnel/visit_placement.h"

#include <gtest/gtest.h>

#include "camera/synthetic_tunnel.h"
#include "core/common/error.h"

namespace rockface::app {
namespace {

using Eigen::Vector3d;

// The rendered surface of a round (a circle of 3 m, face at chainage 14
// bulging 0.4 m) as a visit's surface, registered as `kind`.
VisitSurface round_surface(const tunnel::Alignment& alignment, const tunnel::DesignProfile& profile,
                           const std::string& kind) {
  camera::RenderedTunnelSpec spec;
  spec.chainage_from = 6;
  spec.face_chainage = 14;
  spec.face_relief_m = 0.4;
  VisitSurface s;
  for (const auto& patch : camera::rendered_tunnel_patches(spec, alignment, profile, "test")) {
    const int base = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), patch.polygon.begin(), patch.polygon.end());
    for (int k = 1; k + 1 < static_cast<int>(patch.polygon.size()); ++k)
      s.triangles.push_back({base, base + k, base + k + 1});
  }
  s.not_rock.assign(s.vertices.size(), 0);
  s.models = 1;
  s.first.registration.kind = kind;
  return s;
}

tunnel::Alignment straight_north() {
  return tunnel::Alignment::from_elements({{0, {1000, 2000, 300}}, {100, {1000, 2100, 300}}}, {0},
                                          Vector3d(1000, 2000, 300));
}

TEST(VisitPlacement, MonitoringTargetsPlaceTheVisitWithTheirResiduals) {
  const tunnel::Alignment alignment = straight_north();
  const tunnel::DesignProfile circle = tunnel::circle_profile(3.0);
  VisitSurface s = round_surface(alignment, circle, "ground_control");
  s.first.registration.rms_m = 0.004;
  s.first.residuals = {{"P1", {0.003, -0.002, 0.001}}, {"P2", {-0.004, 0.001, 0.002}}};
  const storage::VisitPlacement p = place_visit(alignment, circle, s, 7);
  EXPECT_EQ(p.visit_id, 7);
  EXPECT_EQ(p.method, storage::VisitPlacement::Method::ground_control);
  ASSERT_TRUE(p.rms_m);
  EXPECT_DOUBLE_EQ(*p.rms_m, 0.004);
  EXPECT_EQ(p.residuals.size(), 2u);
  // The face spans chainage 13.6 (its centre) to 14.0 (where it meets the
  // walls); the rays along the axis start within 70 % of the radius, where
  // the quarters lie between 13.6 and about 13.86: their median is there.
  EXPECT_GT(p.chainage, 13.6);
  EXPECT_LT(p.chainage, 13.9);
  EXPECT_NEAR(p.offset_m, 0.0, 0.05);  // a symmetric face about the axis
}

TEST(VisitPlacement, ARangePoleAndCompassSayHowThePoleWasPlaced) {
  const tunnel::Alignment alignment = straight_north();
  const tunnel::DesignProfile circle = tunnel::circle_profile(3.0);
  VisitSurface s = round_surface(alignment, circle, "range_pole_compass");
  s.first.registration.parameters_json = R"({"registration": {"north": {"azimuth_deg": 91.5}}})";
  const storage::VisitPlacement typed =
      place_visit(alignment, circle, s, 3, "chainage 12.00, offset 0.50 m (typed)");
  EXPECT_EQ(typed.method, storage::VisitPlacement::Method::chainage_compass);
  ASSERT_TRUE(typed.compass_azimuth_deg);
  EXPECT_DOUBLE_EQ(*typed.compass_azimuth_deg, 91.5);
  EXPECT_NE(typed.note.find("typed"), std::string::npos);
  const storage::VisitPlacement surveyed = place_visit(alignment, circle, s, 3);
  EXPECT_NE(surveyed.note.find("surveyed"), std::string::npos);
}

TEST(VisitPlacement, TheTypedPoleLiesAtItsChainageOffsetAndHeight) {
  const tunnel::Alignment alignment = straight_north();
  // North-going axis through the datum: right = east (+x), up = +z.
  const Vector3d pole = typed_pole_position(alignment, 12.0, 0.5, -1.2);
  EXPECT_NEAR(pole.x(), 0.5, 1e-9);
  EXPECT_NEAR(pole.y(), 12.0, 1e-9);
  EXPECT_NEAR(pole.z(), -1.2, 1e-9);
  EXPECT_THROW(typed_pole_position(alignment, 150.0, 0, 0), InputError);
}

// Issue 41: an offset of 130 m (or 1e308) from the axis was taken without a
// word; the pole stands in the excavation, at most 50 m from the axis.
TEST(VisitPlacement, ATypedPoleFartherThanAnyTunnelsHalfWidthIsRefusedByName) {
  const tunnel::Alignment alignment = straight_north();
  auto said = [&](double offset, double height) {
    try {
      typed_pole_position(alignment, 12.0, offset, height);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(said(130, 0),
            "tunnel.placement.offset: 130 m from the axis is more than any tunnel's half-width (at "
            "most 50 m): a typo, or the pole outside the excavation?");
  EXPECT_EQ(said(0, -1e308).substr(0, 41), "tunnel.placement.height: -1e+308 m from t");
  EXPECT_EQ(said(-50, 50), "accepted");
}

}  // namespace
}  // namespace rockface::app
