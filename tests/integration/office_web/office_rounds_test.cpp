// The rounds along the drive (issue 46): listed from a pulled copy of the
// tunnel's figures, never from its photographs — a drive of 3,000 visits
// pulled every photograph (minutes) to show a table of figures.
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "core/common/progress.h"
#include "firmware-app/office/office_rounds.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/office/sync_push.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "tests/integration/office_web/office_site.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/two_headings.h"

// Last: <resolv.h>, which httplib.h includes, defines the macro _res that
// Eigen uses as a parameter name.
#include "tests/integration/office_web/office_client.h"

namespace rockface::office_web_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Images {
  int rows = 0;
  std::int64_t bytes = 0, byte_size = 0;
};

Images images_of(const fs::path& project) {
  storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(
      db,
      "SELECT count(*), coalesce(sum(length(bytes)), 0), coalesce(sum(byte_size), 0) FROM image",
      "counting the photographs");
  st.step();
  return {static_cast<int>(st.column_int(0)), st.column_int(1), st.column_int(2)};
}

// The rounds page of a pulled copy, its visits unnamed.
std::string rounds_of(const fs::path& project) {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(project, read);
  return app::office_web::rounds_page(store, [](storage::RecordId) { return std::string(); })
      .dump();
}

// The truth of a drive's rounds: those of a pull of the whole tunnel,
// measured here by the pulled copy's own code.
json rounds_of_a_whole_pull(const Site& s, const std::string& name) {
  storage::office::Connection reader(s.server, "office_reader", kOfficePassword, 10);
  NoProgress none;
  const fs::path pulled = s.folder / (name + "-" + std::to_string(::getpid()) + ".rockface");
  fs::remove(pulled);
  storage::office::pull_tunnel(reader, "Main drive", pulled, none);
  const json truth = json::parse(rounds_of(pulled));
  fs::remove(pulled);
  return truth;
}

// A pull without photographs reads no photograph from the server (the
// pull's own count of the blobs it fetched) and gives the same rounds.
TEST(OfficeRounds, ACopyWithoutPhotographsGivesTheSameRounds) {
  const Site& s = site();
  storage::office::Connection c(s.server, "office_reader", kOfficePassword, 10);
  NoProgress none;
  const fs::path full = s.folder / "rounds-full.rockface";
  const fs::path figures = s.folder / "rounds-figures.rockface";
  fs::remove(full);
  fs::remove(figures);
  const storage::office::PullResult with =
      storage::office::pull_tunnel(c, "Main drive", full, none);
  storage::office::PullOptions options;
  options.photographs = false;
  const storage::office::PullResult without =
      storage::office::pull_tunnel(c, "Main drive", figures, none, options);
  const Images all = images_of(full), none_read = images_of(figures);
  ASSERT_GT(all.rows, 0);
  EXPECT_EQ(all.bytes, all.byte_size);
  // Every image row is there (captures refer to them), empty.
  EXPECT_EQ(none_read.rows, all.rows);
  EXPECT_EQ(none_read.bytes, 0);
  EXPECT_EQ(none_read.byte_size, all.byte_size) << "the photographs' sizes are kept";
  EXPECT_EQ(without.photographs_left, all.rows);
  // Only the meshes came: the photographs' bytes were never read.
  EXPECT_EQ(with.blob_bytes - without.blob_bytes, all.bytes);
  EXPECT_EQ(with.blobs - without.blobs, all.rows);
  EXPECT_EQ(rounds_of(figures), rounds_of(full));
}

std::vector<fs::path> pulled_copies(const OfficeServer& server) {
  std::vector<fs::path> copies;
  for (const auto& e : fs::directory_iterator(server.work_folder() / "shared"))
    if (e.path().extension() == ".rockface") copies.push_back(e.path());
  return copies;
}

std::int64_t count_of(const fs::path& project, const std::string& sql) {
  storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(db, sql, "counting");
  st.step();
  return st.column_int(0);
}

struct Rounds {
  int status = 0, measured = -1, measuring = -1;
  std::string body;
};

Rounds rounds_request(httplib::Client& c, const std::string& cookie,
                      const std::string& tunnel = "Main drive") {
  const auto r = c.Get("/api/drive/rounds?tunnel=" + httplib::detail::encode_query_param(tunnel),
                       {{"Cookie", cookie}});
  if (!r) return {};
  return {r->status, std::stoi("0" + r->get_header_value("X-Rockface-Rounds-Measured")),
          std::stoi("0" + r->get_header_value("X-Rockface-Rounds-Measuring")), r->body};
}

