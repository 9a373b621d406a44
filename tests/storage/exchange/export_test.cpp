// Exports read back: joints CSV for stereonet programs, the model as PLY
// (binary and ascii, with colour and texture), and the visit as a scene JSON.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "storage/exchange/export_joints_csv.h"
#include "storage/exchange/export_ply.h"
#include "storage/project/project_store.h"
#include "storage/scene/export_scene_json.h"
#include "storage/scene/scene.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;

struct Project {
  test::TempDir dir{"export"};
  ProjectStore store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  RecordId visit = 0, capture = 0, model = 0;
  Capture capture_record;

  Project() {
    visit = store.begin_visit("tablet");
    capture_record = test::sample_capture(visit, 2);
    capture = store.save_capture(capture_record);
    model = store.save_model(test::sample_model(capture));
    store.save_measurements(visit, test::sample_measurements(model));
    store.save_joints(visit, test::sample_joint_sets(), test::sample_joints());
    store.save_analysis(test::sample_analysis(visit, model));
  }
};

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(Export, JointsCsvHasAbsolutePositionsAndSets) {
  Project p;
  EXPECT_EQ(export_joints_csv(p.store, p.dir / "joints.csv", p.visit), 3u);
  const auto lines = lines_of(p.dir / "joints.csv");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "id,dip,dip_direction,set,x,y,z,visit,source,type,persistence");
  // J1 at (0.5, 4.01, 0.6) relative to the datum (2690123.25, 1170456.5, 1105.125).
  EXPECT_EQ(lines[1], "J1,63.500,271.250,S1,2690123.7500,1170460.5100,1105.7250," +
                          std::to_string(p.visit) + ",trace T1,trace,2.750");
  EXPECT_EQ(lines[2].substr(0, 19), "J2,20.000,359.990,S");
  EXPECT_EQ(lines[3], "J3,0.000,0.000,,,,," + std::to_string(p.visit) + ",manual,,");
  EXPECT_EQ(p.store.list_actions().back().action, "export joints csv");

  // A label with a comma is quoted, so the columns stay where they are.
  std::ostringstream out;
  Joint j;
  j.label = "J1, crown";
  j.source = "said \"maybe\"";
  write_joints_csv(out, {j}, Eigen::Vector3d::Zero());
  EXPECT_NE(out.str().find("\"J1, crown\",0.000"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("\"said \"\"maybe\"\"\""), std::string::npos) << out.str();
}

TEST(Export, JointsCsvRoundTrip) {
  // What a stereonet program reads is what rockface wrote: measured joints
  // with type and persistence, a quoted label, an orientation-only joint.
  const Eigen::Vector3d datum(2690123.25, 1170456.5, 1105.125);
  std::vector<Joint> joints(3);
  joints[0].label = "T1";
  joints[0].dip_deg = 63.5;
  joints[0].dipdir_deg = 271.25;
  joints[0].set_label = "S1";
  joints[0].point = Eigen::Vector3d(0.5, 4.01, 0.6);
  joints[0].type = "trace";
  joints[0].persistence_m = 3.25;
  joints[0].source = "trace T1";
  joints[1].label = "A1, \"crown\"";
  joints[1].dip_deg = 20;
  joints[1].dipdir_deg = 359.99;
  joints[1].type = "area";
  joints[2].label = "J3";
  std::stringstream csv;
  write_joints_csv(csv, joints, datum);
  const auto back = read_joints_csv(csv, datum, "joints.csv");
  ASSERT_EQ(back.size(), joints.size());
  for (std::size_t i = 0; i < joints.size(); ++i) {
    EXPECT_EQ(back[i].label, joints[i].label);
    EXPECT_EQ(back[i].set_label, joints[i].set_label);
    EXPECT_EQ(back[i].type, joints[i].type);
    EXPECT_EQ(back[i].source, joints[i].source);
    // Written to 1e-3 degree and 0.1 mm (write_joints_csv).
    EXPECT_NEAR(back[i].dip_deg, joints[i].dip_deg, 5e-4);
    EXPECT_NEAR(back[i].dipdir_deg, joints[i].dipdir_deg, 5e-4);
    ASSERT_EQ(back[i].point.has_value(), joints[i].point.has_value());
    if (joints[i].point) {
      EXPECT_LT((*back[i].point - *joints[i].point).norm(), 1e-4);
    }
    ASSERT_EQ(back[i].persistence_m.has_value(), joints[i].persistence_m.has_value());
    if (joints[i].persistence_m) {
      EXPECT_NEAR(*back[i].persistence_m, *joints[i].persistence_m, 5e-4);
    }
  }
  std::stringstream bad("id,dip,dip_direction\nJ1,sixty,10\n");
  try {
    read_joints_csv(bad, datum, "joints.csv");
    FAIL() << "accepted";
  } catch (const rockface::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("joints.csv: line 2, dip"), std::string::npos) << e.what();
  }
}

