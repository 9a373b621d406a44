#pragma once
// Issue 42: the project's tunnel from files on the tablet. The Project
// screen lists a folder of the tablet's storage or of a USB stick (the
// folder's own files, no system dialog: a gloved finger in a tunnel), the
// geologist taps the alignment CSV and then the design profile, and the
// project gets its tunnel by the workflow `rockface tunnel` runs. A file it
// refuses is refused with the command line's message, shown here, and the
// project is unchanged.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rockface::ui {

struct AppState;

// Where the files may be: the project's own folder on the tablet, or a
// mounted USB stick.
struct FilePlace {
  std::filesystem::path folder;
  std::string label;  // "This tablet", "USB stick KINGSTON"
};

struct TunnelFilesPicker {
  bool open = false;
  std::vector<FilePlace> places;     // read when the picker opens
  std::optional<std::size_t> place;  // the place shown
  std::filesystem::path folder;      // the folder shown, inside the place
  std::optional<std::filesystem::path> alignment, profile;
  std::string name;                // the tunnel's name; empty: the alignment file's
  std::vector<std::string> lines;  // why the last files were refused
};

// Opens the picker on the project's folder (USB sticks looked for now).
void open_tunnel_files_picker(AppState& app);
// Draws the open picker; nothing when it is closed.
void draw_tunnel_files_picker(AppState& app);

}  // namespace rockface::ui
