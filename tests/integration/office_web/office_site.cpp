#include "tests/integration/office_web/office_site.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/progress.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_schema.h"
#include "storage/office/sync_push.h"
#include "storage/project/project_sqlite.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace rockface::office_web_test {

namespace fs = std::filesystem;
using namespace office_test;

namespace {

// A fresh database with tunnel `tunnel` (office_environment.h's roles)
// and the site's folder.
Site empty_site(const std::string& tunnel) {
  Site s;
  s.database = fresh_database(tunnel);
  s.folder = fs::temp_directory_path() /
             ("rockface-office-web-" + std::to_string(::getpid()) + "-" + s.database);
  fs::create_directories(s.folder);
  // The sites' folders (tablets' projects, the servers' logs) go when the
  // process's tests all passed, and stay to be read when one failed.
  struct RemovedIfPassed {
    std::vector<fs::path> folders;
    ~RemovedIfPassed() {
      if (!::testing::UnitTest::GetInstance()->Passed()) return;
      for (const auto& f : folders) {
        std::error_code ignored;
        fs::remove_all(f, ignored);
      }
    }
  };
  static RemovedIfPassed made;
  made.folders.push_back(s.folder);
  // The office server's own role, which its pooled connections log in as
  // (its password from a passfile, as a site's service has it).
  {
    storage::office::Connection c(as_superuser(s.database));
    storage::office::add_web_service(c, "office_web");
  }
  server().psql(std::string("ALTER ROLE office_web PASSWORD '") + kWebServicePassword + "'",
                s.database);
  const fs::path passfile = s.folder / "office-web.pgpass";
  {
    std::ofstream out(passfile);
    out << "127.0.0.1:" << server().port() << ":" << s.database
        << ":office_web:" << kWebServicePassword << "\n";
  }
  fs::permissions(passfile, fs::perms::owner_read | fs::perms::owner_write,
                  fs::perm_options::replace);
  // Over TCP with TLS (the socket trusts every role): passwords are checked.
  s.server = "host=127.0.0.1 port=" + std::to_string(server().port()) + " dbname=" + s.database +
             " sslmode=verify-full sslrootcert=" + server().ca_certificate().string() +
             " user=office_web passfile=" + passfile.string();
  return s;
}

Site make_site() {
  Site s = empty_site("Main drive");
  {
    storage::office::Connection c(as_superuser(s.database));
    storage::office::add_tunnel(c, "North adit");
    storage::office::add_office_user(c, "adit_office", "North adit");
    storage::office::add_office_user(c, "main_office", "Main drive");
    storage::office::add_tablet(c, "tablet_c", "North adit");
  }
  server().psql(std::string("ALTER ROLE office_reader PASSWORD '") + kOfficePassword +
                    "'; ALTER ROLE tablet_a PASSWORD '" + kTabletPassword +
                    "'; ALTER ROLE adit_office PASSWORD '" + kAditPassword +
                    "'; ALTER ROLE main_office PASSWORD '" + kMainOfficePassword + "'",
                s.database);

  const std::array<double, 2> steady{kSteadySet.dip_deg, kSteadySet.dipdir_deg};
  TabletProject a;
  a.name = "tablet A";
  a.visits = 1;
  a.dense_face_visit = true;  // joints, sets and blocks to show
  a.designed_sets = {{"S3", {steady}}};
  TabletProject b;
  b.name = "tablet B";
  b.seed = 2;
  b.first_chainage = kTabletBChainage;
  b.designed_sets = {{"S3", {steady, steady}},
                     {"S4",
                      {std::array<double, 2>{kTurnsFrom.dip_deg, kTurnsFrom.dipdir_deg},
                       std::array<double, 2>{kTurnsTo.dip_deg, kTurnsTo.dipdir_deg}}}};
  // Tablet C maps the other tunnel: what its office role, and only it
  // (besides rockface_office), may read.
  TabletProject c;
  c.name = "tablet C";
  c.seed = 3;
  c.visits = 1;
  c.tunnel = "North adit";
  make_tablet_project(s.folder / "a.rockface", a);
  make_tablet_project(s.folder / "b.rockface", b);
  make_tablet_project(s.folder / "adit-c.rockface", c);
  {
    // Tablet B's first visit was taken at the tunnel's south portal, named
    // with the command line as a geologist names it (issue 46); its
    // second names no heading.
    const test::CliRun named = test::run_rockface("place " + (s.folder / "b.rockface").string() +
                                                  " --visit 1 --heading 'South portal'");
    if (named.exit_code != 0)
      throw std::runtime_error("naming tablet B's heading: " + named.out + named.err);
  }
  // The geologist who mapped each visit (issue 46), named with the command
  // line: tablet A's visits by a name the pages must show as text, tablet
  // B's first by another; B's second names none ("not recorded").
  const std::vector<std::tuple<std::string, int, std::string>> geologists = {
      {"a.rockface", 1, "\"O'Brien <b>\""},  // shell-quoted
      {"a.rockface", 2, "\"O'Brien <b>\""},
      {"b.rockface", 1, "'Anna Berger'"}};
  for (const auto& [file, visit, name] : geologists) {
    const test::CliRun named =
        test::run_rockface("place " + (s.folder / file).string() + " --visit " +
                           std::to_string(visit) + " --geologist " + name);
    if (named.exit_code != 0)
      throw std::runtime_error("naming a visit's geologist: " + named.out + named.err);
  }
  {
    storage::sqlite::Connection db(s.folder / "a.rockface",
                                   storage::sqlite::Connection::Access::read_write);
    std::string note = kScriptNote;
    std::string quoted;
    for (char ch : note) quoted += ch == '\'' ? std::string("''") : std::string(1, ch);
    db.exec("UPDATE visit SET note = '" + quoted + "' WHERE id = (SELECT min(id) FROM visit)",
            "writing the test's note");
    // Tablet A's 3D images were scaled by a range pole whose two targets
    // the reconstruction recorded (kPoleTargets, project frame).
    db.exec(std::string("UPDATE model SET registration_parameters = json_set(CASE WHEN "
                        "json_valid(registration_parameters) THEN registration_parameters ELSE "
                        "'{}' END, '$.registration', json('{\"scale_source\": \"range pole\", "
                        "\"range_pole\": {\"length_m\": 2.0}}'), '$.targets', json('") +
                kPoleTargets + "'))",
            "writing the range pole's targets");
  }
  NoProgress none;
  storage::office::sync_project(s.folder / "a.rockface", as_role(s.database, "tablet_a"), {}, none);
  storage::office::sync_project(s.folder / "b.rockface", as_role(s.database, "tablet_b"), {}, none);
  storage::office::sync_project(s.folder / "adit-c.rockface", as_role(s.database, "tablet_c"), {},
                                none);
  return s;
}

}  // namespace