TEST(Export, BinaryPlyReadsBackExactlyWithTexture) {
  Project p;
  export_model_ply(p.store, p.model, p.dir / "model.ply");
  const auto bytes = test::read_file_bytes(p.dir / "model.ply");
  const std::string text(bytes.begin(), bytes.end());
  const auto header_end = text.find("end_header\n");
  ASSERT_NE(header_end, std::string::npos);
  const std::string header = text.substr(0, header_end);
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex 9\nproperty double x"), std::string::npos);
  EXPECT_NE(header.find("property uchar red"), std::string::npos);
  EXPECT_NE(header.find("property float texture_u"), std::string::npos);
  EXPECT_NE(header.find("element face 8"), std::string::npos);
  EXPECT_NE(header.find("comment TextureFile model-texture.jpg"), std::string::npos);
  // The texture beside it is the capture's left image, byte for byte.
  EXPECT_EQ(test::read_file_bytes(p.dir / "model-texture.jpg"), p.capture_record.left.bytes);

  const Model model = p.store.load_model(p.model);
  const Eigen::Vector3d datum = p.store.project().datum;
  const std::size_t vertex_size = 3 * 8 + 3 + 2 * 4, face_size = 1 + 3 * 4;
  const char* data = text.data() + header_end + std::strlen("end_header\n");
  ASSERT_EQ(text.size() - (header_end + 11), 9 * vertex_size + 8 * face_size);
  for (std::size_t i = 0; i < 9; ++i) {
    double xyz[3];
    std::memcpy(xyz, data + i * vertex_size, sizeof(xyz));
    const Eigen::Vector3d want = datum + model.mesh.vertices[i];
    // Written as double from the same sum: exact.
    EXPECT_EQ(xyz[0], want.x());
    EXPECT_EQ(xyz[1], want.y());
    EXPECT_EQ(xyz[2], want.z());
    EXPECT_EQ(static_cast<std::uint8_t>(data[i * vertex_size + 24]), model.mesh.colours[i][0]);
    float uv[2];
    std::memcpy(uv, data + i * vertex_size + 27, sizeof(uv));
    EXPECT_EQ(uv[0], model.mesh.texcoords[i][0]);
    EXPECT_EQ(uv[1], 1.0f - model.mesh.texcoords[i][1]) << "PLY v points up";
  }
  const char* faces = data + 9 * vertex_size;
  for (std::size_t f = 0; f < 8; ++f) {
    EXPECT_EQ(faces[f * face_size], 3);
    std::int32_t v[3];
    std::memcpy(v, faces + f * face_size + 1, sizeof(v));
    EXPECT_EQ(v[0], model.mesh.faces[f][0]);
    EXPECT_EQ(v[2], model.mesh.faces[f][2]);
  }
}

TEST(Export, AsciiPlyRelativeToDatum) {
  Project p;
  PlyOptions ascii_relative;
  ascii_relative.binary = false;
  ascii_relative.absolute = false;
  export_model_ply(p.store, p.model, p.dir / "model.ply", ascii_relative);
  const auto lines = lines_of(p.dir / "model.ply");
  const auto end = std::find(lines.begin(), lines.end(), "end_header");
  ASSERT_NE(end, lines.end());
  EXPECT_NE(std::find(lines.begin(), end, "property float x"), end);
  ASSERT_EQ(lines.end() - end - 1, 9 + 8);
  // Vertex 0 is (0, 4, 0.123456789): printed to 0.1 mm.
  EXPECT_EQ(*(end + 1), "0.0000 4.0000 0.1235 0 0 200 0.000000 1.000000");
  EXPECT_EQ(*(end + 10), "3 0 1 4");
}

TEST(Export, SceneJsonHoldsTheVisitsGeometry) {
  Project p;
  export_scene_json(p.store, p.dir / "site.scene.json");
  std::ifstream in(p.dir / "site.scene.json");
  const auto scene = nlohmann::json::parse(in);
  const Eigen::Vector3d datum = p.store.project().datum;
  EXPECT_EQ(scene["format"], "rockface-scene/1");
  EXPECT_EQ(scene["name"], test::sample_project().name);
  EXPECT_EQ(scene["datum"][0].get<double>(), datum.x());
  ASSERT_EQ(scene["joints"].size(), 3u);
  const auto& j1 = scene["joints"][0];
  EXPECT_EQ(j1["id"], "J1");
  EXPECT_EQ(j1["dip"].get<double>(), 63.5);
  EXPECT_EQ(j1["dipdir"].get<double>(), 271.25);
  // Absolute point = datum + stored relative point, same double sum: exact.
  EXPECT_EQ(j1["point"][1].get<double>(), datum.y() + 4.01);
  EXPECT_EQ(j1["friction"].get<double>(), 32);
  EXPECT_EQ(j1["cohesion"].get<double>(), 15000);
  EXPECT_FALSE(scene["joints"][2].contains("point")) << "orientation-only joint";

  ASSERT_EQ(scene["free_faces"].size(), 1u);
  const auto& f1 = scene["free_faces"][0];
  EXPECT_EQ(f1["id"], "F1");
  EXPECT_EQ(f1["dip"].get<double>(), 90);
  EXPECT_EQ(f1["dipdir"].get<double>(), 180);
  EXPECT_EQ(f1["rock_side"], "lower");
  EXPECT_EQ(f1["point"][0].get<double>(), datum.x() + 0.5);
  ASSERT_EQ(scene["surface"]["patches"].size(), 1u);
  EXPECT_EQ(scene["surface"]["patches"][0]["polygon"].size(), 4u);

  ASSERT_EQ(scene["traces"].size(), 2u);
  EXPECT_EQ(scene["traces"][0]["id"], "T1");
  EXPECT_EQ(scene["traces"][0]["joint"], "J1");
  EXPECT_EQ(scene["traces"][0]["points"].size(), 3u);
  EXPECT_FALSE(scene["traces"][1].contains("joint")) << "unassigned trace: joint to be fitted";

  EXPECT_EQ(scene["analysis"]["preset"], "precise");
  EXPECT_EQ(scene["effects"]["water"]["unit_weight"], 9810);
  EXPECT_EQ(p.store.list_actions().back().action, "export scene json");
}