// The rounds once every round is in: asked again, as the page polls,
// until none is being measured (bounded: the site's few rounds take
// seconds; 300 s is the suite's margin on a loaded machine).
Rounds rounds_from(const OfficeServer& server, const std::string& tunnel = "Main drive") {
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(300));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  if (office.status != 200) return {office.status, -1, -1, office.error};
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while (true) {
    const Rounds r = rounds_request(c, office.cookie, tunnel);
    if (r.status != 200 || r.measuring == 0 || std::chrono::steady_clock::now() > until) return r;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
}

// The office's rounds route pulls copies without photographs: once the
// rounds are all in (they are measured in the background), none of the
// server's pulled copies holds one.
TEST(OfficeRounds, TheDrivesRoundsReadNoPhotograph) {
  OfficeServer server;
  const Rounds r = rounds_from(server);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.measuring, 0) << r.body;
  EXPECT_FALSE(json::parse(r.body)["rounds"].empty());
  const std::vector<fs::path> copies = pulled_copies(server);
  ASSERT_FALSE(copies.empty());
  for (const fs::path& copy : copies) {
    const Images images = images_of(copy);
    EXPECT_GT(images.rows, 0);
    EXPECT_EQ(images.bytes, 0) << "a copy of the rounds holds photographs";
  }
}

// visit uuid -> when its figures were kept (the server's clock, text).
std::map<std::string, std::string> kept_at(const Site& s) {
  storage::office::Connection su(office_test::as_superuser(s.database));
  const storage::office::Result r = su.query(
      "SELECT visit_uuid::text, computed_at::text FROM rockface.round_figures", {}, "reading");
  std::map<std::string, std::string> out;
  for (int i = 0; i < r.rows(); ++i) out[r.text(i, 0)] = r.text(i, 1);
  return out;
}

// Issue 46: the first rounds request of a 3,000-visit drive measured 3,000
// meshes (753 s), and a restarted server measured them all again. Each
// round's over- and underbreak is now measured once and kept on the
// server: a second server measures none (the route's count of rounds
// measured, and the kept rows' times unchanged) and pulls no mesh; a
// round whose inputs no longer match what its figures were kept for is
// measured again, alone.
TEST(OfficeRounds, EachRoundsFiguresAreMeasuredOnceAndKept) {
  const Site s = fresh_site();
  Rounds first;
  {
    OfficeServer server(s, 30);
    first = rounds_from(server);
    ASSERT_EQ(first.status, 200) << first.body;
  }
  const json page = json::parse(first.body);
  const int rounds = static_cast<int>(page["rounds"].size());
  ASSERT_GT(rounds, 0);
  EXPECT_EQ(first.measured, rounds) << "a fresh database has no figures kept";
  // Every round says what its 3D image gave (the site's see the face only:
  // "unknown", never zero).
  for (const auto& r : page["rounds"]) EXPECT_TRUE(r.contains("excavation_text")) << r;
  const auto kept = kept_at(s);
  EXPECT_EQ(static_cast<int>(kept.size()), rounds);

  {
    OfficeServer server(s, 30);
    const Rounds again = rounds_from(server);
    ASSERT_EQ(again.status, 200) << again.body;
    EXPECT_EQ(again.measured, 0);
    EXPECT_EQ(again.body, first.body);
    // Only the copy without photographs or meshes was pulled.
    const std::vector<fs::path> copies = pulled_copies(server);
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_EQ(count_of(copies.front(), "SELECT count(*) FROM model_mesh_part"), 0);
    EXPECT_GT(count_of(copies.front(), "SELECT count(*) FROM model"), 0);
  }
  EXPECT_EQ(kept_at(s), kept) << "kept figures were written again";

  // One round's kept inputs no longer those of its records (as after a
  // re-sync of its visit): that round alone is measured again.
  const std::string stale = kept.begin()->first;
  office_test::server().psql(
      "UPDATE rockface.round_figures SET inputs = 'stale' WHERE visit_uuid = '" + stale + "'",
      s.database);
  {
    OfficeServer server(s, 30);
    const Rounds third = rounds_from(server);
    ASSERT_EQ(third.status, 200) << third.body;
    EXPECT_EQ(third.measured, 1);
    EXPECT_EQ(third.body, first.body);
    // Measured on a copy of that visit, used once and gone: no copy of the
    // whole drive's meshes was pulled for one round.
    const std::vector<fs::path> copies = pulled_copies(server);
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_EQ(count_of(copies.front(), "SELECT count(*) FROM model_mesh_part"), 0);
  }
  const auto after = kept_at(s);
  for (const auto& [visit, at] : kept)
    if (visit == stale)
      EXPECT_NE(after.at(visit), at) << "the stale round was not measured again";
    else
      EXPECT_EQ(after.at(visit), at) << visit;
}

