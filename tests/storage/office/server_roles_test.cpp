// Who may do what, enforced by the server (privileges and row-level
// security, not the client): a tablet may not delete or alter another
// tablet's visit or records, nor add a revision to them, nor read another
// tunnel; the office reads everything and writes nothing. TLS with
// sslmode=verify-full against a certificate from a CA made in the test,
// the password from a pgpass file, the server named by a service file, and
// no password in any message. An admin made by the superuser sets up a
// tunnel and its tablets without the superuser; a tablet cannot.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_schema.h"
#include "storage/office/sync_push.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/sample_records.h"
#include "tests/support/test_paths.h"

namespace rockface::office_test {
namespace {

namespace fs = std::filesystem;
using storage::office::Connection;
using storage::office::Param;
using storage::office::ServerError;

TEST(OfficeRoles, ATabletCannotChangeOrDeleteAnotherTabletsVisit) {
  const std::string db = fresh_database();
  {
    Connection admin(as_superuser(db));
    storage::office::add_tunnel(admin, "Other drive");
    storage::office::add_tablet(admin, "tablet_c", "Other drive");
  }
  storage::test::TempDir dir("office-roles");
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  storage::office::sync_project(dir / "a.rockface", as_role(db, "tablet_a"), {}, none);
  const std::string b = as_role(db, "tablet_b");
  constexpr const char* kDenied = "42501";  // insufficient privilege / RLS violation
  EXPECT_EQ(refusal(b, "DELETE FROM rockface.visit"), kDenied);
  EXPECT_EQ(refusal(b, "DELETE FROM rockface.record"), kDenied);
  EXPECT_EQ(refusal(b, "UPDATE rockface.visit SET started_at = 'x'"), kDenied);
  EXPECT_EQ(refusal(b, "UPDATE rockface.record SET body = '{}'"), kDenied);
  EXPECT_EQ(refusal(b, "DELETE FROM rockface.blob_chunk"), kDenied);
  // A new revision of tablet A's visit record, in tablet B's name or A's.
  const std::string revise =
      "INSERT INTO rockface.record (kind, uuid, revision, tunnel_id, project_uuid, visit_uuid, "
      "project_schema, content_sha256, body) SELECT kind, uuid, revision + 1, tunnel_id, "
      "project_uuid, visit_uuid, project_schema, 'x', '{}' FROM rockface.record WHERE kind = "
      "'visit'";
  EXPECT_EQ(refusal(b, revise), kDenied);
  EXPECT_EQ(refusal(b,
                    "INSERT INTO rockface.visit (uuid, tunnel_id, project_uuid, owner, "
                    "local_id, started_at) SELECT gen_random_uuid(), tunnel_id, project_uuid, "
                    "'tablet_a', 9, 'x' FROM rockface.visit"),
            kDenied);
  // Tablet A itself may not rewrite history either: a change is a revision.
  EXPECT_EQ(refusal(as_role(db, "tablet_a"), "DELETE FROM rockface.visit"), kDenied);
  // The office reads and never writes; another tunnel's tablet sees nothing.
  Connection office(as_role(db, "office_reader"));
  EXPECT_GT(office.query("SELECT count(*) FROM rockface.record", {}, "reading").int64(0, 0), 0);
  EXPECT_EQ(refusal(as_role(db, "office_reader"), "DELETE FROM rockface.visit"), kDenied);
  Connection c(as_role(db, "tablet_c"));
  EXPECT_EQ(c.query("SELECT count(*) FROM rockface.record", {}, "reading").int64(0, 0), 0);
  EXPECT_EQ(c.query("SELECT count(*) FROM rockface.visit", {}, "reading").int64(0, 0), 0);
  // Tablet B reads its tunnel, tablet A's visit included.
  Connection tb(b);
  EXPECT_EQ(tb.query("SELECT count(*) FROM rockface.visit", {}, "reading").int64(0, 0), 1);
  // And the server still holds tablet A's records, each once.
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
}

TEST(OfficeRoles, AnAdminAddsTunnelsTabletsAndOfficeUsersWithoutTheSuperuser) {
  const std::string db = fresh_database();
  {
    // The verb, as the database administrator types it.
    storage::test::TempDir out("office-admin-verb");
    const std::string command = std::string(ROCKFACE_BINARY_DIR) + "/rockface server add-admin '" +
                                as_superuser(db) + "' site_admin >" + (out / "out.txt").string() +
                                " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream said(out / "out.txt");
    const std::string text((std::istreambuf_iterator<char>(said)), {});
    EXPECT_NE(text.find("admin role site_admin creates tunnels"), std::string::npos) << text;
  }
  {
    Connection admin(as_role(db, "site_admin"));
    storage::office::add_tunnel(admin, "Adit 2");
    storage::office::add_tablet(admin, "tablet_adit", "Adit 2");
    storage::office::add_office_user(admin, "adit_office");
  }
  // The admin's tablet syncs to the admin's tunnel, and the admin's office
  // user reads it.
  storage::test::TempDir dir("office-admin");
  TabletProject a;
  a.visits = 1;
  a.tunnel = "Adit 2";
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  storage::office::sync_project(dir / "a.rockface", as_role(db, "tablet_adit"), {}, none);
  Connection office(as_role(db, "adit_office"));
  EXPECT_EQ(office
                .query("SELECT count(*) FROM rockface.visit v JOIN rockface.tunnel t ON t.id = "
                       "v.tunnel_id WHERE t.name = 'Adit 2'",
                       {}, "reading")
                .int64(0, 0),
            1);
  // A tablet is no admin: no tunnel, no role, no admin of itself.
  constexpr const char* kDenied = "42501";
  EXPECT_EQ(refusal(as_role(db, "tablet_a"), "INSERT INTO rockface.tunnel (name) VALUES ('Rogue')"),
            kDenied);
  EXPECT_EQ(refusal(as_role(db, "tablet_a"), "CREATE ROLE rogue_tablet LOGIN"), kDenied);
  EXPECT_EQ(refusal(as_role(db, "tablet_a"), "GRANT rockface_admin TO tablet_a"), kDenied);
  EXPECT_EQ(refusal(as_role(db, "adit_office"), "INSERT INTO rockface.tunnel (name) VALUES ('X')"),
            kDenied);
}

TEST(OfficeRoles, TlsVerifyFullWithPgpassAndAServiceFileAndNoPasswordShown) {
  const std::string db = fresh_database();
  const std::string secret = "Granite-7-Schist";
  server().psql("CREATE ROLE tablet_tls LOGIN PASSWORD '" + secret + "'", db);
  {
    Connection admin(as_superuser(db));
    storage::office::add_tablet(admin, "tablet_tls", "Main drive");
  }
  const fs::path pgpass = server().write_pgpass("tablet_tls", secret);
  ::setenv("PGPASSFILE", pgpass.c_str(), 1);
  {
    Connection c(server().tls_conninfo("tablet_tls", db));
    EXPECT_TRUE(c.ssl_in_use());
  }
  // The tablet's service file names the server once.
  storage::test::TempDir dir("office-tls");
  std::ofstream(dir / "pg_service.conf")
      << "[site-office]\nhost=localhost\nport=" << server().port() << "\ndbname=" << db
      << "\nuser=tablet_tls\nsslmode=verify-full\nsslrootcert="
      << server().ca_certificate().string() << "\n";
  ::setenv("PGSERVICEFILE", (dir / "pg_service.conf").c_str(), 1);
  TabletProject a;
  a.visits = 1;
  make_tablet_project(dir / "a.rockface", a);
  NoProgress none;
  const auto r = storage::office::sync_project(dir / "a.rockface", "service=site-office", {}, none);
  EXPECT_EQ(r.units_sent, 2);
  expect_server_holds(as_superuser(db), dir / "a.rockface", 1);
  EXPECT_EQ(project_content(dir / "a.rockface").find(secret), std::string::npos);

  // A wrong password in a URL: refused, and the message masks it.
  const std::string wrong = "Basalt-9-Wrong";
  std::string url = server().tls_conninfo("tablet_tls", db);
  url.replace(url.find("tablet_tls@"), 11, "tablet_tls:" + wrong + "@");
  try {
    Connection c(url);
    ADD_FAILURE() << "connected with a wrong password";
  } catch (const ServerError& e) {
    EXPECT_EQ(std::string(e.what()).find(wrong), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("****"), std::string::npos) << e.what();
  }
  EXPECT_EQ(storage::office::masked_conninfo("host=x password='a b' user=y"),
            "host=x password=**** user=y");
  // verify-full against a CA that did not sign the server's certificate.
  const fs::path other = dir / "other-ca.crt";
  const std::string make_ca =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 1 -subj /CN=other "
      "-keyout " +
      (dir / "other.key").string() + " -out " + other.string() + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(make_ca.c_str()), 0);
  std::string foreign = server().tls_conninfo("tablet_tls", db);
  foreign.replace(foreign.find("sslrootcert=") + 12, std::string::npos, other.string());
  try {
    Connection c(foreign);
    ADD_FAILURE() << "verify-full accepted a server its CA did not sign";
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("certificate"), std::string::npos) << e.what();
  }
  ::unsetenv("PGPASSFILE");
  ::unsetenv("PGSERVICEFILE");
}

}  // namespace
}  // namespace rockface::office_test
