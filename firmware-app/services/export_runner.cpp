// The tablet's "Export to USB stick" (ui::ExportRunner): what `rockface
// export` writes (firmware-app/export/visit_export.h), into a folder named
// after the project and the visit on the stick.
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/common/error.h"
#include "firmware-app/export/visit_export.h"
#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"

namespace rockface::app {

namespace {

// /proc/mounts writes a space in a path as \040 (and tab, newline, backslash
// likewise): a stick labelled "FIELD DATA" mounts at /media/geo/FIELD\040DATA.
std::string unescape_mount_path(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 3 < text.size() &&
        text.substr(i + 1, 3).find_first_not_of("01234567") == std::string::npos) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 3), nullptr, 8));
      i += 3;
      continue;
    }
    out += text[i];
  }
  return out;
}

bool removable_mount(const std::string& path) {
  return path.rfind("/media/", 0) == 0 || path.rfind("/run/media/", 0) == 0;
}

ui::ExportTarget stick(const std::filesystem::path& folder) {
  const std::string name = folder.filename().string();
  return {folder, "USB stick " + (name.empty() ? folder.string() : name)};
}

}  // namespace

std::vector<ui::ExportTarget> StoreExportRunner::targets() {
  std::vector<ui::ExportTarget> out;
  if (const char* dir = std::getenv("ROCKFACE_USB_DIR"); dir && *dir) {
    if (std::filesystem::is_directory(dir) && ::access(dir, W_OK) == 0) out.push_back(stick(dir));
    return out;
  }
  std::ifstream mounts("/proc/mounts");
  for (std::string line; std::getline(mounts, line);) {
    std::istringstream fields(line);
    std::string device, mount_point;
    if (!(fields >> device >> mount_point)) continue;
    const std::string path = unescape_mount_path(mount_point);
    if (removable_mount(path) && ::access(path.c_str(), W_OK) == 0) out.push_back(stick(path));
  }
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
