// Every verb's `--help` names every option the verb takes (issue 46: the
// visit's geologist, `--geologist NAME`, on place, replay, import and
// measure). What a verb takes is read from its own source
// (firmware-app/cli/verb_*.cpp: each add_option / add_flag of a long
// option, and registration_cli.h's for the verbs that add those), not from
// the help; the help is the real binary's, parsed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> all_matches(const std::string& text, const std::regex& re) {
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it)
    out.insert((*it)[1]);
  return out;
}

// What the source of one verb declares.
struct VerbSource {
  std::set<std::string> options;      // long options, "--visit"
  std::set<std::string> subcommands;  // "serve"
};

std::map<std::string, VerbSource> verbs_in_sources() {
  const fs::path cli = fs::path(ROCKFACE_SOURCE_DIR) / "firmware-app/cli";
  const std::regex option(R"(add_(?:option|flag)\(\s*"(--[a-z0-9-]+)\")");
  const std::set<std::string> registration =
      all_matches(read_file(cli / "registration_cli.h"), option);
  std::map<std::string, VerbSource> out;
  for (const auto& entry : fs::directory_iterator(cli)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("verb_", 0) != 0 || entry.path().extension() != ".cpp") continue;
    const std::string text = read_file(entry.path());
    const std::set<std::string> verb =
        all_matches(text, std::regex(R"(VerbRegistrar\s+\w+\s*\{\s*"([a-z-]+)\")"));
    if (verb.size() != 1) continue;  // a file of helpers registers no verb
    VerbSource& v = out[*verb.begin()];
    v.options = all_matches(text, option);
    if (text.find("add_registration_options(") != std::string::npos)
      v.options.insert(registration.begin(), registration.end());
    v.subcommands = all_matches(text, std::regex(R"(add_subcommand\(\s*"([a-z-]+)\")"));
  }
  return out;
}

// The lines of a help's section ("Options:", "Subcommands:") that name an
// entry: two spaces, then the entry.
std::vector<std::string> section_lines(const std::string& help, const std::string& title) {
  std::vector<std::string> out;
  std::istringstream in(help);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != ' ')
      inside = line == title;
    else if (inside && line.size() > 2 && line.compare(0, 2, "  ") == 0 && line[2] != ' ')
      out.push_back(line.substr(2));
  }
  return out;
}

// The long options a help lists ("-h,--help  ..." gives --help).
std::set<std::string> listed_options(const std::string& help) {
  std::set<std::string> out;
  for (const auto& line : section_lines(help, "Options:")) {
    std::string names = line.substr(0, line.find(' '));
    std::istringstream each(names);
    for (std::string n; std::getline(each, n, ',');)
      if (n.rfind("--", 0) == 0) out.insert(n);
  }
  return out;
}

// Each help read once for the suite (a start of the binary is about a
// third of a second).
std::string help_of(const std::string& command) {
  static std::map<std::string, std::string> read;
  const auto it = read.find(command);
  if (it != read.end()) return it->second;
  const test::CliRun r = test::run_rockface(command + " --help");
  EXPECT_EQ(r.exit_code, 0) << command << " --help: " << r.err;
  return read[command] = r.out;
}

TEST(VerbHelp, NamesEveryOptionTheVerbTakesAndNoOther) {
  const std::map<std::string, VerbSource> sources = verbs_in_sources();
  ASSERT_GT(sources.size(), 20u) << "the verbs' sources were not found";
  std::set<std::string> listed_verbs;
  for (const auto& line : section_lines(help_of(""), "Subcommands:"))
    listed_verbs.insert(line.substr(0, line.find(' ')));
  std::set<std::string> source_verbs;
  for (const auto& [verb, source] : sources) source_verbs.insert(verb);
  EXPECT_EQ(listed_verbs, source_verbs) << "`rockface --help` lists other verbs than registered";

  for (const auto& [verb, source] : sources) {
    std::set<std::string> listed = listed_options(help_of(verb));
    for (const auto& sub : source.subcommands) {
      const std::set<std::string> more = listed_options(help_of(verb + " " + sub));
      listed.insert(more.begin(), more.end());
    }
    for (const auto& option : source.options)
      EXPECT_TRUE(listed.count(option)) << "`rockface " << verb << " --help` does not name "
                                        << option << ", which the verb takes";
    listed.erase("--help");
    for (const auto& option : listed)
      EXPECT_TRUE(source.options.count(option))
          << "`rockface " << verb << " --help` names " << option << ", which its source lacks";
  }
}

// The verbs that make or name a visit take its geologist by name.
TEST(VerbHelp, TheVerbsThatMakeOrNameAVisitTakeItsGeologistByName) {
  for (const char* verb : {"place", "replay", "import", "measure"}) {
    const std::vector<std::string> lines = section_lines(help_of(verb), "Options:");
    bool named = false;
    for (const auto& line : lines) named |= line.rfind("--geologist NAME ", 0) == 0;
    EXPECT_TRUE(named) << "`rockface " << verb << " --help` does not list --geologist NAME";
  }
}

}  // namespace
}  // namespace rockface
