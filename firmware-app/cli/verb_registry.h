#pragma once
// The command line's verbs. Each verb lives in its own file and registers
// itself with a static VerbRegistrar, so adding a verb touches no other file.
//
//   static rockface::app::VerbRegistrar reg{"analyse", "Analyse a scene", add_analyse};
//
// `setup` adds the verb's options to its CLI11 subcommand and returns the
// function to run when the verb is chosen. That function returns the exit
// code (0 ok, 2 bad input, 1 other failure) and may throw: main maps
// rockface::InputError to 2 and any other exception to 1, with one line on
// stderr.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace rockface::app {

using VerbRun = std::function<int()>;
using VerbSetup = std::function<VerbRun(CLI::App& sub)>;

struct Verb {
  std::string name;
  std::string description;
  VerbSetup setup;
};

std::vector<Verb>& verbs();

struct VerbRegistrar {
  VerbRegistrar(std::string name, std::string description, VerbSetup setup) {
    verbs().push_back({std::move(name), std::move(description), std::move(setup)});
  }
};

}  // namespace rockface::app
