// A model's mesh is stored in parts of storage/project/blob_parts.h's size
// (schema 11), so that a mesh over SQLite's 1 GB blob limit can be stored and
// no save or load holds it encoded whole; a model saved before schema 11,
// whose mesh is whole in model.mesh, still loads.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <cstring>

#include "storage/project/blob_parts.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

// A 700 x 700 grid with texture coordinates and colours: 490,000 vertices
// and 977,202 faces, 28.9 MB encoded, so four parts.
Model grid_model(RecordId capture_id) {
  Model m = test::sample_model(capture_id);
  m.mesh = {};
  constexpr int n = 700;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Survey-sized coordinates with sub-millimetre parts: every bit counts.
      m.mesh.vertices.emplace_back(276771.0 + 0.0101 * i, 5151636.0 + 1e-4 * j * i,
                                   2385.0 + 0.0103 * j);
      m.mesh.texcoords.push_back({static_cast<float>(i) / n, static_cast<float>(j) / n});
      m.mesh.colours.push_back({static_cast<std::uint8_t>(i % 256),
                                static_cast<std::uint8_t>(j % 256),
                                static_cast<std::uint8_t>((i + j) % 256)});
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = n * j + i;
      m.mesh.faces.push_back({a, a + 1, a + n + 1});
      m.mesh.faces.push_back({a, a + n + 1, a + n});
    }
  return m;
}

void expect_same_mesh(const Mesh& got, const Mesh& want) {
  ASSERT_EQ(got.vertices.size(), want.vertices.size());
  ASSERT_EQ(got.faces.size(), want.faces.size());
  // Doubles stored and read as their bytes: equal, not near.
  EXPECT_TRUE(got.vertices == want.vertices);
  EXPECT_TRUE(got.faces == want.faces);
  EXPECT_TRUE(got.texcoords == want.texcoords);
  EXPECT_TRUE(got.colours == want.colours);
}

struct StoredModel {
  std::int64_t column_bytes = -1;
  std::vector<std::int64_t> part_sizes;
  std::vector<std::uint8_t> stream;  // the parts joined
};

// Read with SQLite itself, not through the store's reader.
StoredModel stored_model(const std::filesystem::path& file, RecordId model) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  StoredModel out;
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "SELECT length(mesh) FROM model WHERE id = ?", -1, &st, nullptr);
  sqlite3_bind_int64(st, 1, model);
  if (sqlite3_step(st) == SQLITE_ROW) out.column_bytes = sqlite3_column_int64(st, 0);
  sqlite3_finalize(st);
  sqlite3_prepare_v2(db, "SELECT idx, bytes FROM model_mesh_part WHERE model_id = ? ORDER BY idx",
                     -1, &st, nullptr);
  sqlite3_bind_int64(st, 1, model);
  while (sqlite3_step(st) == SQLITE_ROW) {
    EXPECT_EQ(sqlite3_column_int64(st, 0), static_cast<std::int64_t>(out.part_sizes.size()));
    const auto* p = static_cast<const std::uint8_t*>(sqlite3_column_blob(st, 1));
    const int n = sqlite3_column_bytes(st, 1);
    out.part_sizes.push_back(n);
    out.stream.insert(out.stream.end(), p, p + n);
  }
  sqlite3_finalize(st);
  sqlite3_close(db);
  return out;
}

TEST(ProjectMeshParts, AModelsMeshIsStoredInPartsAndReadBackBitForBit) {
  TempDir dir("mesh-parts");
  const auto file = dir / "site.rockface";
  Model model;
  RecordId id = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    Capture capture = test::sample_capture(visit, 1);
    capture.calibration_id = store.save_calibration(test::sample_calibration());
    const RecordId capture_id = store.save_capture(capture);
    model = grid_model(capture_id);
    id = store.save_model(model);
  }
  const StoredModel stored = stored_model(file, id);
  EXPECT_EQ(stored.column_bytes, 0) << "the mesh is not in the model row";
  // The documented layout (project_blobs.h), counted here: header 28 bytes,
  // then 24 + 8 + 3 bytes a vertex and 12 a face.
  const std::size_t nv = model.mesh.vertices.size(), nf = model.mesh.faces.size();
  const std::size_t expected_bytes = 28 + nv * 35 + nf * 12;
  ASSERT_EQ(stored.stream.size(), expected_bytes);
  ASSERT_EQ(stored.part_sizes.size(), (expected_bytes + parts::kPartBytes - 1) / parts::kPartBytes);
  for (std::size_t i = 0; i + 1 < stored.part_sizes.size(); ++i)
    EXPECT_EQ(stored.part_sizes[i], static_cast<std::int64_t>(parts::kPartBytes)) << i;
  EXPECT_EQ(std::memcmp(stored.stream.data(), "RFMESH01", 8), 0);
  std::uint64_t counts[2];
  std::memcpy(counts, stored.stream.data() + 12, sizeof(counts));
  EXPECT_EQ(counts[0], nv);
  EXPECT_EQ(counts[1], nf);
  double last_vertex[3];
  std::memcpy(last_vertex, stored.stream.data() + 28 + (nv - 1) * 24, sizeof(last_vertex));
  EXPECT_EQ(last_vertex[0], model.mesh.vertices.back().x());
  EXPECT_EQ(last_vertex[2], model.mesh.vertices.back().z());

  auto store = ProjectStore::open(file);
  expect_same_mesh(store.load_model(id).mesh, model.mesh);
}

TEST(ProjectMeshParts, AMeshStoredWholeBeforeSchema11StillLoads) {
  TempDir dir("mesh-whole");
  const auto file = dir / "site.rockface";
  Model model;
  RecordId id = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    Capture capture = test::sample_capture(visit, 1);
    capture.calibration_id = store.save_calibration(test::sample_calibration());
    model = grid_model(store.save_capture(capture));
    id = store.save_model(model);
  }
  {
    // What schema 10 wrote: the encoded mesh whole in model.mesh, no parts.
    const auto whole = blobs::encode_mesh(model.mesh);
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(db, "UPDATE model SET mesh = ? WHERE id = ?", -1, &st, nullptr);
    sqlite3_bind_blob64(st, 1, whole.data(), whole.size(), SQLITE_STATIC);
    sqlite3_bind_int64(st, 2, id);
    EXPECT_EQ(sqlite3_step(st), SQLITE_DONE);
    sqlite3_finalize(st);
    EXPECT_EQ(sqlite3_exec(db, "DELETE FROM model_mesh_part", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
  }
  auto store = ProjectStore::open(file);
  expect_same_mesh(store.load_model(id).mesh, model.mesh);
}

TEST(ProjectMeshParts, AMissingPartIsDamageNamedNotAShortMesh) {
  TempDir dir("mesh-damaged");
  const auto file = dir / "site.rockface";
  RecordId id = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    const RecordId visit = store.begin_visit("tablet");
    Capture capture = test::sample_capture(visit, 1);
    capture.calibration_id = store.save_calibration(test::sample_calibration());
    id = store.save_model(grid_model(store.save_capture(capture)));
  }
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    EXPECT_EQ(
        sqlite3_exec(db, "DELETE FROM model_mesh_part WHERE idx = 1", nullptr, nullptr, nullptr),
        SQLITE_OK);
    sqlite3_close(db);
  }
  auto store = ProjectStore::open(file);
  try {
    store.load_model(id);
    FAIL() << "a mesh with a part missing loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rockface::storage
