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

// Two sets designed along Main drive (issue 46: "new and turning sets
// flagged"), each measured as six planes within 2 deg of its mean
// (tablet_projects.h's DesignedSet) where the tablets see it:
// - the steady set, at every placed visit (tablet A's at ch 102, tablet B's
//   at kTabletBChainage and 2.5 m on): flagged nothing;
// - the turning set, first seen at kTabletBChainage (new there) dipping
//   kTurnsFrom; at tablet B's next visit, 2.5 m on, kTurnsTo: its dip 12
//   deg steeper, the same dip direction. 12 deg is far beyond the
//   confidence cones of six planes this close (a few degrees), and within
//   the 20 deg that keeps a set one track (core/tunnel/drive_sets.h).
struct DipAndDirection {
  double dip_deg = 0, dipdir_deg = 0;
};
inline constexpr DipAndDirection kSteadySet{80, 30};
inline constexpr DipAndDirection kTurnsFrom{35, 340}, kTurnsTo{47, 340};
// Tablet B's first visit's chainage (m); its second is 2.5 m on.
inline constexpr double kTabletBChainage = 107;

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
