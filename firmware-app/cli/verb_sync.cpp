// `rockface sync PROJECT --to postgresql://...|service=NAME [--tunnel NAME]`:
// everything the project's visits hold up to the site's office server;
// run again, it sends only what changed, and it resumes a cut sync.
#include <iostream>
#include <memory>

#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/office/office_workflows.h"
#include "storage/office/pg_connection.h"

namespace rockface::app {
namespace {

struct SyncVerbOptions {
  std::string project, to, tunnel;
  std::int64_t chunk_kib = 1024;
};

VerbRun setup_sync(CLI::App& sub) {
  auto o = std::make_shared<SyncVerbOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--to", o->to,
                 "the server: a libpq connection string (postgresql://USER@HOST/DB?sslmode=..., "
                 "or service=NAME from pg_service.conf); default: the tablet's service")
      ->default_str("service=$ROCKFACE_SERVICE or service=rockface");
  sub.add_option("--tunnel", o->tunnel,
                 "the server's tunnel the visits belong to (default: the project's tunnel)");
  sub.add_option("--chunk-kib", o->chunk_kib, "photographs and meshes go up in chunks of this size")
      ->check(CLI::Range(1, 65536));
  return [o] {
    storage::office::SyncOptions options;
    options.tunnel = o->tunnel;
    options.chunk_bytes = o->chunk_kib * 1024;
    NoProgress progress;
    try {
      for (const auto& line :
           run_sync(o->project, o->to.empty() ? tablet_server() : o->to, options, progress))
        std::cout << line << "\n";
    } catch (const storage::office::ServerError& e) {
      if (!e.connection_lost()) throw;
      std::cerr << "sync: " << e.what()
                << "\nsync: no connection to the server: nothing is lost, the project is "
                   "unchanged, and the next sync sends what waits\n";
      return 3;
    }
    return 0;
  };
}

const VerbRegistrar sync_verb{
    "sync",
    "send the project's visits (captures, photographs, models, measurements, traces, analyses, "
    "the tunnel) to the site's PostgreSQL server; only what changed goes up",
    setup_sync};

}  // namespace
}  // namespace rockface::app
