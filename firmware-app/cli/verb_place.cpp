// `rockface place PROJECT --visit N --chainage C [--offset M] [--height M]
// [--heading NAME] [--geologist NAME]`: places a visit in the project's tunnel by where the
// range pole stood, as the geologist types it (the lower target's chainage,
// offset right of the axis looking in the drive's direction, height above
// the axis), its 3D image oriented by its compass line. A visit registered
// by monitoring targets is placed by them when its tunnel is added; this is
// for the rest. `--heading` names the face the visit was taken at
// (storage/tunnel/visit_heading.h); given alone it names the heading of a
// visit placed before (nothing moves, so a mapped visit may take one too).
// `--geologist NAME` names the geologist who mapped the visit
// (storage/project/visit_geologist.h), placed or not, with or without a
// tunnel; `--geologist ""` takes the name away.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/tunnel/typed_placement.h"
#include "storage/project/visit_geologist.h"
#include "storage/tunnel/visit_heading.h"

namespace rockface::app {
namespace {

struct PlaceOptions {
  std::string project;
  storage::RecordId visit = 0;
  double chainage = 0, offset = 0, height = 0;
  std::string heading;
  std::string geologist;
};

VerbRun setup_place(CLI::App& sub) {
  auto o = std::make_shared<PlaceOptions>();
  sub.add_option("PROJECT", o->project,
                 "project file (*.rockface); with a tunnel to place a visit (--chainage), not "
                 "to name its geologist alone")
      ->required();
  sub.add_option("--visit", o->visit, "visit id")->required();
  CLI::Option* chainage =
      sub.add_option("--chainage", o->chainage, "chainage of the pole's lower target, m");
  CLI::Option* offset =
      sub.add_option("--offset", o->offset, "its offset right of the axis, m (default 0)");
  CLI::Option* height =
      sub.add_option("--height", o->height, "its height above the axis, m (default 0)");
  CLI::Option* heading =
      sub.add_option(
             "--heading", o->heading,
             "the face the visit was taken at, when the tunnel is driven from more than one (e.g. "
             "\"North portal\", \"Bench\"); alone: names a placed visit's heading")
          ->type_name("NAME");
  CLI::Option* geologist =
      sub.add_option("--geologist", o->geologist,
                     "the geologist who mapped the visit, by name (\"\" takes it away); alone: "
                     "names it, placed or not")
          ->type_name("NAME");
  offset->needs(chainage);
  height->needs(chainage);
  return [o, chainage, heading, geologist] {
    if (chainage->count() == 0 && heading->count() == 0 && geologist->count() == 0)
      throw InputError("--chainage",
                       "give the pole's chainage, --heading to name the heading or --geologist "
                       "to name the geologist");
    // Checked before anything moves.
    const std::string name = storage::checked_heading(o->heading, "--heading");
    const std::string geologist_name = storage::checked_geologist(o->geologist, "--geologist");
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    storage::ProjectStore store = storage::ProjectStore::open(o->project);
    if (store.read_only())
      throw InputError(o->project, "cannot place a visit: " + store.read_only_reason());
    if (chainage->count() > 0) {
      const storage::VisitPlacement p =
          place_by_typed_chainage(store, o->visit, {o->chainage, o->offset, o->height});
      std::cout << "visit " << o->visit << " placed: face at chainage "
                << format_fixed(p.chainage, 2) << ", offset " << format_fixed(p.offset_m, 2, " m")
                << (p.height_m ? ", height " + format_fixed(*p.height_m, 2, " m") : std::string())
                << " (" << p.note << ")\n";
    } else if (heading->count() > 0 && !store.load_visit_placement(o->visit)) {
      throw InputError("--heading", "visit " + std::to_string(o->visit) +
                                        " is not placed in the tunnel: give --chainage too");
    }
    if (heading->count() > 0) {
      storage::save_visit_heading(store, o->visit, name);
      std::cout << "visit " << o->visit << " heading: " << (name.empty() ? "none" : name) << "\n";
    }
    if (geologist->count() > 0) {
      store.save_visit_geologist(o->visit, geologist_name);
      std::cout << "visit " << o->visit << " geologist: "
                << (geologist_name.empty() ? storage::kGeologistNotRecorded : geologist_name)
                << "\n";
    }
    return 0;
  };
}

const VerbRegistrar place_verb{
    "place", "places a visit in the project's tunnel by the range pole's typed chainage",
    setup_place};

}  // namespace
}  // namespace rockface::app
