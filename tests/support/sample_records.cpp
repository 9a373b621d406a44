#include "tests/support/sample_records.h"

#include "storage/project/project_schema.h"

#include <unistd.h>

#include <fstream>
#include <random>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace rockface::storage::test {

std::vector<std::uint8_t> encoded_image(int width, int height, int seed, const std::string& ext) {
  // Smooth noise at a few scales plus a little pixel noise: rock-like texture
  // that compresses like a photograph, not like white noise or a flat field.
  cv::RNG rng(static_cast<std::uint64_t>(seed) + 1);
  cv::Mat image(height, width, CV_32FC3, cv::Scalar::all(0));
  for (int scale : {64, 16, 4}) {
    cv::Mat coarse(std::max(2, height / scale), std::max(2, width / scale), CV_32FC3);
    rng.fill(coarse, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(80));
    cv::Mat up;
    cv::resize(coarse, up, image.size(), 0, 0, cv::INTER_CUBIC);
    image += up;
  }
  cv::Mat noise(image.size(), CV_32FC3);
  rng.fill(noise, cv::RNG::NORMAL, cv::Scalar::all(0), cv::Scalar::all(4));
  image += noise;
  cv::Mat bytes8;
  image.convertTo(bytes8, CV_8UC3);
  std::vector<std::uint8_t> out;
  cv::imencode(ext, bytes8, out, {cv::IMWRITE_JPEG_QUALITY, 92});
  return out;
}

ProjectInfo sample_project() {
  ProjectInfo p;
  p.name = "Gotthard access tunnel, chainage 1+120";
  p.datum = {2690123.25, 1170456.5, 1105.125};  // survey coordinates: LV95, metres
  p.datum_crs = "EPSG:2056 LV95 / LN02";
  return p;
}

Calibration sample_calibration() {
  Calibration c;
  auto& k = c.intrinsics;
  k.width = 6000;
  k.height = 4000;
  k.fx = 8930.125;
  k.fy = 8929.75;
  k.cx = 3001.2;
  k.cy = 1998.4;
  k.distortion = {-0.0912, 0.1234, 0.00021, -0.00034, -0.0456};
  k.rms_px = 0.21;
  k.body = "Nikon D7500";
  k.lens = "18-55 @ 24 mm";
  k.focus = "locked";
  c.focal_setting_mm = 24;
  c.method = "chessboard:9x6:0.025";
  return c;
}

Capture sample_capture(RecordId visit_id, int seed, int width, int height) {
  Capture c;
  c.visit_id = visit_id;
  c.label = "face 120 pair " + std::to_string(seed);
  c.taken_at = "2026-11-20T09:1" + std::to_string(seed % 10) + ":00.000Z";
  c.left.bytes = encoded_image(width, height, 2 * seed, ".jpg");
  c.right.bytes = encoded_image(width, height, 2 * seed + 1, seed % 2 ? ".png" : ".jpg");
  c.settings = {{"iso", "200"}, {"shutter", "1/125"}, {"aperture", "f/8"}, {"baseline_m", "1.2"}};
  c.left_exif = {{"Make", "Nikon"}, {"Model", "D7500"}, {"FocalLength", "24/1"}};
  c.right_exif = {
      {"Make", "Nikon"}, {"Model", "D7500"}, {"DateTimeOriginal", "2026:11:20 09:10:02"}};
  return c;
}

Model sample_model(std::optional<RecordId> capture_id) {
  Model m;
  m.capture_id = capture_id;
  m.preset = "standard";
  // A 3 x 3 grid of vertices on a gently curved face, 8 triangles.
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      m.mesh.vertices.emplace_back(0.5 * i + 1e-7 * j, 4.0 + 0.01 * i * j, 0.5 * j + 0.123456789);
      m.mesh.texcoords.push_back({0.5f * static_cast<float>(i), 0.5f * static_cast<float>(j)});
      m.mesh.colours.push_back({static_cast<std::uint8_t>(40 * i),
                                static_cast<std::uint8_t>(50 * j), static_cast<std::uint8_t>(200)});
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 3 * j + i;
      m.mesh.faces.push_back({a, a + 1, a + 4});
      m.mesh.faces.push_back({a, a + 4, a + 3});
    }
  if (capture_id) {
    m.texture_capture_id = capture_id;
    m.texture_side = "left";
  }
  m.registration.kind = "range_pole_compass";
  m.registration.scale = 0.98765;
  m.registration.rotation_wxyz = Eigen::Vector4d(0.9, 0.1, -0.3, 0.2).normalized();
  m.registration.translation = {1.5, -2.25, 0.125};
  m.registration.parameters_json = R"({"pole_length_m":2.0,"azimuth_deg":123.4})";
  m.registration.rms_m = 0.0042;
  m.residuals = {{"pole top", {0.001, -0.002, 0.0005}}, {"pole base", {-0.001, 0.002, -0.0005}}};
  return m;
}

