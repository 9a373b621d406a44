// The tablet's Rock mass view (ui::RockMassRunner): opens its own
// connection to the project (one per thread), saves the form when given,
// and says what `rockface rockmass` prints.
#include "core/rockmass/figures_in_words.h"
#include "firmware-app/rockmass/visit_rock_mass.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"

namespace rockface::app {

std::vector<std::string> StoreRockMassRunner::figures(
    const std::filesystem::path& project, storage::RecordId visit_id,
    const std::optional<rockmass::ClassificationForm>& save, Progress& progress) {
  storage::OpenOptions options;
  options.read_only = !save;
  storage::ProjectStore store = storage::ProjectStore::open(project, options);
  progress.step("spacing, RQD, Jv, block sizes", 0.3);
  // Figured with the form before it is stored: a refusal stores nothing.
  const rockmass::RockMassFigures f = visit_rock_mass(store, visit_id, save);
  if (save) {
    progress.step("saving the form", 0.8);
    store.save_rockmass_form(visit_id, *save);
  }
  progress.step("classification", 0.9);
  std::vector<std::string> lines = rockmass::classification_lines(f);
  for (const auto& line : rockmass::figures_lines(f)) lines.push_back(line);
  return lines;
}

}  // namespace rockface::app
