#pragma once
// Issue 43: "Import a 3D image" on the Project screen
// (ui/project/import_picker.h) needs from above the UI layer: the USB
// sticks plugged in, and the import itself as `rockface import` does it (a
// new visit with the file's 3D image), run on the worker.
#include <filesystem>
#include <string>
#include <vector>

#include "core/common/progress.h"
#include "storage/project/project_records.h"

namespace rockface::ui {

// A folder the picker lists: the tablet's own storage or a stick.
struct ImportFolder {
  std::filesystem::path folder;
  std::string label;  // what the tablet shows ("USB stick KINGSTON")
};

struct ImportedVisit {
  storage::RecordId visit = 0;
  std::string words;  // what was imported, as the import says it
};

class ImportRunner {
 public:
  virtual ~ImportRunner() = default;
  // The removable drives mounted now; empty when none is.
  virtual std::vector<ImportFolder> sticks() = 0;
  // The file's 3D image as a new visit of the project, from its own
  // connection. Throws rockface::InputError with the command line's words
  // when the file is refused (nothing stored), Cancelled when cancelled.
  virtual ImportedVisit import(const std::filesystem::path& project,
                               const std::filesystem::path& file, Progress& progress) = 0;
};

}  // namespace rockface::ui
