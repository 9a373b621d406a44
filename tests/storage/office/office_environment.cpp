#include "tests/storage/office/office_environment.h"

#include <gtest/gtest.h>

#include <memory>

#include "storage/office/pg_connection.h"
#include "storage/office/server_schema.h"
#include "storage/office/server_schema_sql.h"

namespace rockface::office_test {

namespace {

std::unique_ptr<test::PostgresServer> the_server;

class ServerEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    test::PostgresServer::Options options;
    options.tls = true;
    the_server = std::make_unique<test::PostgresServer>(options);
  }
  void TearDown() override { the_server.reset(); }
};

[[maybe_unused]] auto* const environment =
    ::testing::AddGlobalTestEnvironment(new ServerEnvironment);

// CREATE DATABASE as a file copy of template1 (PostgreSQL 15's other
// strategy, WAL_LOG, writes each of its pages to the log: ~0.6 s a database
// against ~0.1 s under CI's load, and the kill test makes one per kill
// point). The database made is the same; the cluster is the test's own.
void create_database(const std::string& db) {
  server().psql("CREATE DATABASE " + db + " STRATEGY = FILE_COPY", "postgres");
}

}  // namespace

test::PostgresServer& server() {
  return *the_server;
}

std::string as_superuser(const std::string& db) {
  return server().socket_conninfo(test::PostgresServer::kSuperuser, db);
}

std::string as_role(const std::string& db, const std::string& role) {
  return server().socket_conninfo(role, db);
}

std::string refusal(const std::string& conninfo, const std::string& sql) {
  storage::office::Connection c(conninfo);
  try {
    c.exec(sql, "trying");
    return "";
  } catch (const storage::office::ServerError& e) {
    return e.sqlstate();
  }
}

std::string fresh_database(const std::string& tunnel) {
  static int count = 0;
  const std::string db = "site" + std::to_string(++count);
  create_database(db);
  storage::office::Connection c(as_superuser(db));
  storage::office::init_server(c);
  storage::office::add_tunnel(c, tunnel);
  storage::office::add_tablet(c, "tablet_a", tunnel);
  storage::office::add_tablet(c, "tablet_b", tunnel);
  storage::office::add_office_user(c, "office_reader");
  return db;
}

std::string fresh_database_at_version_one() {
  static int count = 0;
  const std::string db = "old_site" + std::to_string(++count);
  create_database(db);
  storage::office::Connection c(as_superuser(db));
  c.exec(storage::office::sql::kRoles, "creating the roles of version 1");
  c.exec(storage::office::sql::kVersion1, "creating the layout of version 1");
  c.exec("INSERT INTO rockface.meta (key, value) VALUES ('schema_version', '1')",
         "marking version 1");
  return db;
}

}  // namespace rockface::office_test
