// `rockface tunnel PROJECT --alignment ALIGNMENT.csv --profile PROFILE.json|csv
//  [--name NAME] [--drive ascending|descending] [--underbreak-tolerance M]`:
// gives a project its tunnel from the surveyor's and the designer's files.
#include <iostream>
#include <memory>

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
    const GivenTunnel given = give_project_its_tunnel(o->project, o->files);
    std::cout << "project " << o->project << ": " << given.summary << "\n";
    return 0;
  };
}

const VerbRegistrar tunnel_verb{
    "tunnel", "gives a project its tunnel: the alignment and the design profile from their files",
    setup_tunnel};

}  // namespace
}  // namespace rockface::app
