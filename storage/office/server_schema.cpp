#include "storage/office/server_schema.h"

#include <regex>

#include "core/common/error.h"
#include "storage/office/server_schema_sql.h"

namespace rockface::storage::office {

namespace {

struct Step {
  int to_version;
  const char* sql;
};
constexpr Step kSteps[] = {{1, sql::kVersion1}, {2, sql::kVersion2}, {3, sql::kVersion3}};

// A role name as rockface creates them: plain lower-case words, so that it
// needs no quoting in pg_hba.conf or a service file either.
void require_role_name(const std::string& role) {
  static const std::regex kName("[a-z_][a-z0-9_]{0,62}");
  if (!std::regex_match(role, kName))
    throw InputError("role " + role,
                     "a role name is lower-case letters, digits and '_' (at most 63), starting "
                     "with a letter or '_'");
}

std::int64_t tunnel_id(Connection& c, const std::string& name) {
  const Result r = c.query("SELECT id FROM rockface.tunnel WHERE name = $1", {Param::of(name)},
                           "finding a tunnel");
  if (r.rows() == 0) throw InputError("tunnel " + name, "no such tunnel on " + c.label());
  return r.int64(0, 0);
}

}  // namespace

int server_schema_version(Connection& c) {
  const Result has = c.query("SELECT to_regclass('rockface.meta') IS NOT NULL", {},
                             "reading the server's schema version");
  if (has.text(0, 0) != "t") return 0;
  const Result r = c.query("SELECT value FROM rockface.meta WHERE key = 'schema_version'", {},
                           "reading the server's schema version");
  return r.rows() == 0 ? 0 : static_cast<int>(r.int64(0, 0));
}

std::string server_id(Connection& c) {
  const Result r = c.query("SELECT value FROM rockface.meta WHERE key = 'server_id'", {},
                           "reading the server's identity");
  if (r.rows() == 0) throw Error(c.label() + ": the server has no rockface identity");
  return r.text(0, 0);
}

void require_compatible_server(Connection& c) {
  const int v = server_schema_version(c);
  if (v == 0)
    throw Error(c.label() +
                ": no rockface database here: an administrator creates it with `rockface server "
                "init`");
  if (v > kServerSchemaVersion)
    throw Error(c.label() + ": the server's rockface schema is version " + std::to_string(v) +
                ", newer than this rockface knows (up to " + std::to_string(kServerSchemaVersion) +
                "): this client is too old for the server; update rockface on this machine");
  if (v < kServerSchemaVersion)
    throw Error(c.label() + ": the server's rockface schema is version " + std::to_string(v) +
                ", older than this rockface's " + std::to_string(kServerSchemaVersion) +
                ": an administrator upgrades it with `rockface server init`");
}

InitResult init_server(Connection& c) {
  InitResult result;
  // Roles belong to the cluster, not the database: created outside the
  // layout's transaction so that a second database on the cluster finds them.
  c.exec(sql::kRoles, "creating the rockface roles");
  c.exec(sql::kRolesVersion2, "creating the rockface roles");
  c.exec(sql::kRolesWeb, "creating the rockface roles");
  Transaction tx(c, "creating the rockface layout");
  // One initialiser at a time: a second waits here, then finds the layout.
  c.exec("SELECT pg_advisory_xact_lock(7526351)", "creating the rockface layout");
  result.from_version = server_schema_version(c);
  if (result.from_version > kServerSchemaVersion)
    throw Error(c.label() + ": the server's rockface schema is version " +
                std::to_string(result.from_version) + ", newer than this rockface knows (up to " +
                std::to_string(kServerSchemaVersion) + ")");
  for (const Step& step : kSteps) {
    if (step.to_version <= result.from_version) continue;
    c.exec(step.sql, "upgrading the server's layout to version " + std::to_string(step.to_version));
  }
  c.query(
      "INSERT INTO rockface.meta (key, value) VALUES ('schema_version', $1) "
      "ON CONFLICT (key) DO UPDATE SET value = EXCLUDED.value",
      {Param::of(std::to_string(kServerSchemaVersion))}, "marking the server's schema version");
  tx.commit();
  result.to_version = kServerSchemaVersion;
  return result;
}

void add_tunnel(Connection& c, const std::string& name) {
  if (name.empty()) throw InputError("tunnel", "a tunnel needs a name");
  c.query("INSERT INTO rockface.tunnel (name) VALUES ($1) ON CONFLICT (name) DO NOTHING",
          {Param::of(name)}, "adding tunnel " + name);
}

void add_tablet(Connection& c, const std::string& role, const std::string& tunnel) {
  require_role_name(role);
  Transaction tx(c, "adding tablet " + role);
  const std::int64_t id = tunnel_id(c, tunnel);
  const Result exists =
      c.query("SELECT 1 FROM pg_roles WHERE rolname = $1", {Param::of(role)}, "adding a tablet");
  if (exists.rows() == 0) c.exec("CREATE ROLE " + role + " LOGIN", "adding tablet " + role);
  c.exec("GRANT rockface_tablet TO " + role, "adding tablet " + role);
  c.query(
      "INSERT INTO rockface.tunnel_member (tunnel_id, role_name) VALUES ($1, $2) "
      "ON CONFLICT DO NOTHING",
      {Param::of(id), Param::of(role)}, "adding tablet " + role + " to tunnel " + tunnel);
  tx.commit();
}

void add_office_user(Connection& c, const std::string& role, const std::string& tunnel) {
  require_role_name(role);
  // The web server's group, on a server set up before it (cluster roles:
  // `server init` of this version may not have run on it yet).
  c.exec(sql::kRolesWeb, "creating the rockface roles");
  Transaction tx(c, "adding office user " + role);
  const bool one_tunnel = !tunnel.empty();
  const std::int64_t id = one_tunnel ? tunnel_id(c, tunnel) : 0;
  const Result exists = c.query("SELECT 1 FROM pg_roles WHERE rolname = $1", {Param::of(role)},
                                "adding an office user");
  if (exists.rows() == 0) c.exec("CREATE ROLE " + role + " LOGIN", "adding office user " + role);
  if (!one_tunnel) {
    c.exec("GRANT rockface_office TO " + role, "adding office user " + role);
  } else {
    c.exec("GRANT rockface_tunnel_office TO " + role, "adding office user " + role);
    c.query(
        "INSERT INTO rockface.tunnel_member (tunnel_id, role_name) VALUES ($1, $2) "
        "ON CONFLICT DO NOTHING",
        {Param::of(id), Param::of(role)}, "adding office user " + role + " to tunnel " + tunnel);
  }
  // The office web server may act as this user (kRolesWeb).
  c.exec("GRANT " + role + " TO rockface_web", "adding office user " + role);
  tx.commit();
}

void add_web_service(Connection& c, const std::string& role) {
  require_role_name(role);
  c.exec(sql::kRolesWeb, "creating the rockface roles");
  Transaction tx(c, "adding the office web server's role " + role);
  const Result exists = c.query("SELECT 1 FROM pg_roles WHERE rolname = $1", {Param::of(role)},
                                "adding the office web server's role");
  // NOINHERIT: alone it reads nothing; each request acts as one person.
  if (exists.rows() == 0)
    c.exec("CREATE ROLE " + role + " LOGIN NOINHERIT", "adding the office web server's role");
  else
    c.exec("ALTER ROLE " + role + " NOINHERIT", "adding the office web server's role");
  c.exec("GRANT rockface_web TO " + role, "adding the office web server's role");
  tx.commit();
}

void add_admin(Connection& c, const std::string& role) {
  require_role_name(role);
  Transaction tx(c, "adding admin " + role);
  const Result exists =
      c.query("SELECT 1 FROM pg_roles WHERE rolname = $1", {Param::of(role)}, "adding an admin");
  if (exists.rows() == 0)
    c.exec("CREATE ROLE " + role + " LOGIN CREATEROLE", "adding admin " + role);
  else
    c.exec("ALTER ROLE " + role + " CREATEROLE", "adding admin " + role);
  c.exec("GRANT rockface_admin TO " + role, "adding admin " + role);
  tx.commit();
}

}  // namespace rockface::storage::office
