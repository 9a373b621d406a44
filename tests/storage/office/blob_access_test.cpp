// Issue 39: a tunnel's photographs and meshes (blobs and their chunks) are
// read only by roles that may read a record referring to them, and by their
// uploader while the upload is unfinished; a chunk is added only by its
// blob's uploader. Schema version 2 (storage/office/server_schema_sql.h).
#include <gtest/gtest.h>

#include <string>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/office/server_schema.h"
#include "storage/office/server_schema_sql.h"
#include "storage/office/sync_push.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/sample_records.h"

namespace rockface::office_test {
namespace {

using storage::office::Connection;
using storage::office::Param;

constexpr const char* kDenied = "42501";  // insufficient privilege / RLS violation

std::int64_t count(const std::string& conninfo, const std::string& sql) {
  Connection c(conninfo);
  return c.query(sql, {}, "counting").int64(0, 0);
}

// Tunnel "Main drive" (tablets a and b, office_reader for all tunnels) and
// "Other drive" (tablet_c, and an office login of that tunnel only).
std::string two_tunnels() {
  const std::string db = fresh_database();
  Connection admin(as_superuser(db));
  storage::office::add_tunnel(admin, "Other drive");
  storage::office::add_tablet(admin, "tablet_c", "Other drive");
  storage::office::add_office_user(admin, "office_other", "Other drive");
  storage::office::add_office_user(admin, "office_main", "Main drive");
  return db;
}

TEST(OfficeBlobs, AnotherTunnelsTabletAndOfficeReadNoneOfATunnelsPhotographsAndMeshes) {
  const std::string db = two_tunnels();
  storage::test::TempDir dir("office-blobs");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  const auto sent =
      storage::office::sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none);
  ASSERT_GT(sent.blobs_sent, 0);
  const std::int64_t blobs = count(as_superuser(db), "SELECT count(*) FROM rockface.blob");
  const std::int64_t chunks = count(as_superuser(db), "SELECT count(*) FROM rockface.blob_chunk");
  ASSERT_EQ(blobs, sent.blobs_sent);
  ASSERT_GT(chunks, 0);
  for (const char* other : {"tablet_c", "office_other"}) {
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.blob"), 0) << other;
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.blob_chunk"), 0) << other;
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.blob_ref"), 0) << other;
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.record"), 0) << other;
  }
  // Who may read the records reads every blob and chunk they refer to.
  for (const char* reader : {"tablet_a", "tablet_b", "office_reader", "office_main"}) {
    EXPECT_EQ(count(as_role(db, reader), "SELECT count(*) FROM rockface.blob"), blobs) << reader;
    EXPECT_EQ(count(as_role(db, reader), "SELECT count(*) FROM rockface.blob_chunk"), chunks)
        << reader;
  }
  // An office login of one tunnel reads and never writes.
  EXPECT_EQ(refusal(as_role(db, "office_main"), "DELETE FROM rockface.blob"), kDenied);
  EXPECT_EQ(refusal(as_role(db, "office_main"),
                    "INSERT INTO rockface.blob (sha256, byte_size, chunk_size) VALUES "
                    "(repeat('e', 64), 1, 1)"),
            kDenied);
  // Pulling the tunnel as its office login gets every photograph back.
  const auto pulled = storage::office::pull_tunnel(as_role(db, "office_main"), "Main drive",
                                                   dir / "p.rockface", none);
  EXPECT_EQ(pulled.blobs, blobs);
  // The other tunnel's office login pulls nothing of it.
  EXPECT_THROW(storage::office::pull_tunnel(as_role(db, "office_other"), "Main drive",
                                            dir / "q.rockface", none),
               std::exception);
}

TEST(OfficeBlobs, AnUnfinishedUploadIsReadAndContinuedByItsUploaderOnly) {
  const std::string db = two_tunnels();
  const std::string sha(64, 'a');
  Connection a(as_role(db, "tablet_a"));
  a.query("INSERT INTO rockface.blob (sha256, byte_size, chunk_size) VALUES ($1, 4, 2)",
          {Param::of(sha)}, "starting an upload");
  a.query("INSERT INTO rockface.blob_chunk (sha256, idx, bytes) VALUES ($1, 0, '\\x0102')",
          {Param::of(sha)}, "sending a chunk");
  EXPECT_EQ(count(as_role(db, "tablet_a"), "SELECT count(*) FROM rockface.blob_chunk"), 1);
  // Neither a tablet of the same tunnel nor another's sees it or adds to it.
  for (const char* other : {"tablet_b", "tablet_c"}) {
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.blob"), 0) << other;
    EXPECT_EQ(count(as_role(db, other), "SELECT count(*) FROM rockface.blob_chunk"), 0) << other;
    EXPECT_EQ(refusal(as_role(db, other),
                      "INSERT INTO rockface.blob_chunk (sha256, idx, bytes) "
                      "VALUES (repeat('a', 64), 1, '\\x0304')"),
              kDenied)
        << other;
  }
}

TEST(OfficeBlobs, TheSamePhotographSyncedByTwoTunnelsIsStoredOnceAndReadByBoth) {
  const std::string db = two_tunnels();
  storage::test::TempDir dir("office-blobs-twice");
  TabletProject a;
  a.visits = 1;
  TabletProject c = a;  // same seed: the same photographs and meshes, byte for byte
  c.tunnel = "Other drive";
  make_tablet_project(dir / "a.rockface", a);
  make_tablet_project(dir / "c.rockface", c);
  NoProgress none;
  const auto first =
      storage::office::sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none);
  const auto second =
      storage::office::sync_project(dir / "c.rockface", as_role(db, "tablet_c"), {}, none);
  EXPECT_EQ(second.blobs_sent, 0);
  EXPECT_EQ(second.blobs_already_there, first.blobs_sent);
  const std::int64_t blobs = count(as_superuser(db), "SELECT count(*) FROM rockface.blob");
  EXPECT_EQ(blobs, first.blobs_sent);
  EXPECT_EQ(count(as_role(db, "tablet_c"), "SELECT count(*) FROM rockface.blob"), blobs);
  const auto pulled = storage::office::pull_tunnel(as_role(db, "tablet_c"), "Other drive",
                                                   dir / "p.rockface", none);
  EXPECT_EQ(pulled.blobs, blobs);
}

