// Every parser a user feeds, fed mutated files (tests/storage/fuzz/mutator.h): scene
// JSON, picks JSON, camera JSON, control-point CSV, the reference line, a PLY
// model, the imported clouds and meshes (LAS, XYZ / PTS, PTX, PCD, OBJ), the
// visit file of a capture folder, the tunnel's alignment table and design
// profile (JSON and CSV), the support classes, the rock-mass form, a
// capture's EXIF and a project file. A parser may accept an input or refuse it with a
// rockface::Error (InputError naming the file and field); it may not crash, hang or let another
// exception out (a raw nlohmann or std:: message is not what the user should read). Failing inputs
// are written to ROCKFACE_BINARY_DIR/fuzz-failures; each one found becomes a file in
// tests/storage/fuzz/corpus/regressions, run on every pass.
//
// The inputs tried per parser are bounded (CI); ROCKFACE_FUZZ_ITERATIONS
// multiplies them and ROCKFACE_FUZZ_SEED changes them (docs/fuzzing.md).
#include <unistd.h>
#include "tests/support/test_paths.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "camera/exif.h"
#include "core/common/error.h"
#include "core/photogrammetry/estimators/registration.h"
#include "core/photogrammetry/targets/reference_line.h"
#include "core/tunnel/support_ranges.h"
#include "firmware-app/wedges/support_options.h"
#include "storage/exchange/las_reader.h"
#include "storage/exchange/obj_reader.h"
#include "storage/exchange/pcd_reader.h"
#include "storage/exchange/ply_reader.h"
#include "storage/exchange/ptx_reader.h"
#include "storage/exchange/xyz_reader.h"
#include "storage/project/project_store.h"
#include "storage/scene/camera_json.h"
#include "storage/scene/picks_json.h"
#include "storage/scene/rockmass_form_json.h"
#include "storage/scene/scene.h"
#include "storage/scene/visit_file_json.h"
#include "storage/support/support_classes_json.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/storage/fuzz/mutator.h"

namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(ROCKFACE_SOURCE_DIR) / "tests/storage/fuzz/corpus";

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
}

std::vector<std::string> files_in(const fs::path& dir, const std::string& prefix = "",
                                  const std::string& suffix = "") {
  std::vector<fs::path> paths;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file() && name.rfind(prefix, 0) == 0 && name.size() >= suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        paths.push_back(e.path());
    }
  std::sort(paths.begin(), paths.end());  // a fixed order: the same inputs every run
  std::vector<std::string> out;
  for (const auto& p : paths) out.push_back(read_bytes(p));
  return out;
}

std::uint64_t fuzz_seed() {
  const char* s = std::getenv("ROCKFACE_FUZZ_SEED");
  return s ? std::strtoull(s, nullptr, 10) : 1;
}

// The CI count of a parser, times ROCKFACE_FUZZ_ITERATIONS (a factor, 1
// when unset) for a longer run by hand.
long iterations(long ci_default) {
  const char* s = std::getenv("ROCKFACE_FUZZ_ITERATIONS");
  return s ? ci_default * std::max(1L, std::atol(s)) : ci_default;
}

// What became of one input: accepted, refused with a rockface::Error, or
// something else escaped (described).
struct Outcome {
  bool accepted = false;
  std::string escaped;
};

Outcome run_one(const std::function<void(const std::string&)>& parse, const std::string& in) {
  try {
    parse(in);
    return {true, ""};
  } catch (const rockface::Error&) {
    return {false, ""};
  } catch (const std::exception& e) {
    return {false, std::string("std::exception: ") + e.what()};
  } catch (...) {
    return {false, "an exception of unknown type"};
  }
}

// The fuzz loop shared by every parser: the seeds must parse, the
// regressions and `count` mutated inputs must not escape.
void fuzz(const std::string& name, const std::vector<std::string>& seeds, bool text, long count,
          const std::function<void(const std::string&)>& parse, std::size_t page_size = 0) {
  ASSERT_FALSE(seeds.empty());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    // A seed that does not parse explores only the error paths.
    try {
      parse(seeds[i]);
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << " seed " << i << " is refused: " << e.what();
    }
  }
  const fs::path failures = fs::path(ROCKFACE_BINARY_DIR) / "fuzz-failures";
  for (const std::string& r : files_in(kCorpus / "regressions", name + "-"))
    EXPECT_EQ(run_one(parse, r).escaped, "") << name << " regression";
  rockface::fuzz::Mutator mutator(seeds, fuzz_seed(), text, page_size);
  const auto start = std::chrono::steady_clock::now();
  int failed = 0, accepted = 0;
  for (long n = 0; n < count; ++n) {
    const std::string input = mutator.next();
    const Outcome outcome = run_one(parse, input);
    accepted += outcome.accepted;
    const std::string& what = outcome.escaped;
    if (what.empty()) continue;
    fs::create_directories(failures);
    const fs::path saved = failures / (name + "-" + std::to_string(n));
    write_bytes(saved, input);
    ADD_FAILURE() << name << " input " << n << " (saved as " << saved << "): " << what;
    if (++failed >= 10) break;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::testing::Test::RecordProperty("inputs", static_cast<int>(count));
  ::testing::Test::RecordProperty("accepted", accepted);
  ::testing::Test::RecordProperty("seconds", std::to_string(seconds));
}

}  // namespace

