#pragma once
// The office server's workflows behind the verbs `sync`, `pull`, `server`
// and `drive postgresql://...`, and the tablet's Sync button: each takes a
// libpq connection string (a postgresql:// URL, key=value text or
// service=NAME) and returns the lines to print; no password is ever part of
// what they return (storage/office/pg_connection.h masks it).
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "core/tunnel/drive_sets.h"
#include "firmware-app/support/support_drive.h"
#include "firmware-app/tunnel/project_drive.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_drive.h"
#include "storage/office/sync_push.h"

namespace rockface::app {

// Whether a command-line argument names a server rather than a project
// file: a postgresql:// or postgres:// URL, or libpq key=value text.
bool is_server_address(const std::string& text);

// The tablet's server: the libpq service named by ROCKFACE_SERVICE, else
// "rockface", looked up in ~/.pg_service.conf or PGSYSCONFDIR: set once per
// tablet by whoever sets the tablet up, never typed per visit.
std::string tablet_server();

std::vector<std::string> sync_lines(const storage::office::SyncResult& r);
std::vector<std::string> run_sync(const std::filesystem::path& project, const std::string& server,
                                  const storage::office::SyncOptions& options, Progress& progress);

std::vector<std::string> run_pull(const std::string& server, const std::string& tunnel,
                                  const std::filesystem::path& out, Progress& progress);

std::vector<std::string> run_server_init(const std::string& server);
std::vector<std::string> run_server_add_tunnel(const std::string& server, const std::string& name);
std::vector<std::string> run_server_add_tablet(const std::string& server, const std::string& role,
                                               const std::string& tunnel);
// `tunnel` empty: the role reads every tunnel; else that tunnel only.
std::vector<std::string> run_server_add_office(const std::string& server, const std::string& role,
                                               const std::string& tunnel = "");
std::vector<std::string> run_server_add_admin(const std::string& server, const std::string& role);
// The role `rockface office serve` connects as (storage/office/
// server_schema.h's add_web_service).
std::vector<std::string> run_server_add_web(const std::string& server, const std::string& role);

// The drive of every tablet's visits of the tunnel, from the server: the
// same sets, tracks and events as `rockface drive` of one project holding
// those visits (firmware-app/tunnel/project_drive.h).
tunnel::DriveSets server_drive(const std::string& server, const std::string& tunnel);
// The same over an open connection (the office's web session).
tunnel::DriveSets server_drive(storage::office::Connection& c, const std::string& tunnel);
// The same from the drive's rows already read (storage/office/
// server_drive.h's read_server_drive): no server needed.
tunnel::DriveSets server_drive(const storage::office::ServerDrive& d);
// The drive's rows as the server holds them (read_server_drive after the
// server's schema is checked): its sets and who mapped each visit, from one
// snapshot.
storage::office::ServerDrive server_drive_records(const std::string& server,
                                                  const std::string& tunnel);
// Who mapped each of the drive's visits, by the drive's visit ids.
DriveGeologists server_drive_geologists(const storage::office::ServerDrive& d);

// The support per round of every tablet's visits of the tunnel (`rockface
// drive postgresql://... --support-csv`): the tunnel pulled into a
// temporary project (removed after) and read as `rockface drive PROJECT
// --support-csv` reads a project (firmware-app/support/support_drive.h);
// RMR and Q need each visit's traces, which only a pull brings. Visits
// numbered as the pull numbers them.
std::vector<RoundSupport> server_drive_support(const std::string& server, const std::string& tunnel,
                                               Progress& progress);

}  // namespace rockface::app
