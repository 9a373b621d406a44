#pragma once
// The office suite's one PostgreSQL server (with TLS on 127.0.0.1), and a
// fresh database per test made by `rockface server init`'s code with two
// tablet roles and an office role.
#include <string>

#include "tests/support/postgres_server.h"

namespace rockface::office_test {

test::PostgresServer& server();

// A new database with the rockface schema, tunnel `tunnel`, tablets
// tablet_a and tablet_b members of it, and office user office_reader.
// Returns its name.
std::string fresh_database(const std::string& tunnel = "Main drive");
// A new database as `rockface server init` of schema version 1 left it
// (no tunnels, tablets or rows): for the upgrade's tests.
std::string fresh_database_at_version_one();

// Socket connection strings to database `db` as a role.
std::string as_superuser(const std::string& db);
std::string as_role(const std::string& db, const std::string& role);

// Runs SQL as the connection's role; the SQLSTATE of the server's refusal,
// empty if it ran.
std::string refusal(const std::string& conninfo, const std::string& sql);

}  // namespace rockface::office_test