// Issue 46: a fresh server on a drive without kept figures measured every
// round before answering (552 s at 3,000 visits). It answers at once —
// every round listed and marked "measuring", none of its figures waited
// for — and measures them in the background: asked again, the rounds fill
// in with the figures a copy of the drive gives (office_rounds.h's
// rounds_page, measured in the test on a pull of its own) and are kept.
TEST(OfficeRounds, AServerWithoutKeptFiguresAnswersAtOnceAndFillsTheRoundsIn) {
  const Site s = fresh_site();
  ASSERT_TRUE(kept_at(s).empty());
  OfficeServer server(s, 30);
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(300));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  const Rounds first = rounds_request(c, office.cookie);
  ASSERT_EQ(first.status, 200) << first.body;
  const json at_once = json::parse(first.body);
  ASSERT_FALSE(at_once["rounds"].empty());
  EXPECT_EQ(first.measuring, static_cast<int>(at_once["rounds"].size()));
  EXPECT_EQ(at_once["measuring"], at_once["rounds"].size());
  for (const auto& r : at_once["rounds"]) {
    EXPECT_EQ(r.value("measuring", false), true) << r;
    EXPECT_EQ(r["excavation_text"], "being measured…") << r;
    EXPECT_FALSE(r.contains("overbreak_m3")) << r;
  }

  const json truth = rounds_of_a_whole_pull(s, "rounds-truth");

  const Rounds in = rounds_from(server);
  ASSERT_EQ(in.status, 200) << in.body;
  EXPECT_EQ(in.measuring, 0) << in.body;
  const json filled = json::parse(in.body);
  EXPECT_EQ(filled["measuring"], 0);
  ASSERT_EQ(filled["rounds"].size(), truth["rounds"].size());
  for (std::size_t i = 0; i < truth["rounds"].size(); ++i) {
    const json& got = filled["rounds"][i];
    const json& want = truth["rounds"][i];
    EXPECT_FALSE(got.contains("measuring")) << got;
    for (const char* key :
         {"chainage_text", "rmr_text", "q_text", "proposed", "decided", "excavation_text"})
      EXPECT_EQ(got[key], want[key]) << key << " of round " << i;
  }
  EXPECT_EQ(static_cast<int>(kept_at(s).size()), static_cast<int>(truth["rounds"].size()))
      << "the figures measured in the background were not kept";
}

