// `rockface pull postgresql://... --tunnel NAME --out PROJECT.rockface`: a
// project built from every tablet's visits of a tunnel on the server.
#include <iostream>
#include <memory>

#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/office/office_workflows.h"

namespace rockface::app {
namespace {

struct PullVerbOptions {
  std::string server, tunnel, out;
};

VerbRun setup_pull(CLI::App& sub) {
  auto o = std::make_shared<PullVerbOptions>();
  sub.add_option("SERVER", o->server, "libpq connection string (postgresql://... or service=NAME)")
      ->required();
  sub.add_option("--tunnel", o->tunnel, "the server's tunnel")->required();
  sub.add_option("--out", o->out, "the new project file (*.rockface); must not exist")->required();
  return [o] {
    NoProgress progress;
    for (const auto& line : run_pull(o->server, o->tunnel, o->out, progress))
      std::cout << line << "\n";
    return 0;
  };
}

const VerbRegistrar pull_verb{
    "pull",
    "build a project from the site's PostgreSQL server: every tablet's visits of a tunnel, each "
    "photograph and mesh checked against its SHA-256",
    setup_pull};

}  // namespace
}  // namespace rockface::app
