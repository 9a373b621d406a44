// A visit's pages read a copy of that visit (issue 46: the visit page
// pulled the whole tunnel with every photograph to show one visit, then a
// copy with all 3,000 visits and placements of the drive): the visit's own
// records and the tunnel — no other visit, no photograph at all until one
// is shown, then that one from the server — and where its round starts
// read beside the copy, the same as from a pull of the whole drive.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/office/pg_connection.h"
#include "storage/office/pull_project.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "tests/integration/office_web/office_site.h"

// Last: <resolv.h>, which httplib.h includes, defines the macro _res that
// Eigen uses as a parameter name.
#include "tests/integration/office_web/office_client.h"

namespace rockface::office_web_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::int64_t count_of(const fs::path& project, const std::string& sql, std::int64_t visit) {
  storage::sqlite::Connection db(project, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(db, sql, "counting");
  if (sql.find('?') != std::string::npos) st.bind(1, visit);
  st.step();
  return st.column_int(0);
}

TEST(OfficeVisitCopy, AVisitPageReadsThatVisitAndItsPhotographsOnlyWhenShown) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(120));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  const httplib::Headers cookie = {{"Cookie", office.cookie}};
  const auto drive = c.Get("/api/drive?tunnel=Main%20drive", cookie);
  ASSERT_TRUE(drive);
  ASSERT_EQ(drive->status, 200) << drive->body;
  const json visits = json::parse(drive->body)["visits"];
  ASSERT_GE(visits.size(), 3u) << "the site's drive has visits of two tablets";

  // The first visit with photographs.
  std::string uuid;
  json page;
  for (const auto& v : visits) {
    const auto r =
        c.Get("/api/visit?tunnel=Main%20drive&visit=" + v["id"].get<std::string>(), cookie);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    page = json::parse(r->body);
    if (!page["photos"].empty()) {
      uuid = v["id"];
      break;
    }
  }
  ASSERT_FALSE(uuid.empty()) << "no visit of the site has photographs";

  std::vector<fs::path> copies;
  for (const auto& e : fs::directory_iterator(server.work_folder() / "shared"))
    if (e.path().extension() == ".rockface") copies.push_back(e.path());
  ASSERT_FALSE(copies.empty());
  int copies_of_the_visit = 0;
  for (const fs::path& copy : copies) {
    storage::sqlite::Connection db(copy, storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement st(db, "SELECT id FROM visit WHERE uuid = ?", "finding the visit");
    st.bind(1, uuid);
    // Each copy holds one visit: an earlier one opened is not this one.
    if (!st.step()) continue;
    const std::int64_t id = st.column_int(0);
    ++copies_of_the_visit;
    // That visit alone (none of the site's visits takes its texture from
    // another), not the drive's other visits and placements...
    EXPECT_EQ(count_of(copy, "SELECT count(*) FROM visit", 0), 1);
    EXPECT_EQ(count_of(copy, "SELECT count(*) FROM visit_placement WHERE visit_id <> ?", id), 0);
    // ...and the records of this visit only: no other visit's captures,
    // 3D images, joints or analyses.
    EXPECT_EQ(count_of(copy, "SELECT count(*) FROM capture WHERE visit_id <> ?", id), 0);
    EXPECT_EQ(count_of(copy,
                       "SELECT count(*) FROM model m JOIN capture c ON c.id = m.capture_id "
                       "WHERE c.visit_id <> ?",
                       id),
              0);
    EXPECT_EQ(count_of(copy, "SELECT count(*) FROM joint WHERE visit_id <> ?", id), 0);
    EXPECT_EQ(count_of(copy, "SELECT count(*) FROM analysis WHERE visit_id <> ?", id), 0);
    // No photograph's bytes were fetched to open the page.
    EXPECT_EQ(count_of(copy, "SELECT coalesce(sum(length(bytes)), 0) FROM image", 0), 0);
    EXPECT_GT(count_of(copy, "SELECT count(*) FROM image", 0), 0);
  }
  EXPECT_EQ(copies_of_the_visit, 1);

  // A photograph shown is fetched then, whole: its stored size, and a
  // picture that decodes.
  const json photo = page["photos"][0];
  const auto r = c.Get("/api/visit/photo?tunnel=Main%20drive&visit=" + uuid +
                           "&capture=" + std::to_string(photo["capture"].get<std::int64_t>()) +
                           "&side=" + photo["side"].get<std::string>(),
                       cookie);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const std::vector<std::uint8_t> bytes(r->body.begin(), r->body.end());
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(decoded.empty());
  bool sized = false;
  for (const fs::path& copy : copies)
    sized |=
        count_of(copy,
                 "SELECT count(*) FROM image i JOIN capture c ON i.id = c." +
                     photo["side"].get<std::string>() +
                     "_image_id WHERE c.id = ? AND i.byte_size = " + std::to_string(bytes.size()),
                 photo["capture"].get<std::int64_t>()) > 0;
  EXPECT_TRUE(sized) << "the photograph served is not the size its row keeps";
  // A capture that is not this visit's is refused.
  const auto other = c.Get(
      "/api/visit/photo?tunnel=Main%20drive&visit=" + uuid + "&capture=987654&side=left", cookie);
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 404);
}

// Where each visit's round starts, and so its over- and underbreak, on
// its page: what a copy of the whole drive gives (a pull of the tunnel as
// `rockface pull` makes it, the round read from it by `rockface profile`'s
// code), though the page's copy holds that visit alone. The visits are
// numbered as that pull numbers them ("face of visit N").
TEST(OfficeVisitCopy, EachVisitsRoundIsTheOneTheWholeDriveGives) {
  storage::office::Connection reader(site().server, "office_reader", kOfficePassword, 10);
  NoProgress none;
  const fs::path whole =
      site().folder / ("whole-drive-" + std::to_string(::getpid()) + ".rockface");
  fs::remove(whole);
  storage::office::pull_tunnel(reader, "Main drive", whole, none);
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(whole, read);

  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(120));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  const httplib::Headers cookie = {{"Cookie", office.cookie}};
  int from_a_previous_face = 0, rounds = 0;
  std::map<std::int64_t, std::string> uuids;
  {
    storage::sqlite::Connection db(whole, storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement st(db, "SELECT id, uuid FROM visit", "reading the visits' uuids");
    while (st.step()) uuids[st.column_int(0)] = st.column_text(1);
  }
  for (const auto& v : store.list_visits()) {
    // The round as the whole drive gives it; its first line (the visit's
    // place) is printed by the page above it (report_tunnel.cpp).
    std::vector<std::string> truth;
    try {
      truth = app::visit_profile_summary(app::visit_profile(store, v.id));
    } catch (const InputError&) {
      continue;  // not placed, or no 3D image: no round
    }
    ASSERT_FALSE(truth.empty());
    truth.erase(truth.begin());
    ++rounds;
    for (const auto& line : truth) from_a_previous_face += line.find("face of visit") != line.npos;
    const auto r = c.Get("/api/visit?tunnel=Main%20drive&visit=" + uuids[v.id], cookie);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json shown = json::parse(r->body)["tunnel"]["lines"];
    EXPECT_EQ(shown, json(truth)) << "the round of visit " << v.id << " (" << uuids[v.id] << ")";
  }
  // The site's drive (tablet_projects.cpp) has rounds that start at an
  // earlier visit's face.
  EXPECT_GT(rounds, 1);
  EXPECT_GT(from_a_previous_face, 0);
  std::error_code ec;
  fs::remove(whole, ec);
}

}  // namespace
}  // namespace rockface::office_web_test
