// The tablet's "Import a 3D image" (ui::ImportRunner): `rockface import`'s
// workflow (firmware-app/import/import_surface.h) into a new visit, from the
// runner's own connection to the project.
#include "firmware-app/import/import_surface.h"
#include "firmware-app/services/removable_drives.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"

namespace rockface::app {

std::vector<ui::ImportFolder> StoreImportRunner::sticks() {
  std::vector<ui::ImportFolder> out;
  for (const auto& drive : removable_drives(false)) out.push_back({drive.folder, drive.label});
  return out;
}

ui::ImportedVisit StoreImportRunner::import(const std::filesystem::path& project,
                                            const std::filesystem::path& file, Progress& progress) {
  storage::ProjectStore store = storage::ProjectStore::open(project);
  ImportRequest request;
  request.file = file;
  const ImportResult r = import_surface(store, request, progress);
  ui::ImportedVisit done;
  done.visit = r.visit;
  done.words = file.filename().string() + ", " + r.format + ", " + std::to_string(r.points) +
               " points, " + (r.frame == "survey" ? "survey coordinates" : "a local frame") +
               (r.intensity_as_grey ? ", its intensity drawn as grey" : "");
  return done;
}

}  // namespace rockface::app
