// The rounds along the drive (issue 46): listed from a pulled copy of the
// tunnel's figures, never from its photographs — a drive of 3,000 visits
// pulled every photograph (minutes) to show a table of figures.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "firmware-app/office/office_rounds.h"
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

// The office's rounds route pulls the copy without photographs: after the
// rounds alone, the server's only pulled copy holds none.
TEST(OfficeRounds, TheDrivesRoundsReadNoPhotograph) {
  OfficeServer server;
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(120));
  const Login office = log_in(c, server.origin(), "office_reader", kOfficePassword);
  ASSERT_EQ(office.status, 200) << office.error;
  const auto r = c.Get("/api/drive/rounds?tunnel=Main%20drive", {{"Cookie", office.cookie}});
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_FALSE(json::parse(r->body)["rounds"].empty());
  std::vector<fs::path> copies;
  for (const auto& e : fs::directory_iterator(server.work_folder() / "shared"))
    if (e.path().extension() == ".rockface") copies.push_back(e.path());
  ASSERT_EQ(copies.size(), 1u) << "the rounds made more than their own copy";
  const Images images = images_of(copies.front());
  EXPECT_GT(images.rows, 0);
  EXPECT_EQ(images.bytes, 0) << "the rounds' copy holds photographs";
}

}  // namespace
}  // namespace rockface::office_web_test
