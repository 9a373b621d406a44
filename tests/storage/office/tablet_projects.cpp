#include "tests/storage/office/tablet_projects.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/common/degrees_per_radian.h"
#include "core/geometry/orientation.h"
#include "core/measure/joint_sets.h"
#include "storage/office/pg_connection.h"
#include "storage/office/record_documents.h"
#include "storage/office/sqlite_rows.h"
#include "storage/project/project_store.h"
#include "storage/tunnel/tunnel_files.h"
#include "tests/support/dense_face.h"
#include "tests/support/sample_records.h"
#include "tests/support/test_paths.h"

namespace rockface::office_test {

namespace fs = std::filesystem;
using namespace storage;

namespace {

// The sample analysis (a removable block that fails, with its motion
// after failure, and a keyed block) with a shape for each
// block on the sample model's face (x 0-1 m, y about 4 m, z 0.1-1.1 m: a
// tetrahedron standing out of it) and a third, infinite block (its loop on
// the face), so that the 3D face draws every verdict. Report points are
// absolute: the datum added.
AnalysisRun analysis_with_shapes(ProjectStore& store, RecordId visit, RecordId model) {
  AnalysisRun a = storage::test::sample_analysis(visit, model);
  const Eigen::Vector3d datum = store.project().datum;
  auto tetrahedron = [&](analysis::ReportBlock& b, double x) {
    b.vertices = {datum + Eigen::Vector3d(x, 4.0, 0.3), datum + Eigen::Vector3d(x + 0.25, 4.0, 0.3),
                  datum + Eigen::Vector3d(x + 0.1, 4.0, 0.6),
                  datum + Eigen::Vector3d(x + 0.1, 3.8, 0.4)};
    b.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  };
  tetrahedron(a.blocks.at(0), 0.15);
  tetrahedron(a.blocks.at(1), 0.6);
  // B1 fails (FoS below 1) and the analysis followed its motion after
  // failure: it slides out of the face and lands a metre below.
  analysis::ReportBlock& b1 = a.blocks.at(0);
  b1.fos = 0.85;
  analysis::ReportDynamics motion;
  motion.trigger = "limit equilibrium: FoS 0.85 < 1";
  motion.outcome = "lands";
  motion.duration_s = motion.end_time_s = 0.6;
  motion.sample_s = 0.3;
  const Eigen::Vector3d start = datum + Eigen::Vector3d(0.25, 3.95, 0.4);
  for (int i = 0; i <= 2; ++i) {
    analysis::ReportMotionSample at;
    at.time_s = 0.3 * i;
    at.position = start + Eigen::Vector3d(0, -0.2 * i, -0.5 * i);
    motion.path.push_back(at);
  }
  motion.events = {{0, "slides", "slides on J1", {"J1"}}, {0.6, "lands", "lands", {}}};
  b1.dynamics = motion;
  analysis::ReportBlock infinite;
  infinite.id = "B3";
  infinite.source = "traces";
  infinite.code = "0011";
  infinite.finite = infinite.removable = false;
  infinite.vertices = {datum + Eigen::Vector3d(0.2, 4.0, 0.8),
                       datum + Eigen::Vector3d(0.5, 4.0, 0.8),
                       datum + Eigen::Vector3d(0.35, 4.0, 1.0)};
  a.blocks.push_back(infinite);
  return a;
}

// Visit `v` of the project's tablet (options `o`): its place, photographs,
// model, planes and analysis.
void add_visit(ProjectStore& store, const TabletProject& o, RecordId calibration, int v) {
  // Scatter of a geologist's planes about a set's mean (degrees).
  const std::array<double, 6> ddip{-2, -1, 0, 1, 2, 0}, ddir{1, -2, 2, -1, 0, -1};
  const double chainage = o.first_chainage + 2.5 * v;
  const RecordId visit = store.begin_visit(o.name + " at " + std::to_string(chainage));
  Capture capture =
      storage::test::sample_capture(visit, 100 * o.seed + v, o.image_width, o.image_height);
  capture.calibration_id = calibration;
  const RecordId capture_id = store.save_capture(capture);
  const RecordId model = store.save_model(storage::test::sample_model(capture_id));
  std::vector<Measurement> planes;
  // Six planes about (dip, dipdir), turned by `shift_deg` in dip direction.
  auto add = [&](double dip, double dipdir, double shift_deg) {
    for (std::size_t i = 0; i < ddip.size(); ++i) {
      Measurement m;
      m.visit_id = visit;
      m.model_id = model;
      m.kind = Measurement::Kind::trace;
      m.label = "T" + std::to_string(planes.size() + 1);
      // The first visit's joints (below) with traces assigned to them as
      // the geologist assigns them on the tablet: T1-T5 to J1 (set S1),
      // T7-T11 to J2 (set S2), T6 to J3 (a joint of no set), T12 to none.
      // The designed sets' traces (13 on) are assigned to no joint.
      if (v == 0) {
        const std::size_t n = planes.size() + 1;
        m.joint_label = n < 6 ? "J1" : n == 6 ? "J3" : n < 12 ? "J2" : "";
      }
      m.points = {{0.1 * i, chainage - 70, 0.3}, {1.0 + 0.1 * i, chainage - 70, 1.1}};
      m.dip_deg = dip + ddip[i] + 0.1 * o.seed;
      m.dipdir_deg = std::fmod(dipdir + ddir[(i + o.seed) % ddir.size()] + shift_deg + 360, 360);
      planes.push_back(m);
    }
  };
  add(60, 200, 5.0 * v);
  add(75, 110, 5.0 * v);
  std::vector<JointSet> sets = storage::test::sample_joint_sets();
  for (const DesignedSet& d : o.designed_sets) {
    if (static_cast<std::size_t>(v) >= d.per_visit.size() || !d.per_visit[v]) continue;
    const std::size_t first = planes.size();
    add((*d.per_visit[v])[0], (*d.per_visit[v])[1], 0);
    std::vector<Eigen::Vector3d> poles;
    for (std::size_t i = first; i < planes.size(); ++i)
      poles.push_back(geometry::plane_normal_deg(*planes[i].dip_deg, *planes[i].dipdir_deg));
    // Stored as the tablet computes a set: the Fisher statistics of its poles.
    const measure::FisherStatistics f = measure::fisher_statistics(poles);
    JointSet js;
    js.label = d.label;
    js.dip_deg = f.plane().dip * kDegPerRad;
    js.dipdir_deg = f.plane().dipdir * kDegPerRad;
    js.fisher_k = f.kappa;
    js.count = static_cast<int>(f.count);
    js.alpha95_deg = f.alpha95 * kDegPerRad;
    sets.push_back(js);
  }
  store.save_measurements(visit, planes);
  if (v == 0) store.save_joints(visit, sets, storage::test::sample_joints());
  store.save_analysis(analysis_with_shapes(store, visit, model));
  VisitPlacement p;
  p.visit_id = visit;
  p.chainage = chainage;
  p.note = "typed";
  store.save_visit_placement(p);
}

}  // namespace

void make_tablet_project(const fs::path& file, const TabletProject& o) {
  ProjectInfo info = storage::test::sample_project();
  info.name = o.name;
  ProjectStore store = ProjectStore::create(file, info);
  const fs::path samples = fs::path(ROCKFACE_SOURCE_DIR) / "tools/samples";
  TunnelRecord tunnel;
  tunnel.name = o.tunnel;
  tunnel.underbreak_tolerance_m = o.underbreak_tolerance_m;
  const AlignmentTable table = read_alignment_csv(samples / "tunnel-drive.alignment.csv");
  tunnel.stations = table.stations;
  tunnel.radii = table.radii;
  tunnel.polyline = table.polyline;
  tunnel.profile = read_profile_file(samples / "tunnel-drive.profile.json");
  store.save_tunnel(tunnel);
  const RecordId calibration = store.save_calibration(storage::test::sample_calibration());
  for (int v = 0; v < o.visits; ++v) add_visit(store, o, calibration, v);
  if (o.dense_face_visit) {
    const RecordId visit = store.begin_visit(o.name + " mapped face");
    const rockface::test::DenseFace face =
        rockface::test::dense_face(40, static_cast<unsigned>(o.seed));
    std::vector<Measurement> measurements;
    Measurement area;
    area.kind = Measurement::Kind::area;
    area.label = "FACE";
    area.points = face.polygon();
    area.dip_deg = 90;
    area.dipdir_deg = 180;
    area.rock_side = "lower";
    measurements.push_back(area);
    std::vector<Joint> joints;
    for (const auto& t : face.traces) {
      Measurement m;
      m.kind = Measurement::Kind::trace;
      m.label = t.id;
      m.joint_label = t.joint;
      m.points = {t.from, t.point, t.to};
      m.dip_deg = t.dip;
      m.dipdir_deg = t.dipdir;
      measurements.push_back(m);
      Joint j;
      j.label = t.joint;
      j.dip_deg = t.dip;
      j.dipdir_deg = t.dipdir;
      j.point = t.point;
      j.friction_deg = t.friction;
      j.cohesion_pa = 0;
      j.source = "trace " + t.id;
      joints.push_back(j);
    }
    store.save_measurements(visit, measurements);
    store.save_joints(visit, {}, joints);
  }
}

void add_tablet_visit(const fs::path& file, const TabletProject& options, int v) {
  ProjectStore store = ProjectStore::open(file);
  const auto calibrations = store.list_calibrations();
  if (calibrations.empty()) throw std::runtime_error(file.string() + " has no calibration");
  add_visit(store, options, calibrations.front().id, v);
}

std::string project_content(const fs::path& file) {
  sqlite::Connection db(file, sqlite::Connection::Access::read_only);
  std::vector<std::string> tables;
  {
    office::RawStatement st(db,
                            "SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT "
                            "LIKE 'sync_%' AND name NOT LIKE 'sqlite_%' ORDER BY name",
                            "listing tables");
    while (st.step()) tables.push_back(st.text(0));
  }
  std::ostringstream out;
  for (const auto& t : tables) {
    office::RawStatement st(db, "SELECT * FROM " + t + " ORDER BY rowid", "dumping " + t);
    out << "table " << t << "\n";
    while (st.step()) {
      for (int c = 0; c < st.columns(); ++c) {
        if (st.type(c) == SQLITE_BLOB) {
          const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(st.get(), c));
          out << office::hex_of(p, static_cast<std::size_t>(sqlite3_column_bytes(st.get(), c)));
        } else if (st.type(c) == SQLITE_FLOAT) {
          char text[40];
          std::snprintf(text, sizeof(text), "%.17g", sqlite3_column_double(st.get(), c));
          out << text;
        } else {
          out << st.text(c);
        }
        out << "|";
      }
      out << "\n";
    }
  }
  return out.str();
}