TEST(OfficeBlobs, AVersionOneServerUpgradedKeepsItsTunnelsBlobsApart) {
  // A server as version 1 left it: the blob of tunnel "Main drive"'s record
  // was readable by every role.
  const std::string db = fresh_database_at_version_one();
  const std::string sha(64, 'b');
  {
    Connection su(as_superuser(db));
    su.exec(
        "INSERT INTO rockface.tunnel (name) VALUES ('Old drive'), ('Next drive');"
        "INSERT INTO rockface.blob (sha256, byte_size, chunk_size, complete) "
        "VALUES (repeat('b', 64), 2, 2, true);"
        "INSERT INTO rockface.blob_chunk (sha256, idx, bytes) VALUES (repeat('b', 64), 0, "
        "'\\x0102');"
        "INSERT INTO rockface.project (uuid, tunnel_id, owner, name) SELECT "
        "'00000000-0000-0000-0000-000000000001', id, 'someone', 'p' FROM rockface.tunnel "
        "WHERE name = 'Old drive';"
        "INSERT INTO rockface.record (kind, uuid, revision, tunnel_id, project_uuid, owner, "
        "project_schema, content_sha256, body) SELECT 'capture', "
        "'00000000-0000-0000-0000-000000000002', 1, id, "
        "'00000000-0000-0000-0000-000000000001', 'someone', 1, 'x', "
        "jsonb_build_object('left', jsonb_build_object('$blob', repeat('b', 64))) "
        "FROM rockface.tunnel WHERE name = 'Old drive';",
        "a version 1 server's rows");
    const auto upgraded = storage::office::init_server(su);
    EXPECT_EQ(upgraded.from_version, 1);
    EXPECT_EQ(upgraded.to_version, storage::office::kServerSchemaVersion);
    storage::office::add_tablet(su, "tablet_old", "Old drive");
    storage::office::add_tablet(su, "tablet_next", "Next drive");
  }
  EXPECT_EQ(count(as_role(db, "tablet_old"), "SELECT count(*) FROM rockface.blob"), 1);
  EXPECT_EQ(count(as_role(db, "tablet_old"), "SELECT count(*) FROM rockface.blob_chunk"), 1);
  EXPECT_EQ(count(as_role(db, "tablet_next"), "SELECT count(*) FROM rockface.blob"), 0);
  EXPECT_EQ(count(as_role(db, "tablet_next"), "SELECT count(*) FROM rockface.blob_chunk"), 0);
}

}  // namespace
}  // namespace rockface::office_test
