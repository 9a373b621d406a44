// A project written by version 1 of the layout (images inline in the capture
// row) opens in this program, is upgraded in place, and loses nothing.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <Eigen/Geometry>

#include "core/common/error.h"
#include "storage/project/project_blobs.h"
#include "storage/project/project_schema.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

using test::TempDir;

// Writes a version-1 project the way version 1 of rockface did: the schema
// function kept for that version plus the INSERTs of that layout.
struct Version1File {
  Capture first, second;
  RecordId model_id = 0;
};

Version1File write_version_1(const std::filesystem::path& file) {
  Version1File v1;
  sqlite::Connection db(file, sqlite::Connection::Access::read_write_create);
  db.exec("PRAGMA foreign_keys = ON", "test");
  schema::create_version_1(db);
  db.exec("PRAGMA journal_mode = WAL", "test");
  sqlite::WriteTransaction tx(db, "test");
  db.exec(
      "INSERT INTO project VALUES (1, 'old site', 2690000.5, 1170000.25, 1100, 'LV95', "
      "'2025-01-01T00:00:00.000Z', 'rockface 0.0');"
      "INSERT INTO visit VALUES (1, '2025-01-02T08:00:00.000Z', 'tablet', '');"
      "INSERT INTO visit VALUES (2, '2025-01-03T08:00:00.000Z', 'tablet', 'same pair again');",
      "test");
  v1.first = test::sample_capture(1, 4);
  v1.second = test::sample_capture(2, 5);
  // The second visit re-used the first pair's right image (same bytes).
  v1.second.right = v1.first.right;
  sqlite::Statement cap(db,
                        "INSERT INTO capture (id, visit_id, calibration_id, label, taken_at, "
                        "created_at, left_format, right_format, left_image, right_image) VALUES "
                        "(?, ?, NULL, ?, ?, ?, 'jpeg', ?, ?, ?)",
                        "test");
  RecordId id = 1;
  for (const Capture* c : {&v1.first, &v1.second}) {
    cap.reset();
    cap.bind(1, id).bind(2, c->visit_id).bind(3, c->label).bind(4, c->taken_at);
    cap.bind(5, "2025-01-02T08:00:00.000Z");
    cap.bind(6, c->right.bytes[0] == 0x89 ? "png" : "jpeg");
    cap.bind_blob(7, c->left.bytes).bind_blob(8, c->right.bytes);
    cap.run();
    ++id;
  }
  db.exec(
      "INSERT INTO capture_setting VALUES (1, 'iso', '100');"
      "INSERT INTO capture_exif VALUES (2, 'left', 'Make', 'Canon');"
      "INSERT INTO action_log VALUES (1, '2025-01-02T08:00:00.000Z', 1, 'capture saved', '');",
      "test");
  // Model 7 registered by its range pole; model 8 a further pair of the
  // visit registered onto the face (its registration the map onto the
  // face, its camera's map not kept).
  sqlite::Statement model(db,
                          "INSERT INTO model VALUES (7, 2, '2025-01-03T09:00:00.000Z', 'fast', 1, "
                          "0, ?, 2, 'right', 'range_pole_compass', 2.5, 0.6, 0.8, 0, 0, 10, 20, "
                          "30, '{}', 0)",
                          "test");
  Mesh mesh;
  mesh.vertices = {{1, 2, 3}};
  const auto blob = blobs::encode_mesh(mesh);
  model.bind_blob(1, blob);
  model.run();
  sqlite::Statement further(db,
                            "INSERT INTO model VALUES (8, 1, '2025-01-03T09:00:00.000Z', 'fast', "
                            "1, 0, ?, 1, 'left', 'face_images', 0.5, 1, 0, 0, 0, 1, 2, 3, "
                            "'{\"format\": \"rockface-face-registration/1\"}', 0.01)",
                            "test");
  further.bind_blob(1, blob);
  further.run();
  v1.model_id = 7;
  tx.commit();
  return v1;
}

