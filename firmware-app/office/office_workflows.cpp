#include "firmware-app/office/office_workflows.h"

#include <unistd.h>

#include <cstdlib>
#include <system_error>

#include "firmware-app/tunnel/project_drive.h"
#include "storage/field_report/field_report.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/office/server_drive.h"
#include "storage/office/server_schema.h"
#include "storage/project/project_store.h"

namespace rockface::app {

namespace office = storage::office;

bool is_server_address(const std::string& text) {
  return text.rfind("postgresql://", 0) == 0 || text.rfind("postgres://", 0) == 0 ||
         text.find('=') != std::string::npos;
}

std::string tablet_server() {
  const char* name = std::getenv("ROCKFACE_SERVICE");
  return std::string("service=") + (name && *name ? name : "rockface");
}

std::vector<std::string> sync_lines(const office::SyncResult& r) {
  std::vector<std::string> lines;
  lines.push_back("server " + r.server_label + ", tunnel " + r.tunnel);
  if (r.units_total == 0) {
    lines.push_back("nothing to send: the server holds everything of this project");
    return lines;
  }
  lines.push_back(std::to_string(r.units_sent) + " of " + std::to_string(r.units_total) +
                  " units sent (the project's records and one per visit), " +
                  std::to_string(r.records_sent) + " new record revisions");
  lines.push_back(std::to_string(r.blobs_sent) + " photographs and meshes sent (" +
                  storage::report_number(static_cast<double>(r.blob_bytes_sent) / 1e6, 2) +
                  " MB), " + std::to_string(r.blobs_already_there) + " already on the server");
  return lines;
}

std::vector<std::string> run_sync(const std::filesystem::path& project, const std::string& server,
                                  const office::SyncOptions& options, Progress& progress) {
  return sync_lines(office::sync_project(project, server, options, progress));
}

std::vector<std::string> run_pull(const std::string& server, const std::string& tunnel,
                                  const std::filesystem::path& out, Progress& progress) {
  const office::PullResult r = office::pull_tunnel(server, tunnel, out, progress);
  std::vector<std::string> lines{
      "server " + r.server_label + ", tunnel " + tunnel,
      std::to_string(r.projects) + " tablet projects, " + std::to_string(r.visits) + " visits, " +
          std::to_string(r.records) + " records, " + std::to_string(r.blobs) +
          " photographs and meshes (" +
          storage::report_number(static_cast<double>(r.blob_bytes) / 1e6, 2) +
          " MB, each checked against its SHA-256)",
      "project: " + out.string()};
  for (const std::string& w : r.warnings) lines.push_back("warning: " + w);
  return lines;
}

std::vector<std::string> run_server_init(const std::string& server) {
  office::Connection c(server);
  const office::InitResult r = office::init_server(c);
  if (r.from_version == r.to_version)
    return {c.label() + ": the rockface schema is current (version " +
            std::to_string(r.to_version) + ")"};
  return {c.label() + ": rockface schema " +
              (r.from_version == 0 ? std::string("created")
                                   : "upgraded from version " + std::to_string(r.from_version)) +
              " at version " + std::to_string(r.to_version),
          "roles rockface_tablet, rockface_office, rockface_admin and their row-level security "
          "policies in place"};
}

std::vector<std::string> run_server_add_tunnel(const std::string& server, const std::string& name) {
  office::Connection c(server);
  office::require_compatible_server(c);
  office::add_tunnel(c, name);
  return {c.label() + ": tunnel " + name};
}

std::vector<std::string> run_server_add_tablet(const std::string& server, const std::string& role,
                                               const std::string& tunnel) {
  office::Connection c(server);
  office::require_compatible_server(c);
  office::add_tablet(c, role, tunnel);
  return {c.label() + ": tablet role " + role + " may add visits to tunnel " + tunnel +
          " (give it a password with psql's \\password, or a client certificate)"};
}

std::vector<std::string> run_server_add_office(const std::string& server, const std::string& role,
                                               const std::string& tunnel) {
  office::Connection c(server);
  office::require_compatible_server(c);
  office::add_office_user(c, role, tunnel);
  return {c.label() + ": office role " + role +
          (tunnel.empty() ? " reads every tunnel" : " reads tunnel " + tunnel + " only")};
}

std::vector<std::string> run_server_add_admin(const std::string& server, const std::string& role) {
  office::Connection c(server);
  office::require_compatible_server(c);
  office::add_admin(c, role);
  return {c.label() + ": admin role " + role +
          " creates tunnels, tablets and office users (give it a password with psql's "
          "\\password, or a client certificate)"};
}

std::vector<std::string> run_server_add_web(const std::string& server, const std::string& role) {
  office::Connection c(server);
  office::require_compatible_server(c);
  office::add_web_service(c, role);
  return {c.label() + ": role " + role +
          " is the office web server's (`rockface office serve` connects as it and acts as each "
          "office user; give it a password with psql's \\password and the web server a passfile)"};
}

tunnel::DriveSets server_drive(const std::string& server, const std::string& name) {
  office::Connection c(server);
  return server_drive(c, name);
}

tunnel::DriveSets server_drive(office::Connection& c, const std::string& name) {
  office::require_compatible_server(c);
  return server_drive(office::read_server_drive(c, name));
}

tunnel::DriveSets server_drive(const office::ServerDrive& d) {
  std::vector<tunnel::VisitSets> visits;
  for (const auto& v : d.visits)
    visits.push_back({v.visit_id, v.chainage, set_observations(v.sets, v.measurements)});
  tunnel::DriveSetOptions options;
  options.drive = d.drive;
  return tunnel::track_sets_along_drive(std::move(visits), options);
}

office::ServerDrive server_drive_records(const std::string& server, const std::string& name) {
  office::Connection c(server);
  office::require_compatible_server(c);
  return office::read_server_drive(c, name);
}

DriveGeologists server_drive_geologists(const office::ServerDrive& d) {
  DriveGeologists out;
  for (const auto& v : d.visits)
    if (v.geologist) out[v.visit_id] = *v.geologist;
  return out;
}

std::vector<RoundSupport> server_drive_support(const std::string& server, const std::string& name,
                                               Progress& progress) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("rockface-drive-support-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  // Removed however the reading ends.
  struct Remove {
    std::filesystem::path dir;
    ~Remove() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  } remove{folder};
  const std::filesystem::path file = folder / "pulled.rockface";
  office::pull_tunnel(server, name, file, progress);
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(file, read);
  return drive_support(store);
}

}  // namespace rockface::app