// Issue 46: after a tablet synced a new visit while `office serve` ran,
// every round read "reading…" until the drive's copy was pulled again.
// Now the server notices the sync (the records' revisions on the server)
// while it runs: the rounds already shown stay as they were, the new
// visit's round is "measuring", and the page's polling fills it in with
// the figures a pull of the drive gives (measured in the test on a pull of
// its own), the new round alone measured.
TEST(OfficeRounds, AVisitSyncedWhileServingFillsItsRoundInAndTheOthersStay) {
  const Site s = fresh_site();
  OfficeServer server(s, 30);
  const Rounds before = rounds_from(server);
  ASSERT_EQ(before.status, 200) << before.body;
  ASSERT_EQ(before.measuring, 0) << before.body;
  const json shown = json::parse(before.body);
  std::map<std::string, json> shown_by_visit;
  for (const auto& r : shown["rounds"]) shown_by_visit[r["visit"].get<std::string>()] = r;

  // Tablet B adds its third visit (2.5 m beyond its second) and syncs.
  office_test::TabletProject b;
  b.name = "tablet B";
  b.seed = 2;
  b.first_chainage = 107;
  office_test::add_tablet_visit(s.folder / "b.rockface", b, 2);
  NoProgress none;
  storage::office::sync_project(s.folder / "b.rockface",
                                office_test::as_role(s.database, "tablet_b"), {}, none);

  // Asked as the page polls until the new visit is listed (the server sees
  // a sync within a second; 60 s is the margin of a loaded machine): from
  // the first answer that lists it, every round shown before is as it was.
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(300));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  json after;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (true) {
    const Rounds r = rounds_request(c, office.cookie);
    ASSERT_EQ(r.status, 200) << r.body;
    after = json::parse(r.body);
    if (after["rounds"].size() > shown["rounds"].size() || std::chrono::steady_clock::now() > until)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_EQ(after["rounds"].size(), shown["rounds"].size() + 1) << after;
  std::string added;
  for (const auto& r : after["rounds"]) {
    const auto was = shown_by_visit.find(r["visit"].get<std::string>());
    if (was == shown_by_visit.end()) {
      added = r["visit"].get<std::string>();
      continue;
    }
    EXPECT_FALSE(r.value("measuring", false)) << r;
    for (const char* key :
         {"chainage_text", "rmr_text", "q_text", "proposed", "decided", "excavation_text"})
      EXPECT_EQ(r[key], was->second[key]) << key << ": a round shown before the sync changed";
  }
  ASSERT_FALSE(added.empty());

  const json truth = rounds_of_a_whole_pull(s, "rounds-synced");

  const Rounds in = rounds_from(server);
  ASSERT_EQ(in.status, 200) << in.body;
  EXPECT_EQ(in.measuring, 0) << in.body;
  EXPECT_EQ(in.measured, 1) << "the synced visit's round alone is measured";
  const json filled = json::parse(in.body);
  ASSERT_EQ(filled["rounds"].size(), truth["rounds"].size());
  bool found = false;
  for (std::size_t i = 0; i < truth["rounds"].size(); ++i) {
    const json& got = filled["rounds"][i];
    const json& want = truth["rounds"][i];
    found = found || got["visit"] == added;
    EXPECT_FALSE(got.contains("measuring")) << got;
    for (const char* key :
         {"chainage_text", "rmr_text", "q_text", "proposed", "decided", "excavation_text"})
      EXPECT_EQ(got[key], want[key]) << key << " of round " << i;
  }
  EXPECT_TRUE(found) << "the synced visit has no round";
}

// visit uuid -> the figures kept for its round.
std::map<std::string, json> kept_figures(const Site& s) {
  storage::office::Connection su(office_test::as_superuser(s.database));
  const storage::office::Result r =
      su.query("SELECT visit_uuid::text, figures::text FROM rockface.round_figures", {}, "reading");
  std::map<std::string, json> out;
  for (int i = 0; i < r.rows(); ++i) out[r.text(i, 0)] = json::parse(r.text(i, 1));
  return out;
}