const Site& site() {
  static const Site s = make_site();
  return s;
}

Site fresh_site() {
  return make_site();
}

Site site_of_project(const fs::path& project, const std::string& tunnel) {
  Site s = empty_site(tunnel);
  server().psql(std::string("ALTER ROLE office_reader PASSWORD '") + kOfficePassword + "'",
                s.database);
  NoProgress none;
  storage::office::sync_project(project, as_role(s.database, "tablet_a"), {}, none);
  return s;
}

OfficeServer::OfficeServer(double session_minutes) : OfficeServer(site(), session_minutes) {}

OfficeServer::OfficeServer(const Site& s, double session_minutes)
    : OfficeServer(s, session_minutes, {}) {}

OfficeServer::OfficeServer(const Site& s, double session_minutes,
                           const std::vector<std::string>& more, const std::string& listen) {
  static int count = 0;
  const fs::path log = s.folder / ("office-serve-" + std::to_string(++count) + ".out");
  const std::string binary = std::string(ROCKFACE_BINARY_DIR) + "/rockface";
  const std::string minutes = std::to_string(session_minutes);
  const std::string work = s.folder.string();
  pid_ = ::fork();
  if (pid_ == 0) {
    if (!std::freopen(log.c_str(), "w", stdout)) ::_exit(126);
    // What the server tells systemd's journal (stderr) in the same log.
    ::dup2(::fileno(stdout), 2);
    std::vector<std::string> args = {
        binary,  "office", "serve", s.server, "--listen", listen, "--session-minutes",
        minutes, "--work", work};
    args.insert(args.end(), more.begin(), more.end());
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  // "office: serving http://ADDR:PORT/ ..." once it listens: within a
  // second (issue 46); 20 s before this says it did not start at all.
  for (int i = 0; i < 200 && port_ == 0; ++i) {
    std::ifstream in(log);
    std::string text;
    std::getline(in, text);
    const std::size_t at = text.find("://");
    const std::size_t slash = at == std::string::npos ? at : text.find('/', at + 3);
    const std::size_t colon = slash == std::string::npos ? slash : text.rfind(':', slash);
    if (colon != std::string::npos && colon > at)
      port_ = std::stoi(text.substr(colon + 1, slash - colon - 1));
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (port_ == 0)
    throw std::runtime_error("rockface office serve did not start: see " + log.string());
  work_folder_ = s.folder / ("rockface-office-" + std::to_string(pid_));
}

OfficeServer::~OfficeServer() {
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
}

}  // namespace rockface::office_web_test