TEST(Fuzz, SceneJson) {
  std::vector<std::string> seeds = files_in(kCorpus / "scene");
  // The sample scenes (tools/samples also holds sample picks and a README).
  for (const auto& s : files_in(fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples", "", ".scene.json"))
    seeds.push_back(s);
  // Named as if beside the samples: a scene's tunnel names its alignment and
  // profile files relative to the scene file.
  const std::string source =
      (fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples/fuzz.scene.json").string();
  fuzz("scene", seeds, true, iterations(200000),
       [&source](const std::string& in) { rockface::storage::parse_scene(in, source); });
}

TEST(Fuzz, PicksJson) {
  std::vector<std::string> seeds = files_in(kCorpus / "picks");
  for (const auto& s : files_in(fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples", "", ".picks.json"))
    seeds.push_back(s);
  fuzz("picks", seeds, true, iterations(100000),
       [](const std::string& in) { rockface::storage::parse_picks(in, "fuzz.picks.json"); });
}

TEST(Fuzz, CameraJson) {
  fuzz("camera", files_in(kCorpus / "camera"), true, iterations(100000),
       [](const std::string& in) { rockface::storage::parse_camera_json(in, "fuzz.camera.json"); });
}

TEST(Fuzz, ControlPointCsv) {
  fuzz("gcp", files_in(kCorpus / "gcp"), true, iterations(100000), [](const std::string& in) {
    std::istringstream s(in);
    rockface::photogrammetry::parse_control_points(s, "fuzz.csv");
  });
}

TEST(Fuzz, ReferenceLine) {
  fuzz("reference_line", files_in(kCorpus / "reference_line"), true, iterations(100000),
       [](const std::string& in) {
         rockface::photogrammetry::parse_reference_line(in, "--reference-line");
       });
}

// The support typed for the wedges (`rockface wedges --bolts / --shotcrete`,
// the tablet's Wedges form): each text through both parsers, as a geologist
// may type either into either field. A refusal is an InputError; what is
// accepted must lie within the scene's ranges.
TEST(Fuzz, WedgeSupportOptions) {
  fuzz("wedge_support", files_in(kCorpus / "wedge_support"), true, iterations(100000),
       [](const std::string& in) {
         try {
           const auto b = rockface::app::parse_pattern_bolts(in, "--bolts");
           // Accepted: every value within the scene's ranges.
           if (!(b.length >= 0.3 && b.length <= 30 && b.spacing >= 0.3 && b.spacing <= 10))
             throw std::logic_error("bolts accepted out of range: " + in);
         } catch (const rockface::InputError&) {
         }
         try {
           const auto sc = rockface::app::parse_shotcrete(in, "--shotcrete");
           if (!(sc.thickness >= 1e-3 && sc.thickness <= 2 &&
                 rockface::tunnel::kShotcreteShearRange.contains(sc.shear_strength)))
             throw std::logic_error("shotcrete accepted out of range: " + in);
         } catch (const rockface::InputError&) {
         }
       });
}

TEST(Fuzz, PlyModel) {
  // The header is text (counts, types, names), the body ascii or binary:
  // the text mutations (extreme numbers) reach the element counts.
  fuzz("ply", files_in(kCorpus / "ply"), true, iterations(100000),
       [](const std::string& in) { rockface::storage::parse_ply(in, "fuzz.ply"); });
}

// The import readers of `rockface import` (issue 43). LAS is binary (its
// counts and scales in the header: byte mutations reach them); the others
// are text or a text header (number mutations reach their counts).
TEST(Fuzz, LasCloud) {
  fuzz("las", files_in(kCorpus / "las"), false, iterations(100000),
       [](const std::string& in) { rockface::storage::parse_las(in, "fuzz.las"); });
}

TEST(Fuzz, TextCloud) {
  fuzz("xyz", files_in(kCorpus / "xyz"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_xyz(in, "fuzz.xyz", {}, false); });
  fuzz("pts", files_in(kCorpus / "pts"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_xyz(in, "fuzz.pts", {}, true); });
}

TEST(Fuzz, PtxScan) {
  fuzz("ptx", files_in(kCorpus / "ptx"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_ptx(in, "fuzz.ptx"); });
}

TEST(Fuzz, PcdCloud) {
  fuzz("pcd", files_in(kCorpus / "pcd"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_pcd(in, "fuzz.pcd"); });
}

// tinyobjloader parses; the reader checks what it gives (indices, NaN).
TEST(Fuzz, ObjMesh) {
  fuzz("obj", files_in(kCorpus / "obj"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_obj(in, "fuzz.obj", {}); });
}

// The files issue 41 named that had no fuzz target: the visit file beside a
// capture folder's photographs (`rockface replay FOLDER`), the tunnel's
// alignment table and design profile (`rockface tunnel`, a scene's tunnel),
// the designer's support classes (`rockface support --classes`) and the
// rock-mass form (`rockface rockmass --form`). Each reader is fed as the
// verb feeds it: the alignment is built (its elements checked), the profile
// validated.
TEST(Fuzz, VisitFile) {
  fuzz("visit", files_in(kCorpus / "visit"), true, iterations(50000), [](const std::string& in) {
    rockface::storage::parse_visit_file(in, "/card/DCIM/visit.json");
  });
}

TEST(Fuzz, AlignmentCsv) {
  fuzz("alignment", files_in(kCorpus / "alignment"), true, iterations(50000),
       [](const std::string& in) {
         rockface::storage::parse_alignment_csv(in, "fuzz.alignment.csv")
             .build(Eigen::Vector3d(2690000, 1170000, 1100), rockface::tunnel::Drive::ascending);
       });
}

TEST(Fuzz, ProfileFile) {
  fuzz("profile_json", files_in(kCorpus / "profile_json"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_profile_json(in, "fuzz.json"); });
  fuzz("profile_csv", files_in(kCorpus / "profile_csv"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_profile_csv(in, "fuzz.csv"); });
}

TEST(Fuzz, SupportClasses) {
  fuzz("support_classes", files_in(kCorpus / "support_classes"), true, iterations(50000),
       [](const std::string& in) {
         rockface::storage::parse_support_classes(in, "fuzz.classes.json");
       });
}

TEST(Fuzz, RockmassForm) {
  fuzz("rockmass_form", files_in(kCorpus / "rockmass_form"), true, iterations(50000),
       [](const std::string& in) { rockface::storage::parse_rockmass_form(in, "fuzz.form.json"); });
}

namespace {

// A small JPEG of the kind a capture folder holds, with every EXIF field
// rockface reads.
std::string jpeg_with_exif(int seed) {
  cv::Mat image(48, 64, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", image, jpeg);
  rockface::camera::ExifInfo info;
  info.make = "Nikon";
  info.model = "D7500";
  info.lens = "18-55 @ 24 mm";
  info.datetime = "2026:11:20 09:10:0" + std::to_string(seed % 10);
  info.focal_length_mm = 24;
  info.f_number = 8;
  info.exposure_time_s = 1.0 / 125;
  info.iso = 200 * (seed + 1);
  info.flash_fired = seed % 2 == 0;
  info.focus_distance_m = 6.5;
  info.width = 64;
  info.height = 48;
  const auto bytes = rockface::camera::with_exif(jpeg, info);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

TEST(Fuzz, CaptureExif) {
  std::vector<std::string> seeds{jpeg_with_exif(0), jpeg_with_exif(1)};
  fuzz("exif", seeds, false, iterations(100000), [](const std::string& in) {
    rockface::camera::read_exif(std::vector<uint8_t>(in.begin(), in.end()));
  });
}

namespace {

// A small project with a record of each kind (camera body, calibration,
// capture, model, measurements, joint set and joint, analysis), as one file
// (checkpointed).
std::string sample_project_file(const fs::path& dir) {
  namespace st = rockface::storage;
  const fs::path file = dir / "seed.rockface";
  {
    st::ProjectInfo info;
    info.name = "fuzz seed";
    auto store = st::ProjectStore::create(file, info);
    const auto visit = store.begin_visit("tablet", "a note");
    st::CameraBody body;
    body.make = "Nikon";
    body.model = "D7500";
    body.serial = "3012345";
    st::Calibration cal;
    cal.body_id = store.save_camera_body(body);
    cal.intrinsics.width = 64;
    cal.intrinsics.height = 48;
    cal.intrinsics.fx = cal.intrinsics.fy = 80;
    cal.intrinsics.cx = 31.5;
    cal.intrinsics.cy = 23.5;
    cal.intrinsics.distortion = {-0.1, 0.01, 0, 0, 0};
    cal.focal_setting_mm = 24;
    cal.method = "chessboard:9x6:0.025";
    st::Capture c;
    c.calibration_id = store.save_calibration(cal);
    c.visit_id = visit;
    c.label = "pair 1";
    const std::string jpeg = jpeg_with_exif(3);
    c.left.bytes.assign(jpeg.begin(), jpeg.end());
    c.right.bytes.assign(jpeg.begin(), jpeg.end());
    c.right.bytes[c.right.bytes.size() / 2] ^= 1;
    c.settings = {{"iso", "200"}};
    const auto capture = store.save_capture(c);
    st::Model m;
    m.capture_id = capture;
    m.preset = "fast";
    m.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.mesh.faces = {{0, 1, 2}};
    m.mesh.colours = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
    m.id = store.save_model(m);
    st::Measurement trace;
    trace.visit_id = visit;
    trace.model_id = m.id;
    trace.label = "T1";
    trace.joint_label = "J1";
    trace.points = {{0, 0, 0}, {0.5, 0.1, 0.2}, {1, 0.2, 0.5}};
    trace.dip_deg = 60;
    trace.dipdir_deg = 120;
    trace.fit_rms_m = 0.002;
    st::Measurement area = trace;
    area.kind = st::Measurement::Kind::area;
    area.label = "A1";
    area.rock_side = "lower";
    const auto measured = store.save_measurements(visit, {trace, area});
    st::JointSet set;
    set.label = "S1";
    set.dip_deg = 60;
    set.dipdir_deg = 120;
    set.fisher_k = 40;
    set.count = 1;
    set.alpha95_deg = 5;
    set.spacing_m = 0.4;
    set.note = "one trace leaves the mapped area";
    st::Joint joint;
    joint.label = "J1";
    joint.set_label = "S1";
    joint.dip_deg = 60;
    joint.dipdir_deg = 120;
    joint.point = Eigen::Vector3d(0.5, 0.1, 0.2);
    joint.friction_deg = 30;
    joint.measurement_id = measured.front();
    joint.source = "trace T1";
    joint.type = "trace";
    joint.persistence_m = 1.2;
    store.save_joints(visit, {set}, {joint});
    st::AnalysisRun a;
    a.visit_id = visit;
    a.preset = "fast";
    a.effects = {"gravity"};
    rockface::analysis::ReportBlock b;
    b.id = "B1";
    b.source = "scene";
    b.code = "012";
    b.volume = 1.5;
    a.blocks.push_back(b);
    store.save_analysis(a);
    store.checkpoint();
  }
  const std::string bytes = read_bytes(file);
  fs::remove(file);
  return bytes;
}

}  // namespace

TEST(Fuzz, ProjectFile) {
  constexpr std::size_t kSqlitePageSize = 4096;  // SQLite's default, which the store keeps
  const fs::path dir = fs::temp_directory_path() / ("rockface-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<std::string> seeds{sample_project_file(dir)};
  const fs::path file = dir / "fuzzed.rockface";
  // Opening (quick check), then reading every record back: a damaged file is
  // refused or read, never a crash.
  fuzz(
      "project", seeds, false, iterations(10000),
      [&](const std::string& in) {
        for (const char* side : {"", "-wal", "-shm", "-journal"}) fs::remove(file.string() + side);
        write_bytes(file, in);
        rockface::storage::OpenOptions read_only;
        read_only.read_only = true;  // a damaged file must not be written to
        auto store = rockface::storage::ProjectStore::open(file, read_only);
        store.project();
        for (const auto& v : store.list_visits()) store.list_joint_sets(v.id);
        store.list_camera_bodies();
        for (const auto& c : store.list_calibrations()) store.load_calibration(c.id);
        for (const auto& c : store.list_captures()) {
          store.load_capture(c.id);
          store.load_capture_image(c.id, "left");
        }
        store.list_measurements();
        store.list_joints();
        for (const auto& m : store.list_models()) store.load_model(m.id);
        for (const auto& a : store.list_analyses()) store.load_analysis(a.id);
        store.list_actions();
        store.check_integrity(rockface::storage::OpenOptions::Check::full);
      },
      kSqlitePageSize);
  fs::remove_all(dir);
}