// Issue 46: a round's earlier face was taken from the whole drive, so of
// two headings driven towards each other the south heading's rounds
// started at the nearest face of either. Through the office (a tablet's
// project synced to PostgreSQL, `office serve` measuring the rounds in
// the background, the figures kept on the server): each round starts at
// the previous face of its own heading, the south heading read toward
// descending chainage (tests/support/two_headings.h holds the truth).
TEST(OfficeRounds, EachHeadingsRoundStartsAtItsOwnPreviousFace) {
  const fs::path folder =
      fs::temp_directory_path() / ("rockface-two-headings-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const auto visits = test::make_two_headings_project(folder / "p.rockface", "Two headings");
  const Site s = site_of_project(folder / "p.rockface", "Two headings");
  OfficeServer server(s, 30);
  const Rounds r = rounds_from(server, "Two headings");
  ASSERT_EQ(r.status, 200) << r.body;
  ASSERT_EQ(r.measuring, 0) << r.body;
  const json page = json::parse(r.body);
  ASSERT_EQ(page["rounds"].size(), visits.size()) << r.body;
  const auto kept = kept_figures(s);
  // The visits' faces are at distinct chainages: a round is found by its own.
  struct Want {
    const char* label;
    json previous;     // the earlier face's chainage, null for none
    double sense;      // the heading's drive direction
    const char* text;  // where the page says the round starts
  };
  for (const Want& w :
       {Want{"N1", nullptr, 1, "ch 100.0 m to "}, Want{"S1", nullptr, -1, "ch 128.0 m to "},
        Want{"N2", 104.0, 1, "ch 104.0 m to "}, Want{"S2", 124.0, -1, "ch 124.0 m to "},
        Want{"U1", nullptr, 1, "ch 100.0 m to "}}) {
    double face = 0;
    for (const auto& v : visits)
      if (v.label == w.label) face = v.face;
    const json* round = nullptr;
    for (const auto& row : page["rounds"])
      if (row["chainage"].get<double>() == face) round = &row;
    ASSERT_TRUE(round) << w.label << " has no round in " << r.body;
    const std::string text = (*round)["excavation_text"].get<std::string>();
    EXPECT_NE(text.find(w.text), std::string::npos) << w.label << ": " << text;
    ASSERT_TRUE(kept.count((*round)["visit"].get<std::string>())) << w.label;
    const json& f = kept.at((*round)["visit"].get<std::string>());
    EXPECT_EQ(f["previous_face"], w.previous) << w.label << ": " << f;
    EXPECT_EQ(f["sense"], w.sense) << w.label << ": " << f;
    // 0.4 m short of the flat face on the heading's side (visit_profile.cpp's
    // kFaceClearM); the rendered face is placed to rounding (1e-6 m, far
    // below the metres a wrong heading's face is off).
    EXPECT_NEAR(f["round_to"].get<double>(), face - w.sense * 0.4, 1e-6) << w.label;
  }
  // The drive filtered by one heading lists that heading's visits, and
  // every heading of the tunnel to choose from ("—" last: U1 names none).
  httplib::Client c("127.0.0.1", server.port());
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  const auto drive =
      c.Get("/api/drive?tunnel=Two%20headings&heading=North%20portal", {{"Cookie", office.cookie}});
  ASSERT_TRUE(drive);
  ASSERT_EQ(drive->status, 200) << drive->body;
  const json d = json::parse(drive->body);
  EXPECT_EQ(d["headings"], json::array({"North portal", "South portal", "—"})) << d["headings"];
  ASSERT_EQ(d["visits"].size(), 2u) << drive->body;
  for (const auto& v : d["visits"]) EXPECT_EQ(v["heading"], "North portal") << v;
  // By date (N2 and S2 were taken on 3 March) and by tablet (tablet_a
  // synced every visit).
  auto count = [&](const std::string& query) -> int {
    const auto r = c.Get("/api/drive?tunnel=Two%20headings&" + query, {{"Cookie", office.cookie}});
    if (!r || r->status != 200) return -1;
    return static_cast<int>(json::parse(r->body)["visits"].size());
  };
  EXPECT_EQ(count("from=2026-03-03&to=2026-03-03"), 2);
  EXPECT_EQ(count("from=2026-03-03"), 3);
  EXPECT_EQ(count("to=2026-03-02"), 2);
  EXPECT_EQ(count("tablet=tablet_a"), 5);
  EXPECT_EQ(count("tablet=tablet_b"), 0);
  EXPECT_EQ(count("heading=%E2%80%94"), 1) << "U1 alone names no heading";
  if (!::testing::Test::HasFailure()) fs::remove_all(folder);
}

// The kept figures are the web server's to write (its group, through one
// function): an office person's own role writes none, directly or through
// the function, and reads only the rounds of tunnels it may read.
TEST(OfficeRounds, AnOfficeRoleNeitherWritesKeptFiguresNorReadsOtherTunnels) {
  const Site& s = site();
  {
    OfficeServer server(s, 30);
    ASSERT_EQ(rounds_from(server).status, 200);
  }
  storage::office::Connection office(s.server, "office_reader", kOfficePassword, 10);
  for (const char* sql :
       {"SELECT rockface.keep_round_figures(gen_random_uuid(), 'x', '{}'::jsonb)",
        "INSERT INTO rockface.round_figures (visit_uuid, inputs, figures) SELECT visit_uuid, "
        "'x', '{}' FROM rockface.round_figures LIMIT 1",
        "UPDATE rockface.round_figures SET figures = '{}'"}) {
    try {
      office.query(sql, {}, "writing figures");
      ADD_FAILURE() << "an office role ran " << sql;
    } catch (const storage::office::ServerError& e) {
      EXPECT_EQ(e.sqlstate(), "42501") << sql << ": " << e.what();
    }
  }
  EXPECT_GT(office.query("SELECT count(*) FROM rockface.round_figures", {}, "reading").int64(0, 0),
            0);
  // The adit's office reads none of Main drive's visits, nor their figures.
  storage::office::Connection adit(s.server, "adit_office", kAditPassword, 10);
  EXPECT_EQ(adit.query("SELECT count(*) FROM rockface.visit v JOIN rockface.tunnel t ON t.id = "
                       "v.tunnel_id WHERE t.name = 'Main drive'",
                       {}, "reading")
                .int64(0, 0),
            0);
  EXPECT_EQ(adit.query("SELECT count(*) FROM rockface.round_figures", {}, "reading").int64(0, 0), 0)
      << "the adit's office read Main drive's figures";
}

}  // namespace
}  // namespace rockface::office_web_test
