#include "ui/project/tunnel_files_picker.h"

#include <algorithm>
#include <memory>
#include <system_error>

#include <imgui.h>

#include "ui/app/app_state.h"
#include "ui/widgets/widgets_controls.h"

namespace rockface::ui {

namespace {

namespace fs = std::filesystem;

struct FolderEntries {
  std::vector<fs::path> folders, files;
};

// The folder's visible subfolders and the files `wanted` takes, by name. A
// folder that cannot be read lists nothing (a stick pulled out).
template <class Wanted>
FolderEntries entries_of(const fs::path& folder, Wanted wanted) {
  FolderEntries out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.front() == '.') continue;
    std::error_code kind;
    if (e.is_directory(kind))
      out.folders.push_back(e.path());
    else if (e.is_regular_file(kind) && wanted(e.path()))
      out.files.push_back(e.path());
  }
  std::sort(out.folders.begin(), out.folders.end());
  std::sort(out.files.begin(), out.files.end());
  return out;
}

std::string lower_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void show_place(TunnelFilesPicker& p, std::size_t k) {
  p.place = k;
  p.folder = p.places[k].folder;
  p.alignment.reset();
  p.profile.reset();
  p.lines.clear();
}

// The folder as the geologist knows it: the place, then the folders below
// it (never the machine's mount point).
std::string folder_words(const TunnelFilesPicker& p) {
  const FilePlace& place = p.places[*p.place];
  const fs::path inside = p.folder.lexically_relative(place.folder);
  return inside.empty() || inside == "." ? place.label : place.label + " / " + inside.string();
}

void give_tunnel(AppState& app) {
  TunnelRunner* runner = app.services.tunnel;
  const auto file = app.session->file();
  TunnelFilesPicker& p = app.project.tunnel.picker;
  const TunnelFileChoice choice{*p.alignment, *p.profile, p.name};
  app.task.start(
      "Tunnel from files",
      [runner, file, choice](Progress& progress) {
        return runner->give_tunnel(file, choice, progress);
      },
      [&app](const TaskOutcome& outcome) {
        TunnelFilesPicker& picker = app.project.tunnel.picker;
        if (outcome.kind != TaskOutcome::Kind::done) {
          picker.lines = {outcome.message};
          return;
        }
        picker = {};
        app.project.tunnel.loaded = false;  // re-read: the project has its tunnel now
      });
}

// The folder's subfolders to go into, and its files of one kind to choose.
// Returns the file tapped.
template <class Wanted>
std::optional<fs::path> draw_folder(AppState& app, Wanted wanted) {
  TunnelFilesPicker& p = app.project.tunnel.picker;
  const bool idle = !app.task.running();
  paragraph("In " + folder_words(p) + ":");
  const FolderEntries in = entries_of(p.folder, wanted);
  if (p.folder != p.places[*p.place].folder && app.targets.button("Up a folder", 0, idle)) {
    p.folder = p.folder.parent_path();
    return std::nullopt;
  }
  for (const auto& f : in.folders)
    if (app.targets.button_in_row(f.filename().string() + "/", idle)) {
      p.folder = f;
      return std::nullopt;
    }
  if (in.files.empty()) note("(no such file here)");
  std::optional<fs::path> tapped;
  for (const auto& f : in.files)
    if (app.targets.button(f.filename().string(), 0, idle)) tapped = f;
  return tapped;
}

}  // namespace

void open_tunnel_files_picker(AppState& app) {
  TunnelFilesPicker& p = app.project.tunnel.picker;
  p = {};
  p.open = true;
  p.places.push_back({app.session->file().parent_path(), "This tablet"});
  if (p.places.back().folder.empty()) p.places.back().folder = ".";
  // The sticks are looked for when the picker opens: one plugged in since
  // counts when it is opened again.
  if (app.services.exports)
    for (const ExportTarget& stick : app.services.exports->targets())
      p.places.push_back({stick.folder, stick.label});
  show_place(p, p.places.size() > 1 ? 1 : 0);
}

void draw_tunnel_files_picker(AppState& app) {
  TunnelFilesPicker& p = app.project.tunnel.picker;
  if (!p.open || !p.place) return;
  const bool idle = !app.task.running();
  heading("The tunnel from its files");
  label_in_row("Look in:");
  for (std::size_t k = 0; k < p.places.size(); ++k)
    if (app.targets.button_in_row(p.places[k].label, idle && k != *p.place)) show_place(p, k);
  if (p.places.size() == 1) note("No USB stick found: plug one in and open this again.");
  if (!p.alignment) {
    paragraph("1. The alignment: the surveyor's CSV of stations.");
    if (auto f = draw_folder(app, [](const fs::path& f) { return lower_extension(f) == ".csv"; }))
      p.alignment = *f;
  } else {
    paragraph("Alignment: " + p.alignment->filename().string());
    if (app.targets.button_in_row("Another alignment", idle)) {
      p.alignment.reset();
      p.profile.reset();
      p.lines.clear();
    } else if (!p.profile) {
      paragraph("2. The design profile (JSON or CSV).");
      const fs::path alignment = *p.alignment;
      if (auto f = draw_folder(app, [&alignment](const fs::path& f) {
            const std::string ext = lower_extension(f);
            return (ext == ".json" || ext == ".csv") && f != alignment;
          }))
        p.profile = *f;
    } else {
      paragraph("Design profile: " + p.profile->filename().string());
      if (app.targets.button_in_row("Another profile", idle)) {
        p.profile.reset();
        p.lines.clear();
      }
    }
  }
  if (p.alignment && p.profile) {
    label_in_row("Name:");
    ImGui::SetNextItemWidth(std::min(320 * app.targets.scale(), ImGui::GetContentRegionAvail().x));
    text_field(app.targets, "tunnel name", &p.name);
    if (p.name.empty()) note("(empty: " + p.alignment->stem().string() + ")");
    const bool can = idle && app.services.tunnel && !app.session->read_only();
    if (app.targets.button("Give the project this tunnel", 0, can)) give_tunnel(app);
  }
  for (const auto& line : p.lines) paragraph(line, warning_colour());
  if (app.targets.button_in_row("Close the file list", idle)) p = {};
}

}  // namespace rockface::ui
