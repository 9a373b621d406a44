// Issue 41: `rockmass --form FORM.json` on a visit without traces exited 2
// but had already stored the form. Everything is checked (the visit, its
// traces, the form) before anything is stored: the refusal leaves the
// project's bytes and rows as they were.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "storage/project/project_store.h"
#include "tests/support/cli_run.h"

namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(RockmassFormRefusedCli, AVisitWithoutTracesStoresNoForm) {
  const fs::path dir = fs::temp_directory_path() / "rockmass-form-refused-cli";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path p = dir / "p.rockface";
  rockface::storage::RecordId visit = 0;
  {
    rockface::storage::ProjectInfo info;
    info.name = "no traces";
    info.datum = {2690123.25, 1170456.5, 1105.125};
    auto store = rockface::storage::ProjectStore::create(p, info);
    visit = store.begin_visit("test");
  }
  std::ofstream(dir / "form.json") << R"({"Jr": 1.5, "Ja": 1, "Jw": 1, "SRF": 1})";
  const std::string bytes = bytes_of(p);
  const auto r = rockface::test::run_rockface("rockmass " + p.string() + " --form " +
                                              (dir / "form.json").string() + " --out " +
                                              (dir / "rm.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("trace"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "rm.json"));
  EXPECT_TRUE(bytes_of(p) == bytes) << "the project changed";
  auto store = rockface::storage::ProjectStore::open(p);
  EXPECT_FALSE(store.load_rockmass_form(visit));
  EXPECT_EQ(store.list_actions().size(), 2u);  // created, visit begun
  fs::remove_all(dir);
}
