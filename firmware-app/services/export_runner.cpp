// The tablet's "Export to USB stick" (ui::ExportRunner): what `rockface
// export` writes (firmware-app/export/visit_export.h), into a folder named
// after the project and the visit on the stick.
#include "core/common/error.h"
#include "firmware-app/export/visit_export.h"
#include "firmware-app/services/removable_drives.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"

namespace rockface::app {

std::vector<ui::ExportTarget> StoreExportRunner::targets() {
  std::vector<ui::ExportTarget> out;
  for (const auto& drive : removable_drives(true)) out.push_back({drive.folder, drive.label});
  return out;
}

std::string StoreExportRunner::write(const std::filesystem::path& project,
                                     storage::RecordId visit_id, const ui::ExportTarget& target,
                                     Progress& progress) {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(project, read);
  ExportRequest request;
  request.visit = visit_id;
  request.out_dir =
      target.folder / (project.stem().string() + "-visit-" + std::to_string(visit_id));
  progress.step("writing the exports", 0.1);
  const ExportResult r = export_visit(store, request);
  if (r.files.empty()) throw Error("visit " + std::to_string(visit_id) + " has nothing to export");
  return std::to_string(r.files.size()) + " files in " + request.out_dir.filename().string() +
         " on " + target.label +
         (r.notes.empty() ? std::string() : " (" + std::to_string(r.notes.size()) + " notes)");
}

}  // namespace rockface::app