// A joint's trace marked partly on a visit's pair 1 and partly on its pair 2
// (the Mapping screen stores each piece with its pair's model): the scene
// the tablet's analysis runs on (load_scene_source, make_scene_json, as
// StoreAnalysisRunner) has one trace spanning both pieces, naming them. A
// trace of the same joint 20 cm away, and two pieces on one pair, stay
// traces of their own.
TEST(Export, PiecesOfOneJointStoredFromTwoPairsAreOneTraceInTheScene) {
  test::TempDir dir("export-pieces");
  ProjectStore store = ProjectStore::create(dir / "site.rockface", test::sample_project());
  const RecordId visit = store.begin_visit("tablet");
  const RecordId m1 =
      store.save_model(test::sample_model(store.save_capture(test::sample_capture(visit, 1))));
  const RecordId m2 =
      store.save_model(test::sample_model(store.save_capture(test::sample_capture(visit, 2))));
  // On the face (y = 4 m), running down to the east; pair 2's piece differs
  // from pair 1's by a 1 cm registration residual where they overlap.
  const Eigen::Vector3d run = Eigen::Vector3d(1, 0, -0.3).normalized();
  const Eigen::Vector3d across = Eigen::Vector3d(0.3, 0, 1).normalized();
  const Eigen::Vector3d start(0, 4, 2);
  auto trace = [&](const std::string& label, RecordId model, double from, double to,
                   double offset) {
    Measurement m;
    m.kind = Measurement::Kind::trace;
    m.model_id = model;
    m.label = label;
    m.joint_label = "J1";
    for (double s = from; s <= to + 1e-9; s += 0.1)
      m.points.push_back(start + s * run + offset * across);
    return m;
  };
  store.save_measurements(visit, {trace("T1", m1, 0.0, 1.2, 0), trace("T2", m2, 0.9, 2.0, 0.01),
                                  trace("T3", m1, 0.0, 1.2, 0.2), trace("T4", m1, 1.3, 2.0, 0.2)});
  auto joints = test::sample_joints();
  store.save_joints(visit, test::sample_joint_sets(), joints);

  const nlohmann::json json = make_scene_json(load_scene_source(store, visit));
  const Scene scene = parse_scene(json.dump(), "scene of visit");
  ASSERT_EQ(scene.traces.size(), 3u);
  EXPECT_EQ(scene.traces[0].id, "T1");
  EXPECT_EQ(json["traces"][0]["pieces"], nlohmann::json::array({"T1", "T2"}));
  EXPECT_EQ(scene.traces[0].joint, std::optional<std::string>("J1"));
  // T3 and T4, 20 cm off and on one pair (T4 continues T3): apart.
  EXPECT_EQ(scene.traces[1].id, "T3");
  EXPECT_EQ(scene.traces[2].id, "T4");
  EXPECT_FALSE(json["traces"][1].contains("pieces"));
  // The joined trace spans both pieces, 0 to 2.0 m along the run, points
  // ordered along it. 1e-9 m: the datum (10^6 m) added and taken back
  // rounds at 1e-10 m; the 1 cm offset is across the run.
  const auto& pts = scene.traces[0].points;
  ASSERT_EQ(pts.size(), 13u + 12u);
  const Eigen::Vector3d origin = scene.datum + start;
  double first = (pts.front() - origin).dot(run), last = (pts.back() - origin).dot(run);
  if (first > last) std::swap(first, last);
  EXPECT_NEAR(first, 0.0, 1e-9);
  EXPECT_NEAR(last, 2.0, 1e-9);
}

TEST(Export, ReadOnlyProjectExportsWithoutLogging) {
  fs::path file;
  Project p;
  file = p.store.file();
  OpenOptions reading;
  reading.read_only = true;
  auto reader = ProjectStore::open(file, reading);
  const auto actions = reader.list_actions().size();
  EXPECT_EQ(export_joints_csv(reader, p.dir / "ro.csv"), 3u);
  export_scene_json(reader, p.dir / "ro.scene.json");
  EXPECT_EQ(reader.list_actions().size(), actions);
  EXPECT_TRUE(fs::exists(p.dir / "ro.scene.json"));
}

}  // namespace
}  // namespace rockface::storage
