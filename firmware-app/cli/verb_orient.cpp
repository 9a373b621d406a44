// `rockface orient PROJECT --visit N --reference-line U1,V1,U2,V2 --azimuth DEG
//  [--declination DEG]`: north for a visit stored without it (a pole but no
// compass line), from the compass line read on site.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/reconstruct/registration_options.h"
#include "firmware-app/records/orient_visit.h"

namespace rockface::app {
namespace {

struct OrientOptions {
  std::string project;
  storage::RecordId visit = 0;
  RegistrationOptions line;
};

VerbRun setup_orient(CLI::App& sub) {
  auto o = std::make_shared<OrientOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--visit", o->visit, "visit id")->required();
  sub.add_option("--reference-line", o->line.reference_line,
                 "U1,V1,U2,V2: the line's two pixels in the left photograph of the visit's "
                 "first pair")
      ->required();
  sub.add_option("--azimuth", o->line.azimuth,
                 "compass bearing of the line, degrees clockwise from north")
      ->required();
  sub.add_option("--declination", o->line.declination,
                 "magnetic declination, degrees, east positive");
  return [o] {
    // The line checked as `reconstruct` checks it, before the project opens.
    const auto north = registration_sources(o->line).north;
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    storage::ProjectStore store = storage::ProjectStore::open(o->project);
    if (store.read_only())
      throw InputError(o->project, "cannot orient a visit: " + store.read_only_reason());
    const VisitOrientation r = orient_visit_by_compass(store, o->visit, *north);
    std::cout << "visit " << o->visit << ": " << r.note << "\n";
    return 0;
  };
}

const VerbRegistrar orient_verb{
    "orient", "north for a visit stored without it, from a compass line on its photograph",
    setup_orient};

}  // namespace
}  // namespace rockface::app
