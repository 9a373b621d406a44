#pragma once
// What the office benchmarks share (office_sync_bench.cpp,
// office_load_bench.cpp): a tablet's project of synthetic visits along a
// straight bench tunnel (a photograph, a 3D image made by the caller, 18
// measured planes in three sets, an analysis and a placement each, visits
// 3 m apart), and a copy of it as another tablet's (every record a new UUID,
// never synced).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/tunnel/design_profile.h"
#include "storage/office/sqlite_rows.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::bench {

// The visit's 3D image of its capture, `mesh_side` vertices a side.
using BenchModel = std::function<storage::Model(storage::RecordId capture, int mesh_side)>;

inline void add_bench_visit(storage::ProjectStore& store, int i, int width, int height,
                            int mesh_side, const BenchModel& model_of) {
  const storage::RecordId visit = store.begin_visit("bench visit " + std::to_string(i));
  const storage::RecordId cap =
      store.save_capture(storage::test::sample_capture(visit, i, width, height));
  const storage::RecordId model = store.save_model(model_of(cap, mesh_side));
  std::mt19937 rng(static_cast<unsigned>(i));
  std::normal_distribution<double> jitter(0, 2.0);
  std::vector<storage::Measurement> planes;
  for (const auto& [dip, dipdir] :
       std::vector<std::pair<double, double>>{{70, 120}, {45, 300}, {20, 30}})
    for (int k = 0; k < 6; ++k) {
      storage::Measurement m;
      m.visit_id = visit;
      m.model_id = model;
      m.label = "T" + std::to_string(planes.size() + 1);
      m.points = {{0, 3.0 * i, 0}, {0.5, 3.0 * i, 0.4}, {1, 3.0 * i, 1}};
      m.dip_deg = std::clamp(dip + jitter(rng), 0.0, 90.0);
      m.dipdir_deg = std::fmod(dipdir + jitter(rng) + 360, 360);
      planes.push_back(m);
    }
  store.save_measurements(visit, planes);
  store.save_analysis(storage::test::sample_analysis(visit, model));
  storage::VisitPlacement p;
  p.visit_id = visit;
  p.chainage = 3.0 * i;
  store.save_visit_placement(p);
}

// A 3D image of side x side vertices: a rough face on a grid (2 cm of
// roughness), textured by its grid position.
inline storage::Model grid_model(storage::RecordId capture, int side, const std::string& preset) {
  storage::Model m;
  m.capture_id = capture;
  m.preset = preset;
  std::mt19937 rng(3);
  std::normal_distribution<double> rough(0, 0.02);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      m.mesh.vertices.push_back({0.01 * i, rough(rng), 0.01 * j});
      m.mesh.texcoords.push_back({static_cast<float>(i) / side, static_cast<float>(j) / side});
    }
  for (int i = 0; i + 1 < side; ++i)
    for (int j = 0; j + 1 < side; ++j) {
      const int a = i * side + j;
      m.mesh.faces.push_back({a, a + 1, a + side});
      m.mesh.faces.push_back({a + 1, a + side + 1, a + side});
    }
  m.registration.kind = "none";
  return m;
}

// `folder`/NAME.rockface, made once (kept when it exists).
inline std::filesystem::path make_bench_project(const std::filesystem::path& folder,
                                                const std::string& name, int visits, int width,
                                                int height, int mesh_side,
                                                const BenchModel& model_of) {
  const std::filesystem::path file = folder / (name + ".rockface");
  if (std::filesystem::exists(file)) return file;
  storage::ProjectInfo info;
  info.name = name;
  storage::ProjectStore store = storage::ProjectStore::create(file, info);
  storage::TunnelRecord tunnel;
  tunnel.name = "bench";
  tunnel.stations = {{0, {0, 0, 0}}, {10000, {0, 10000, 0}}};
  tunnel.radii = {0};
  tunnel.profile = tunnel::circle_profile(3.0);
  store.save_tunnel(tunnel);
  for (int i = 0; i < visits; ++i) add_bench_visit(store, i, width, height, mesh_side, model_of);
  return file;
}

// A copy of a project as another tablet's: every record a new UUID.
inline std::filesystem::path another_tablets_copy(const std::filesystem::path& folder,
                                                  const std::filesystem::path& file,
                                                  const std::string& name) {
  const std::filesystem::path copy = folder / (name + ".rockface");
  std::filesystem::remove(copy);
  std::filesystem::copy_file(file, copy);
  storage::sqlite::Connection db(copy, storage::sqlite::Connection::Access::read_write);
  for (const char* t :
       {"project", "visit", "camera_body", "calibration", "image", "capture", "model",
        "measurement", "joint_set", "joint", "analysis", "block", "action_log"})
    db.exec(std::string("UPDATE ") + t +
                " SET uuid = lower(hex(randomblob(4)) || '-' || hex(randomblob(2)) || '-4' || "
                "substr(hex(randomblob(2)), 2) || '-a' || substr(hex(randomblob(2)), 2) || '-' "
                "|| hex(randomblob(6)))",
            "new uuids");
  db.exec("DELETE FROM sync_record; DELETE FROM sync_run; DELETE FROM sync_target", "reset");
  return copy;
}

}  // namespace rockface::bench
