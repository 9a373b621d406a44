#pragma once
// The office web suite's site: one real PostgreSQL server (with TLS and
// passwords on 127.0.0.1, tests/storage/office/office_environment.h), a
// database where two tablets synced their projects of tunnel "Main drive"
// (tablet A with a mapped face: joints, sets, blocks; tablet B two more
// visits further on), a second tunnel "North adit" with an office role of
// its own and tablet C's visit, an office role of "Main drive" only, and a real `rockface office
// serve` process on a loopback port.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace rockface::office_web_test {

// Passwords the site's roles log in with (PostgreSQL checks them: scram).
inline constexpr const char* kOfficePassword = "office pass 1";
inline constexpr const char* kTabletPassword = "tablet pass 2";
inline constexpr const char* kAditPassword = "adit pass 3";
inline constexpr const char* kMainOfficePassword = "main pass 4";
// The office web server's service role (office_web), from its passfile.
inline constexpr const char* kWebServicePassword = "web pass 5";
// A note on one of tablet A's visits: a script that must stay text.
inline constexpr const char* kScriptNote =
    "<script>window.rockfaceInjected=1</script><img src=x onerror=\"window.rockfaceInjected=2\">";

// The range pole's targets on tablet A's 3D images (project frame, m):
// 2 m apart, on the sample face (y about 4).
inline constexpr const char* kPoleTargets = "[[0.1, 4.0, 0.2], [0.1, 4.0, 2.2]]";

struct Site {
  std::string database;
  // libpq key=value text naming the web server's service role and its
  // passfile: what `office serve` takes.
  std::string server;
  std::filesystem::path folder;
};

// Built once per test binary (the first call syncs the tablets).
const Site& site();
// Another such site, in a database of its own: for a test that syncs more.
Site fresh_site();
// A site whose database holds one project's visits, synced by tablet_a
// (a tablet of `tunnel`), and the office_reader role with kOfficePassword.
Site site_of_project(const std::filesystem::path& project, const std::string& tunnel);

// A running `rockface office serve` on 127.0.0.1 (any free port); stopped
// (SIGTERM) when destroyed.
class OfficeServer {
 public:
  explicit OfficeServer(double session_minutes = 30);
  OfficeServer(const Site& s, double session_minutes);
  // With more arguments for `office serve` (e.g. {"--tls", "CERT,KEY"}),
  // listening on `listen` (ADDR:PORT; port 0 any free one).
  OfficeServer(const Site& s, double session_minutes, const std::vector<std::string>& more,
               const std::string& listen = "127.0.0.1:0");
  ~OfficeServer();
  OfficeServer(const OfficeServer&) = delete;
  OfficeServer& operator=(const OfficeServer&) = delete;
  int port() const { return port_; }
  // The server's own work folder (`--work` + rockface-office-PID): its
  // pulled copies are in shared/.
  std::filesystem::path work_folder() const { return work_folder_; }
  std::string origin() const { return "http://127.0.0.1:" + std::to_string(port_); }

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  std::filesystem::path work_folder_;
};

}  // namespace rockface::office_web_test
