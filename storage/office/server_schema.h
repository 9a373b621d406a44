#pragma once
// The office server's layout (PostgreSQL schema "rockface") and its history,
// like the project file's (storage/project/project_schema.h): each change is a
// numbered forward step kept forever, run by `rockface server init`, which
// creates the layout, the three group roles and the row-level-security
// policies in one transaction, or upgrades an older server.
//
// Roles (group roles, NOLOGIN; a person or tablet logs in as a member):
//   rockface_tablet  adds visits and records to the tunnels it is a member
//                    of (tunnel_member) and reads those tunnels; it never
//                    updates or deletes a row (a change is a new revision),
//                    and may not add a revision to another tablet's record.
//   rockface_office  reads every tunnel.
//   rockface_admin   creates tunnels, tablet and office roles, and grants.
//
// Versions:
//   1  tunnels and their members, projects, visits, records (one row per
//      revision of a record, body as JSON), blobs stored once by SHA-256 in
//      chunks, sync runs; the policies above.
//   2  blobs readable only through a readable record (blob_ref); office
//      roles of one tunnel.
//   3  each round's over- and underbreak kept (round_figures), written only
//      by the office web server's group.
#include <string>

#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

constexpr int kServerSchemaVersion = 3;

// The server's schema version, 0 when it has no rockface layout.
int server_schema_version(Connection& c);

// The server's identity (a UUID made at init): a project remembers what it
// synced to which server by it.
std::string server_id(Connection& c);

// Throws Error naming the server and both versions when the server's schema
// is newer than this program (an older client is refused: it would write
// records the newer layout does not expect), or older (an administrator
// runs `rockface server init` to upgrade it), or missing.
void require_compatible_server(Connection& c);

struct InitResult {
  int from_version = 0, to_version = 0;
};
// Creates or upgrades the layout, roles and policies; run by a superuser
// or the database's owner with CREATEROLE. Idempotent.
InitResult init_server(Connection& c);

// Admin: a tunnel (a site's drive) that tablets add visits to.
void add_tunnel(Connection& c, const std::string& name);
// Admin: a login role for one tablet (member of rockface_tablet) that may
// add visits to `tunnel`; an existing role is only granted the tunnel. No
// password is set here: the administrator gives one with psql's \password
// or authenticates the tablet by certificate.
void add_tablet(Connection& c, const std::string& role, const std::string& tunnel);
// Admin: a login role of the office. Without a tunnel it reads every
// tunnel (member of rockface_office); with one it reads that tunnel only
// (member of rockface_tunnel_office and of the tunnel, schema version 2).
// Neither writes.
void add_office_user(Connection& c, const std::string& role, const std::string& tunnel = "");
// Admin: the login role `rockface office serve` connects as (its pooled
// connections, storage/office/connection_pool.h): NOINHERIT, a member of
// rockface_web, so it may act as each office user and as nothing else.
// Its password is set by the admin (ALTER ROLE ... PASSWORD) and given to
// the web server in a passfile.
void add_web_service(Connection& c, const std::string& role);
// Superuser (or an admin): a login role that administers the site (member
// of rockface_admin, with CREATEROLE so that it can add tablets and office
// users itself: role attributes are not inherited through membership). An
// existing role is made an admin.
void add_admin(Connection& c, const std::string& role);

}  // namespace rockface::storage::office
