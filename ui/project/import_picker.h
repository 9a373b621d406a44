#pragma once
// Issue 43: "Import a 3D image" on the Project screen: the files a scanner,
// a drone's software or the office left in the tablet's storage or on a USB
// stick, listed by the format their name says (no system dialog: a
// geologist in gloves taps a row), imported on the worker with its progress
// bar as a new visit of the open project; the visit is chosen when it is
// done. A refused file is said on the status line in the command line's
// words, and nothing is stored.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rockface::ui {

struct AppState;

struct ImportPickerFile {
  std::filesystem::path file;
  std::string shown;   // its path under the listed folder
  std::string format;  // as the import names it ("LAS", "text cloud")
  std::uintmax_t bytes = 0;
};

struct ImportPickerPlace {
  std::string label;  // "Tablet", "USB stick KINGSTON"
  std::vector<ImportPickerFile> files;
  bool more = false;  // more files than listed
};

struct ImportPickerState {
  bool open = false;
  std::vector<ImportPickerPlace> places;  // read when opened or looked at again
};

// The 3D image files in `folder` and the folders in it, down to `depth`
// levels (hidden ones skipped), by name; at most `limit` (`more` says
// when there were others).
ImportPickerPlace import_files_in(const std::filesystem::path& folder, const std::string& label,
                                  int depth = 2, std::size_t limit = 200);

// The button, and the list while it is open; nothing without an import
// service or a project.
void draw_import_picker(AppState& app);

}  // namespace rockface::ui
