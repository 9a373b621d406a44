// `rockface reconstruct` as the user runs it: images and a camera file on
// disk (rendered by the synthetic mock camera), the executable, its exit
// code, its files and its one-line errors.
#include <sys/wait.h>
#include <unistd.h>
#include "tests/support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "camera/synthetic_renderer.h"
#include "core/photogrammetry/camera/camera_cv.h"
#include "storage/scene/camera_json.h"
#include "tests/support/synthetic_face.h"

namespace fs = std::filesystem;
namespace rp = rockface::photogrammetry;

namespace {

struct VerbRun {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// One rendered pair for all tests of this file (rendering takes seconds).
class ReconstructVerb : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("rockface-cli-reconstruct-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    scene_ = rockface::testing::synthetic_face(1200, 800, false, 1.0);
    rockface::NoProgress progress;
    render_ = rockface::camera::render_scene(scene_, progress);
    cv::imwrite((dir_ / "left.png").string(), render_.images[0]);
    cv::imwrite((dir_ / "right.png").string(), render_.images[1]);
    rockface::storage::save_camera_json((dir_ / "camera.json").string(), render_.intrinsics);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static VerbRun rockface(const std::string& args) {
    VerbRun r;
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string(ROCKFACE_BINARY_DIR) + "/rockface reconstruct " + args +
                            " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }
  static std::string path(const std::string& name) { return (dir_ / name).string(); }
  static std::string pair() {
    return path("left.png") + " " + path("right.png") + " --camera " + path("camera.json");
  }
  static Eigen::Vector2d left_pixel(const Eigen::Vector3d& world) {
    return rp::project({render_.poses[0].to_camera(world)}, render_.intrinsics)[0];
  }

  static fs::path dir_;
  static rockface::camera::SyntheticScene scene_;
  static rockface::camera::SyntheticRender render_;
};

fs::path ReconstructVerb::dir_;
rockface::camera::SyntheticScene ReconstructVerb::scene_;
rockface::camera::SyntheticRender ReconstructVerb::render_;

}  // namespace

TEST_F(ReconstructVerb, RangePoleAndCompassGiveAScaledNorthOrientedModel) {
  const auto [from, to] = *scene_.reference_line;
  const Eigen::Vector2d a = left_pixel(from), b = left_pixel(to);
  const double bearing = rockface::rad_to_deg(std::atan2(to.x() - from.x(), to.y() - from.y()));
  std::ostringstream args;
  args << pair() << " --preset fast --range-pole 2.0 --azimuth " << bearing - 3.0
       << " --declination 3.0 --reference-line " << a.x() << "," << a.y() << "," << b.x() << ","
       << b.y() << " --out " << path("model.ply") << " --report " << path("report.json");
  const VerbRun r = rockface(args.str());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("scale: range pole, vertical: range pole, north: compass"),
            std::string::npos)
      << r.out;

