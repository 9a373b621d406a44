// `rockface tunnel PROJECT --alignment ALIGNMENT.csv --profile PROFILE.json|csv
//  [--name NAME] [--drive ascending|descending] [--underbreak-tolerance M]`:
// gives a project its tunnel from the surveyor's and the designer's files.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/tunnel/tunnel_from_files.h"

namespace rockface::app {
namespace {

struct TunnelOptions {
  std::string project;
  TunnelFiles files;
};

VerbRun setup_tunnel(CLI::App& sub) {
  auto o = std::make_shared<TunnelOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--alignment", o->files.alignment,
                 "the alignment: CSV of stations (chainage, easting, northing, height[, radius])")
      ->required();
  sub.add_option("--profile", o->files.profile, "the design profile: JSON or CSV of segments")
      ->required();
  sub.add_option("--name", o->files.name, "the tunnel's name (default: the alignment file's)");
  sub.add_option("--drive", o->files.drive, "ascending | descending chainage (default ascending)");
  sub.add_option("--underbreak-tolerance", o->files.underbreak_tolerance_m,
                 "underbreak not counted up to this depth, m (default 0.05)");
  return [o] {
    // Everything read and checked before the project is opened for writing.
    const storage::TunnelRecord tunnel = tunnel_from_files(o->files);
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    storage::ProjectStore store = storage::ProjectStore::open(o->project);
    if (store.read_only())
      throw InputError(o->project, "cannot add a tunnel: " + store.read_only_reason());
    give_project_its_tunnel(store, tunnel);
    const tunnel::Alignment a = tunnel.alignment(store.project().datum);
    std::cout << "project " << o->project << ": tunnel " << tunnel.name << ", chainage "
              << format_fixed(a.first_chainage(), 2) << " to " << format_fixed(a.last_chainage(), 2)
              << ", " << tunnel.stations.size() << " stations, profile "
              << format_fixed(tunnel.profile.area(), 2, " m²") << "\n";
    return 0;
  };
}

const VerbRegistrar tunnel_verb{
    "tunnel", "gives a project its tunnel: the alignment and the design profile from their files",
    setup_tunnel};

}  // namespace
}  // namespace rockface::app
