// The checks of a project file (storage/project/project_integrity.h): the
// quick check reads every page; the check of the rows leaves the
// photographs' pages to be read when they are loaded, and must still
// refuse a file whose rows or length are damaged. The damage is made by
// overwriting pages that SQLite's own page map (the dbstat table) names, as
// a failing card would.
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "storage/project/project_integrity.h"
#include "storage/project/project_store.h"
#include "tests/support/sample_records.h"

namespace rockface::storage {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

class ProjectIntegrity : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = dir_ / "visits.rockface";
    auto store = ProjectStore::create(file_, test::sample_project());
    for (int v = 0; v < 3; ++v) {
      const RecordId visit = store.begin_visit("visit " + std::to_string(v));
      store.save_capture(test::sample_capture(visit, v));
      std::vector<Measurement> planes(1);
      planes[0].visit_id = visit;
      planes[0].label = "T1";
      planes[0].points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}};
      planes[0].dip_deg = 45;
      planes[0].dipdir_deg = 120;
      store.save_measurements(visit, planes);
    }
    store.checkpoint();
  }

  // A page of `table` of the given kind ('leaf', 'internal', 'overflow'),
  // by SQLite's own page map.
  std::int64_t page_of(const std::string& table, const std::string& kind) {
    sqlite::Connection db(file_, sqlite::Connection::Access::read_only);
    sqlite::Statement st(db,
                         "SELECT pageno FROM dbstat WHERE name = ? AND pagetype = ? ORDER BY "
                         "pageno LIMIT 1 OFFSET 3",
                         "finding a page");
    st.bind(1, table).bind(2, kind);
    if (!st.step()) {
      sqlite::Statement first(
          db, "SELECT pageno FROM dbstat WHERE name = ? AND pagetype = ? ORDER BY pageno",
          "finding a page");
      first.bind(1, table).bind(2, kind);
      if (!first.step()) return 0;
      return first.column_int(0);
    }
    return st.column_int(0);
  }

  void overwrite_page(std::int64_t page) {
    ASSERT_GT(page, 1);
    std::fstream f(file_, std::ios::in | std::ios::out | std::ios::binary);
    const std::string pattern(4096, '\x5A');
    f.seekp((page - 1) * 4096);
    f.write(pattern.data(), static_cast<std::streamsize>(pattern.size()));
  }

  std::string refusal(OpenOptions::Check depth) {
    OpenOptions options;
    options.check = depth;
    try {
      ProjectStore::open(file_, options);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), file_.string());
      return e.reason();
    }
    return {};
  }

  TempDir dir_{"project-integrity"};
  fs::path file_;
};

TEST_F(ProjectIntegrity, ASoundFilePassesEveryDepth) {
  for (auto depth : {IntegrityDepth::rows, IntegrityDepth::quick, IntegrityDepth::full}) {
    EXPECT_EQ(refusal(depth), "");
    const IntegrityReport report = check_project_file(file_, depth);
    EXPECT_TRUE(report.ok);
    EXPECT_TRUE(report.problems.empty());
  }
}

// A photograph's page damaged: the rows open (the photograph's damage shows
// when it is loaded, and the tablet's whole-file check finds it), the whole
// file's check refuses it.
TEST_F(ProjectIntegrity, APhotographsDamagedPageIsLeftToTheWholeFileCheck) {
  overwrite_page(page_of("image", "overflow"));
  EXPECT_EQ(refusal(OpenOptions::Check::rows), "");
  EXPECT_NE(refusal(OpenOptions::Check::quick).find("damaged"), std::string::npos);
  const IntegrityReport whole = check_project_file(file_, IntegrityDepth::quick);
  EXPECT_FALSE(whole.ok);
  EXPECT_FALSE(whole.problems.empty());
  // And loading the damaged photograph says so, naming the file.
  OpenOptions rows;
  rows.check = OpenOptions::Check::rows;
  auto store = ProjectStore::open(file_, rows);
  bool refused = false;
  for (const auto& c : store.list_captures()) try {
      store.load_capture(c.id);
    } catch (const Error& e) {
      refused = true;
      EXPECT_NE(std::string(e.what()).find(file_.string()), std::string::npos) << e.what();
    }
  EXPECT_TRUE(refused) << "no capture's photograph read the damaged page";
}

TEST_F(ProjectIntegrity, ADamagedPageOfTheRowsIsRefusedAtEveryDepth) {
  std::int64_t page = page_of("measurement", "leaf");
  if (page == 0) page = page_of("visit", "leaf");
  overwrite_page(page);
  const auto before = test::read_file_bytes(file_);
  for (auto depth : {IntegrityDepth::rows, IntegrityDepth::quick})
    EXPECT_NE(refusal(depth).find("damaged"), std::string::npos);
  EXPECT_EQ(test::read_file_bytes(file_), before) << "a refused file was changed";
}

// A copy cut short loses the last pages, which in a project of photographs
// are photographs: the rows' check sees it from the header's length.
TEST_F(ProjectIntegrity, AFileCutShortIsRefusedByTheRowsCheck) {
  const auto size = fs::file_size(file_);
  fs::resize_file(file_, size - 3 * 4096);
  const std::string reason = refusal(OpenOptions::Check::rows);
  EXPECT_NE(reason.find("cut short"), std::string::npos) << reason;
}

TEST_F(ProjectIntegrity, ACancelledCheckIsNeitherSoundNorDamaged) {
  std::atomic<bool> cancel{true};
  const IntegrityReport report = check_project_file(file_, IntegrityDepth::quick, &cancel);
  EXPECT_FALSE(report.ok);
  EXPECT_TRUE(report.problems.empty());
}

}  // namespace
}  // namespace rockface::storage
