// The Model screen's accuracy in words, from the registration the
// reconstruction stores (here the demo's, as `rockface replay` stored it):
// no report key, no JSON, no 15-digit number, and a residual that two
// range-pole targets cannot give says so.
#include <gtest/gtest.h>

#include "ui/app/text_check.h"
#include "ui/model/accuracy_summary.h"

namespace {

using namespace rockface::ui;

// The demo's stored registration (fast preset), as the replay wrote it.
constexpr const char* kDemoRegistration = R"({"base": 1.8001098341618573,
  "base_to_distance": 0.18263278019891738,
  "dense": {"image_scale": 0.6666666666666666, "left_right_rejected_fraction": 0.031210879662821964,
            "min_disparity": -44, "num_disparities": 48, "valid_fraction": 0.9006191904047977},
  "disparity_sigma_px": 0.4, "distance": 9.856444348058652, "focal_px": 1527.0096365094967,
  "format": "rockface-reconstruction/1",
  "images": {"left": "/tmp/x/SYN_0001.JPG", "right": "/tmp/x/SYN_0002.JPG"},
  "orientation": {"R": [[0.9832707117960201, 0.012930310313364363, 0.1816907108229479],
                        [-0.012945615657221497, 0.9999155950504125, -0.0011017305637347496],
                        [-0.18168962094573085, -0.0012687987151903599, 0.9833551097088055]],
                  "inliers": 2380, "matches": 2620, "rms_reprojection_px": 0.030973252195296275,
                  "tie_point_coverage": 0.8374101439210121},
  "point_spacing": 0.013024008320080955, "points": 150327,
  "predicted_depth_sigma_mm": 14.137081356407048, "preset": "fast",
  "registration": {"datum": [0.0, 0.0, 0.0],
    "north": {"azimuth_deg": 88.93012567095953, "declination_deg": 0.0},
    "north_source": "compass",
    "range_pole": {"length_m": 2.0, "targets": [{"which": "lower"}, {"which": "upper"}]},
    "scale": 1.8001098341618573, "scale_checks": [], "scale_source": "range pole",
    "scaled": true, "vertical_source": "range pole"},
  "sigma_z": 0.014137081356407047, "triangles": 297783, "units": "m", "warnings": []})";

std::string all_text(const std::vector<AccuracyLine>& lines) {
  std::string out;
  for (const auto& l : lines) out += l.title + ": " + l.value + "\n";
  return out;
}

TEST(AccuracySummary, TheDemoRegistrationReadsInWordsWithUnits) {
  rockface::storage::Model model;
  model.registration.kind = "range_pole_compass";
  model.registration.parameters_json = kDemoRegistration;
  const auto lines = accuracy_lines(model);
  const std::string text = all_text(lines);
  EXPECT_NE(text.find("Scale: range pole, 2.00 m between its targets"), std::string::npos) << text;
  EXPECT_NE(text.find("North: compass line on the face, line at 088.9°"), std::string::npos)
      << text;
  EXPECT_NE(text.find("Point precision: ± 14 mm in depth"), std::string::npos) << text;
  EXPECT_NE(text.find("Distance to the face: 9.86 m, base 1.80 m (1 : 5.5)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("2,380 of 2,620 matches kept"), std::string::npos) << text;
  // Two targets give the scale and nothing over to check it: no "RMS 0.0 mm".
  EXPECT_NE(text.find("Residual: needs three or more targets"), std::string::npos) << text;
  EXPECT_EQ(text.find("0.0 mm"), std::string::npos) << text;
  for (const auto& l : lines) {
    const std::string line = l.title + ": " + l.value;
    EXPECT_FALSE(looks_like_key(line)) << line;
    EXPECT_FALSE(looks_like_json(line)) << line;
    EXPECT_FALSE(overlong_number(line)) << line;
    EXPECT_EQ(line.find("/tmp/"), std::string::npos) << line;
  }
}

TEST(AccuracySummary, ThreeControlPointsGiveAResidualWithItsWorst) {
  rockface::storage::Model model;
  model.registration.kind = "control points";
  model.registration.rms_m = 0.0042;
  model.registration.parameters_json = R"({"format": "rockface-reconstruction/1",
      "registration": {"scale_source": "control points", "vertical_source": "control points",
        "north_source": "control points",
        "control_points": {"rms_m": 0.0042, "worst": "P3", "worst_m": 0.0061}}})";
  model.residuals = {{"P1", {0.001, 0, 0}}, {"P2", {0, 0.003, 0}}, {"P3", {0, 0, 0.0061}}};
  const std::string text = all_text(accuracy_lines(model));
  EXPECT_NE(text.find("Residual: 4.2 mm rms over 3 control points, worst P3 6.1 mm"),
            std::string::npos)
      << text;
}

TEST(AccuracySummary, AFurtherPairSaysHowItWasPlacedOntoPairOne) {
  rockface::storage::Model model;
  model.registration.kind = "face_images";
  model.registration.rms_m = 0.0093;
  model.registration.parameters_json = R"({"format": "rockface-face-registration/1",
      "images": [{"name": "pair 1", "role": "master", "scale": 1.0},
                 {"name": "pair 2", "role": "registered", "reference": "pair 1",
                  "tie_points": 512, "tie_point_rms_m": 0.0081, "overlap": 0.64,
                  "surface_rms_m": 0.0093, "scale": 1.0000123456789}],
      "predicted_depth_sigma_mm": 15.2})";
  const std::string text = all_text(accuracy_lines(model));
  EXPECT_NE(text.find("Tie points (pair 2): 512 tie points, 8.1 mm rms, 64 % overlap"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Surface fit: 9.3 mm rms"), std::string::npos) << text;
}

}  // namespace