std::vector<Measurement> sample_measurements(std::optional<RecordId> model_id) {
  std::vector<Measurement> out(4);
  out[0].model_id = model_id;
  out[0].kind = Measurement::Kind::trace;
  out[0].label = "T1";
  out[0].joint_label = "J1";
  out[0].points = {{0.1, 4.0, 0.2}, {0.5, 4.01, 0.6}, {0.9, 4.02, 1.05}};
  out[0].dip_deg = 63.5;
  out[0].dipdir_deg = 271.25;
  out[0].fit_rms_m = 0.003;
  out[0].photo = "left";
  out[0].pixels = {{1203.25, 884.5}, {1410.125, 902.0625}, {1650.0, 955.75}};
  out[0].sigma_deg = 0.35;
  out[0].trace_length_m = 1.21;
  out[0].censored = true;
  out[0].note = "2 of 300 points left out of the fit";
  out[1].model_id = model_id;
  out[1].kind = Measurement::Kind::trace;
  out[1].label = "T2";  // collinear: no plane, no joint yet
  out[1].points = {{0.0, 4.0, 0.0}, {1.0, 4.0, 1.0}};
  out[2].model_id = model_id;
  out[2].kind = Measurement::Kind::area;
  out[2].label = "F1";
  out[2].points = {{0, 4, 0}, {1, 4, 0}, {1, 4, 1}, {0, 4, 1}};
  out[2].dip_deg = 90;
  out[2].dipdir_deg = 180;
  out[2].rock_side = "lower";
  out[3].model_id = model_id;
  out[3].kind = Measurement::Kind::point_orientation;
  out[3].label = "P1";
  out[3].points = {{0.7, 4.05, 0.3}};
  out[3].dip_deg = 35;
  out[3].dipdir_deg = 0;
  return out;
}

std::vector<JointSet> sample_joint_sets() {
  std::vector<JointSet> sets(2);
  sets[0].label = "S1";
  sets[0].dip_deg = 63.0;
  sets[0].dipdir_deg = 270.5;
  sets[0].fisher_k = 45.0;
  sets[0].count = 12;
  sets[0].alpha95_deg = 4.25;
  sets[0].spacing_m = 0.8;
  sets[0].mean_trace_length_m = 2.5;
  sets[0].censored_traces = 3;
  sets[0].note = "3 of 12 traces leave the mapped area";
  sets[1].label = "S2";
  sets[1].dip_deg = 20.0;
  sets[1].dipdir_deg = 95.0;
  sets[1].fisher_k = 80.0;
  sets[1].count = 7;
  return sets;
}

std::vector<Joint> sample_joints() {
  std::vector<Joint> out(3);
  out[0].label = "J1";
  out[0].set_label = "S1";
  out[0].dip_deg = 63.5;
  out[0].dipdir_deg = 271.25;
  out[0].point = Eigen::Vector3d(0.5, 4.01, 0.6);
  out[0].friction_deg = 32;
  out[0].cohesion_pa = 15000;
  out[0].source = "trace T1";
  out[0].type = "trace";
  out[0].persistence_m = 2.75;
  out[1].label = "J2";
  out[1].set_label = "S2";
  out[1].dip_deg = 20;
  out[1].dipdir_deg = 359.99;
  out[1].point = Eigen::Vector3d(0.2, 4.0, 0.9);
  out[1].source = "manual";
  out[2].label = "J3";
  out[2].dip_deg = 0;
  out[2].dipdir_deg = 0;
  out[2].source = "manual";  // orientation only, no set
  return out;
}

AnalysisRun sample_analysis(RecordId visit_id, std::optional<RecordId> model_id) {
  AnalysisRun a;
  a.visit_id = visit_id;
  a.model_id = model_id;
  a.preset = "precise";
  a.effects = {"gravity", "water"};
  a.effects_json = R"({"water":{"unit_weight":9810}})";
  rockface::analysis::ReportBlock b1;
  b1.id = "B1";
  b1.source = "traces";
  b1.code = "0102";
  b1.volume = 12.5;
  b1.finite = b1.removable = true;
  b1.mode = rockface::analysis::ReportMode{};
  b1.mode->type = "sliding";
  b1.fos = 1.35;
  rockface::analysis::ReportBlock b2;
  b2.id = "B2";
  b2.source = "scene";
  b2.code = "1100";
  b2.volume = 0.75;
  b2.finite = true;
  b2.marginal = true;
  a.blocks = {b1, b2};
  return a;
}

TempDir::TempDir(const std::string& name) {
  path_ = std::filesystem::temp_directory_path() /
          ("rockface-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

sqlite::Connection project_at_schema(const std::filesystem::path& file, int version) {
  sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
  schema::create_version_1(db);
  schema::migrate_to(db, version);
  db.exec(
      "INSERT INTO project (id, name, datum_x, datum_y, datum_z, created_at, created_by) "
      "VALUES (1, 'site', 0, 0, 0, '2026-01-01T00:00:00.000Z', 'rockface');"
      "INSERT INTO visit (id, started_at, source) VALUES (1, '2026-01-02T08:00:00.000Z', "
      "'tablet');",
      "writing a schema " + std::to_string(version) + " project");
  return db;
}

}  // namespace rockface::storage::test
