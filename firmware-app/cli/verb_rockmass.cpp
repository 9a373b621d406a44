// `rockface rockmass PROJECT [--visit N] [--form FORM.json] --out ROCKMASS.json`:
// the rock mass of a visit in figures (spacing, RQD, Jv, block sizes,
// persistence) and its RMR89 and Q with each rating's source. --form stores
// the form entered for the visit first (refused by name when out of range).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/rockmass/figures_in_words.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/rockmass/visit_rock_mass.h"
#include "storage/project/project_store.h"
#include "storage/report/rockmass_report_json.h"
#include "storage/scene/rockmass_form_json.h"

namespace rockface::app {
namespace {

struct RockmassOptions {
  std::string project, out, form;
  std::optional<storage::RecordId> visit;
};

VerbRun setup_rockmass(CLI::App& sub) {
  auto o = std::make_shared<RockmassOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface)")->required();
  sub.add_option("--visit", o->visit, "visit id (default: the latest visit)");
  sub.add_option("--out", o->out, "the figures and classifications, a JSON file")->required();
  sub.add_option("--form", o->form,
                 "the classification form entered on site (JSON, docs/scene-extensions.md "
                 "\"rockmass\"): stored with the visit, replacing the one stored");
  return [o] {
    if (!std::filesystem::exists(o->project)) throw InputError(o->project, "no such project file");
    std::optional<rockmass::ClassificationForm> form;
    if (!o->form.empty()) form = storage::load_rockmass_form(o->form);
    storage::OpenOptions options;
    options.read_only = !form;
    storage::ProjectStore store = storage::ProjectStore::open(o->project, options);
    const auto visit = o->visit ? o->visit : store.latest_visit();
    if (!visit) throw InputError(o->project, "the project has no visit");
    // Everything checked (the visit, its traces, the form's values) before
    // the form is stored: a refusal leaves the project as it was (issue 41).
    const rockmass::RockMassFigures figures = visit_rock_mass(store, *visit, form);
    if (form) store.save_rockmass_form(*visit, *form);
    write_text_atomically(o->out, storage::rockmass_report_json(figures).dump(2) + "\n");
    for (const auto& line : rockmass::figures_lines(figures)) std::cout << line << "\n";
    for (const auto& line : rockmass::classification_lines(figures)) std::cout << line << "\n";
    std::cout << "rock mass: " << o->out << "\n";
    return 0;
  };
}

const VerbRegistrar rockmass_verb{
    "rockmass",
    "the rock mass of a visit in figures (spacing, RQD, Jv, block sizes, persistence) and its "
    "RMR89 and Q, each rating measured or entered",
    setup_rockmass};

}  // namespace
}  // namespace rockface::app
