// rockface: the composition root. Parses the command line and runs one verb;
// without a verb it starts the tablet UI.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <system_error>

#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/cli/verb_ui.h"

namespace rockface::app {
std::vector<Verb>& verbs() {
  static std::vector<Verb> all;
  return all;
}
}  // namespace rockface::app

int main(int argc, char** argv) {
  using namespace rockface;
  CLI::App cli{"rockface: rock-face photogrammetry and block stability for the field tablet"};
  cli.require_subcommand(0, 1);
  auto& verbs = app::verbs();
  std::sort(verbs.begin(), verbs.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, app::VerbRun>> runs;
  for (const auto& verb : verbs) {
    CLI::App* sub = cli.add_subcommand(verb.name, verb.description);
    runs.emplace_back(sub, verb.setup(*sub));
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help (exit 0) or the usage error; usage errors are bad input.
    const int rc = cli.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, run] : runs)
      if (sub->parsed()) return run();
    return app::start_tablet_ui();
  } catch (const InputError& e) {
    std::cerr << "rockface: " << e.what() << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path longer than the file system takes is the user's input, said by
    // its name (issue 41: "filesystem error: status: File name too long",
    // exit 1); any other file-system failure is the machine's.
    if (e.code() == std::errc::filename_too_long) {
      std::cerr << "rockface: " << e.path1().string()
                << ": the name is too long for the file system\n";
      return 2;
    }
    std::cerr << "rockface: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "rockface: " << e.what() << "\n";
    return 1;
  }
}
