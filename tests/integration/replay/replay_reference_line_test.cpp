// Issue 41: a replay whose scene's reference line cannot give north named
// `--reference-line`, an option of `reconstruct`, not the scene's field.
// A vertical line (no bearing) is refused naming the scene file and
// imaging.reference_line.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

namespace {

namespace fs = std::filesystem;

TEST(ReplayReferenceLine, AVerticalLineIsNamedByTheScenesField) {
  const fs::path dir =
      fs::temp_directory_path() / ("rockface-replay-refline-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(
      std::string(ROCKFACE_SOURCE_DIR) + "/tools/samples/tunnel-face-demo.scene.json"));
  auto& line = scene["imaging"]["reference_line"];
  // The second point straight above the first: no bearing.
  line["to"] = line["from"];
  line["to"][2] = line["from"][2].get<double>() + 1.5;
  const fs::path file = dir / "vertical.scene.json";
  std::ofstream(file) << scene.dump(2);
  const std::string cmd = std::string(ROCKFACE_BINARY_DIR) + "/rockface replay " + file.string() +
                          " --project " + (dir / "p.rockface").string() + " > " +
                          (dir / "out.txt").string() + " 2> " + (dir / "err.txt").string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::stringstream err;
  err << std::ifstream(dir / "err.txt").rdbuf();
  EXPECT_NE(err.str().find(file.string() + ": imaging.reference_line"), std::string::npos)
      << err.str();
  EXPECT_EQ(err.str().find("--reference-line"), std::string::npos) << err.str();
  fs::remove_all(dir);
}

}  // namespace