std::string first_difference(const std::string& a, const std::string& b) {
  if (a == b) return "";
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool ga = static_cast<bool>(std::getline(sa, la));
    const bool gb = static_cast<bool>(std::getline(sb, lb));
    if (!ga && !gb) return "differ in length";
    if (la != lb || ga != gb)
      return "line " + std::to_string(line) + ":\n  " + la.substr(0, 300) + "\n  " +
             lb.substr(0, 300);
  }
}

void expect_server_holds(const std::string& superuser, const fs::path& project,
                         int revisions_each) {
  sqlite::Connection db(project, sqlite::Connection::Access::read_write);
  const office::ProjectDocuments docs = office::read_project_documents(db);
  office::Connection c(superuser);
  const office::Result r = c.query(
      "SELECT kind, uuid::text, content_sha256, body::text, revision, "
      "count(*) OVER (PARTITION BY kind, uuid), deleted FROM (SELECT *, rank() OVER (PARTITION BY "
      "kind, "
      "uuid ORDER BY revision DESC) AS newest FROM rockface.record WHERE project_uuid = "
      "$1::uuid) r WHERE newest = 1 OR true ORDER BY kind, uuid, revision",
      {office::Param::of(docs.project_uuid)}, "checking the server");
  struct Held {
    std::string sha, body;
    int revisions = 0;
    bool deleted = false;
  };
  std::map<std::pair<std::string, std::string>, Held> held;
  for (int i = 0; i < r.rows(); ++i) {
    Held& h = held[{r.text(i, 0), r.text(i, 1)}];
    h.sha = r.text(i, 2);  // rows come oldest first: the last one is the newest
    h.body = r.text(i, 3);
    h.revisions = static_cast<int>(r.int64(i, 5));
    h.deleted = r.text(i, 6) == "t";
  }
  // A record whose newest revision is its deletion is no longer held.
  std::erase_if(held, [](const auto& kv) { return kv.second.deleted; });
  EXPECT_EQ(held.size(), docs.records.size()) << "records on the server vs the tablet";
  for (const auto& d : docs.records) {
    const auto it = held.find({d.kind, d.uuid});
    if (it == held.end()) {
      ADD_FAILURE() << d.kind << " " << d.uuid << " is not on the server";
      continue;
    }
    EXPECT_EQ(it->second.sha, d.content_sha256) << d.kind << " " << d.local_id;
    EXPECT_EQ(nlohmann::json::parse(it->second.body), nlohmann::json::parse(d.body))
        << d.kind << " " << d.local_id;
    if (revisions_each > 0) {
      EXPECT_EQ(it->second.revisions, revisions_each) << d.kind << " " << d.local_id;
    }
    for (const auto& b : d.blobs) {
      const office::Result blob = c.query(
          "SELECT b.complete, b.byte_size, (SELECT encode(sha256(string_agg(bytes, ''::bytea "
          "ORDER BY idx)), 'hex') FROM rockface.blob_chunk WHERE sha256 = b.sha256) FROM "
          "rockface.blob b WHERE b.sha256 = $1",
          {office::Param::of(b.sha256)}, "checking a blob");
      ASSERT_EQ(blob.rows(), 1) << "blob " << b.sha256 << " of " << d.kind;
      EXPECT_EQ(blob.text(0, 0), "t");
      EXPECT_EQ(blob.int64(0, 1), b.size);
      EXPECT_EQ(blob.text(0, 2), b.sha256);
    }
  }
}

}  // namespace rockface::office_test
