// `rockface profile PROJECT --visit N --out PROFILE.png [--json F]`: the
// excavation of a visit's round against the tunnel's design profile.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/records/project_visit.h"
#include "firmware-app/tunnel/visit_profile.h"
#include "firmware-app/tunnel/visit_profile_json.h"
#include "storage/exchange/image_file.h"
#include "storage/field_report/tunnel_pictures.h"
#include "storage/project/project_store.h"

namespace rockface::app {
namespace {

struct ProfileOptions {
  std::string project, out, json, preset = "standard";
  std::optional<storage::RecordId> visit;
};

VerbRun setup_profile(CLI::App& sub) {
  auto o = std::make_shared<ProfileOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface) with a tunnel")->required();
  sub.add_option("--visit", o->visit, "visit id (default: the latest visit)");
  sub.add_option("--out", o->out, "the developed view of the round, a PNG file")->required();
  sub.add_option("--json", o->json, "the figures per cross-section, a JSON file");
  sub.add_option("--preset", o->preset, "fast | standard | precise: sections and rays");
  return [o] {
    const Preset preset = parse_preset(o->preset, "--preset");
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    storage::OpenOptions read;
    read.read_only = true;
    storage::ProjectStore store = storage::ProjectStore::open(o->project, read);
    const auto visit = o->visit ? o->visit : store.latest_visit();
    if (!visit) throw InputError(o->project, "the project has no visit");
    if (o->visit) require_visit(store, *o->visit);
    const VisitProfile profile = visit_profile(store, *visit, preset);
    storage::write_image_file(
        o->out, storage::developed_view_picture(profile.deviation, profile.tunnel.profile), ".png");
    if (!o->json.empty()) write_text_atomically(o->json, visit_profile_json(profile));
    for (const auto& line : visit_profile_summary(profile)) std::cout << line << "\n";
    std::cout << "developed view: " << o->out << "\n";
    // Nothing to compare (no walls in view) is said in the summary and on
    // the picture, never printed as zero over- and underbreak.
    return 0;
  };
}

const VerbRegistrar profile_verb{
    "profile",
    "the excavation of a visit's round against the tunnel's design profile: over- and "
    "underbreak per cross-section, volumes, the deepest underbreak, a developed view",
    setup_profile};

}  // namespace
}  // namespace rockface::app