TEST(ProjectMigration, Version1FileIsUpgradedWithEveryRecord) {
  TempDir dir("migration");
  const auto file = dir / "old.rockface";
  const Version1File v1 = write_version_1(file);

  {
    // Read-only opening cannot upgrade: it says so and leaves the file at v1.
    try {
      OpenOptions reading;
      reading.read_only = true;
      ProjectStore::open(file, reading);
      FAIL() << "an old project was served read-only without its upgrade";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("older rockface"), std::string::npos) << e.what();
    }
    sqlite::Connection db(file, sqlite::Connection::Access::read_only);
    EXPECT_EQ(schema::version_of(db), 1);
  }

  auto store = ProjectStore::open(file);
  EXPECT_EQ(store.schema_version(), schema::kCurrentVersion);
  EXPECT_TRUE(store.check_integrity().ok);
  EXPECT_EQ(store.project().name, "old site");
  EXPECT_EQ(store.project().datum.x(), 2690000.5);
  ASSERT_EQ(store.list_visits().size(), 2u);

  const auto captures = store.list_captures();
  ASSERT_EQ(captures.size(), 2u);
  const Capture first = store.load_capture(1);
  const Capture second = store.load_capture(2);
  EXPECT_EQ(first.left.bytes, v1.first.left.bytes);
  EXPECT_EQ(first.right.bytes, v1.first.right.bytes);
  EXPECT_EQ(second.left.bytes, v1.second.left.bytes);
  EXPECT_EQ(second.right.bytes, v1.first.right.bytes);
  EXPECT_EQ(first.label, v1.first.label);
  EXPECT_EQ(second.visit_id, 2);
  EXPECT_EQ(first.settings.at("iso"), "100");
  EXPECT_EQ(second.left_exif.at("Make"), "Canon");

  // The model still points at capture 2 (the table was rebuilt under it).
  const Model model = store.load_model(v1.model_id);
  EXPECT_EQ(model.capture_id, 2);
  EXPECT_EQ(model.texture_capture_id, 2);
  // Schema 4: a model registered on its own has its registration as the
  // map from its camera frame (exactly: the same numbers are copied).
  ASSERT_TRUE(model.camera_to_mesh);
  EXPECT_EQ(model.camera_to_mesh->scale, 2.5);
  const Eigen::Matrix3d R = Eigen::Quaterniond(0.6, 0.8, 0, 0).toRotationMatrix();
  // 1e-12: the quaternion is unit in the file; normalising and turning it
  // into a matrix costs a few ulps.
  EXPECT_LT((model.camera_to_mesh->R - R).norm(), 1e-12);
  EXPECT_EQ(model.camera_to_mesh->t, Eigen::Vector3d(10, 20, 30));
  // A further pair's registration maps its 3D image onto the face, not its
  // camera: its camera's map stays unknown, its registration as it was.
  const Model further = store.load_model(8);
  EXPECT_FALSE(further.camera_to_mesh);
  EXPECT_EQ(further.registration.kind, "face_images");
  EXPECT_EQ(further.registration.scale, 0.5);
  EXPECT_EQ(further.registration.translation, Eigen::Vector3d(1, 2, 3));

  // Four images in v1 rows, three distinct byte strings: the shared right
  // image is stored once after the upgrade.
  sqlite::Connection raw(file, sqlite::Connection::Access::read_only);
  EXPECT_EQ(raw.query_int("SELECT count(*) FROM image", "test"), 3);
  EXPECT_EQ(raw.query_int("PRAGMA foreign_key_check", "test"), 0);

  // The upgraded file takes new records with foreign keys enforced.
  const RecordId visit = store.begin_visit("tablet");
  store.save_capture(test::sample_capture(visit, 6));
  EXPECT_EQ(store.list_captures().size(), 3u);
}

TEST(ProjectMigration, NewerSchemaOpensReadOnlyWithAClearMessage) {
  TempDir dir("newer");
  const auto file = dir / "future.rockface";
  RecordId visit = 0;
  {
    auto store = ProjectStore::create(file, test::sample_project());
    visit = store.begin_visit("tablet");
    store.save_capture(test::sample_capture(visit, 1));
  }
  {
    // What a later rockface would do: add something and bump the version.
    sqlite::Connection db(file, sqlite::Connection::Access::read_write);
    db.exec("ALTER TABLE capture ADD COLUMN weather TEXT; PRAGMA user_version = 99", "test");
  }
  const auto before = test::read_file_bytes(file);
  auto store = ProjectStore::open(file);
  EXPECT_TRUE(store.read_only());
  EXPECT_EQ(store.schema_version(), 99);
  EXPECT_NE(store.read_only_reason().find("newer rockface"), std::string::npos);
  // Everything is readable...
  ASSERT_EQ(store.list_captures().size(), 1u);
  EXPECT_FALSE(store.load_capture(store.list_captures()[0].id).left.bytes.empty());
  // ...and nothing can be written, with the reason in the message.
  try {
    store.begin_visit("tablet");
    FAIL() << "a newer project was written to";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("newer rockface"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::read_file_bytes(file), before);
}

}  // namespace
}  // namespace rockface::storage