  const std::string ply = slurp(path("model.ply"));
  ASSERT_EQ(ply.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  const auto at = ply.find("element vertex ");
  ASSERT_NE(at, std::string::npos);
  const long vertices = std::stol(ply.substr(at + 15));
  // The fast preset matches at 1000 px width with a lattice step of 2: the
  // three facets fill ~half of the frame, so >= 50k points.
  EXPECT_GT(vertices, 50000);
  EXPECT_NE(ply.find("property float texture_u"), std::string::npos);

  const auto report = nlohmann::json::parse(slurp(path("report.json")));
  EXPECT_EQ(report["format"], "rockface-reconstruction/1");
  EXPECT_EQ(report["units"], "m");
  EXPECT_EQ(report["registration"]["scale_source"], "range pole");
  EXPECT_EQ(report["points"].get<long>(), vertices);
  // Distance of the face ~10 m, base 1.6 m: the report's figures are the
  // scene's to the precision of the reconstruction (a few percent at most).
  EXPECT_NEAR(report["distance"].get<double>(), 10.0, 0.5);
  EXPECT_NEAR(report["base"].get<double>(), 1.6, 0.02);
  EXPECT_GT(report["sigma_z"].get<double>(), 0.0);
  EXPECT_LT(report["sigma_z"].get<double>(), 0.05);
  const auto& targets = report["registration"]["range_pole"]["targets"];
  ASSERT_EQ(targets.size(), 2u);
  // Target centres against the renderer's projected true centres: well
  // under a tenth of a pixel (sub-pixel ellipse fit with bias correction).
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(targets[k]["left_px"][0].get<double>(), render_.targets[k].image[0].x(), 0.1);
    EXPECT_NEAR(targets[k]["left_px"][1].get<double>(), render_.targets[k].image[0].y(), 0.1);
  }
}

TEST_F(ReconstructVerb, ControlPointsGiveResidualsAndTheWorstPoint) {
  // Four points on the facets, surveyed in UTM-like coordinates.
  const Eigen::Vector3d utm(512340.0, 5211870.0, 410.0);
  const auto& facets = rockface::testing::synthetic_facets();
  std::ofstream csv(path("gcp.csv"));
  csv << "id,u,v,E,N,H\n";
  const std::pair<int, Eigen::Vector2d> spots[] = {
      {0, {-3.0, 2.5}}, {1, {0.0, -1.6}}, {2, {3.0, 2.0}}, {1, {-0.5, 2.8}}};
  int n = 0;
  for (const auto& [k, xz] : spots) {
    const Eigen::Vector3d w(xz.x(), rockface::testing::facet_y(facets[k], xz.x(), xz.y()), xz.y());
    const Eigen::Vector2d px = left_pixel(w);
    csv.precision(12);
    csv << "GCP" << ++n << "," << px.x() << "," << px.y() << "," << (w + utm).x() << ","
        << (w + utm).y() << "," << (w + utm).z() << "\n";
  }
  csv.close();
  const VerbRun r = rockface(pair() + " --preset fast --gcp " + path("gcp.csv") + " --out " +
                             path("gcp.obj") + " --report " + path("gcp.json"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(path("gcp.json")));
  const auto& cp = report["registration"]["control_points"];
  ASSERT_EQ(cp["residuals"].size(), 4u);
  // Each control point is picked at the nearest lattice vertex (fast preset:
  // ~2.4 px of the full image = ~2 cm at 10 m) and carries sigma_Z ~ 3 cm:
  // residuals of a few centimetres.
  EXPECT_LT(cp["rms_m"].get<double>(), 0.06);
  EXPECT_FALSE(cp["worst"].get<std::string>().empty());
  EXPECT_NEAR(report["registration"]["datum"][0].get<double>(), utm.x(), 5.0);
  EXPECT_TRUE(fs::exists(path("gcp.mtl")));
  const std::string obj = slurp(path("gcp.obj"));
  // Absolute coordinates survive in the file: the first vertex is near the survey origin.
  const auto v = obj.find("\nv ");
  ASSERT_NE(v, std::string::npos);
  EXPECT_NEAR(std::stod(obj.substr(v + 3)), utm.x(), 10.0);
}

TEST_F(ReconstructVerb, BadInputExitsWithTwoAndNamesTheCulprit) {
  VerbRun r = rockface(path("nope.png") + " " + path("right.png") + " --camera " +
                       path("camera.json") + " --out " + path("m.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nope.png: no such file"), std::string::npos) << r.err;

  r = rockface(pair() + " --preset best --out " + path("m.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--preset"), std::string::npos) << r.err;

  r = rockface(pair() + " --azimuth 40 --out " + path("m.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--reference-line"), std::string::npos) << r.err;

  r = rockface(pair() + " --azimuth 40 --reference-line 1,2,x,4 --out " + path("m.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'x' is not a number"), std::string::npos) << r.err;

  r = rockface(pair() + " --out " + path("m.xyz"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(".ply or .obj"), std::string::npos) << r.err;

  {
    std::ofstream two(path("two.csv"));
    two << "A,1,2,3,4,5\nB,6,7,8,9,10\n";
  }
  r = rockface(pair() + " --gcp " + path("two.csv") + " --out " + path("m.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("three or more"), std::string::npos) << r.err;

  // A model already there is never replaced by a failed run.
  {
    std::ofstream keep(path("keep.ply"));
    keep << "precious";
  }
  r = rockface(pair() + " --preset nonsense --out " + path("keep.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(slurp(path("keep.ply")), "precious");
  EXPECT_FALSE(fs::exists(path("m.ply")));
}

TEST_F(ReconstructVerb, MissingTargetsAreNamed) {
  // A pair rendered without the pole, reconstructed with --range-pole.
  auto scene = scene_;
  scene.range_pole.reset();
  rockface::NoProgress progress;
  const auto render = rockface::camera::render_scene(scene, progress);
  cv::imwrite(path("left-nopole.png"), render.images[0]);
  cv::imwrite(path("right-nopole.png"), render.images[1]);
  const VerbRun r =
      rockface(path("left-nopole.png") + " " + path("right-nopole.png") + " --camera " +
               path("camera.json") + " --preset fast --range-pole 2 --out " + path("nopole.ply"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("range pole: no target found in the left image"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1200x800"), std::string::npos) << r.err;
}

TEST_F(ReconstructVerb, HelpDescribesTheOptions) {
  const VerbRun r = rockface("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* option :
       {"--camera", "--right-camera", "--preset", "--range-pole", "--azimuth", "--reference-line",
        "--declination", "--gcp", "--baseline", "--out", "--report"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}
