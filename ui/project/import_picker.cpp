#include "ui/project/import_picker.h"

#include <algorithm>
#include <memory>

#include <imgui.h>

#include "core/common/number_format.h"
#include "storage/exchange/import_reader.h"
#include "ui/app/app_state.h"
#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

namespace fs = std::filesystem;

std::string size_words(std::uintmax_t bytes) {
  if (bytes < 1000 * 1000) return format_fixed(static_cast<double>(bytes) / 1000, 0, " kB");
  return format_fixed(static_cast<double>(bytes) / 1e6, 1, " MB");
}

// Read on the tap that opens the list or looks again, never every frame: a
// stick's folders may take a moment.
void look(AppState& app) {
  ImportPickerState& p = app.project.import;
  p.places.clear();
  p.places.push_back(import_files_in(app.options.projects_folder, "Tablet"));
  for (const ImportFolder& stick : app.services.imports->sticks())
    p.places.push_back(import_files_in(stick.folder, stick.label));
}

void start_import(AppState& app, const ImportPickerFile& chosen) {
  ImportRunner* runner = app.services.imports;
  const fs::path project = app.session->file(), file = chosen.file;
  auto done = std::make_shared<ImportedVisit>();
  app.task.start(
      "Import a 3D image",
      [runner, project, file, done](Progress& progress) {
        *done = runner->import(project, file, progress);
        return done->words + ": visit " + std::to_string(done->visit);
      },
      [&app, done](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done || !app.session) return;
        app.project.import.open = false;
        app.session->choose_visit(done->visit);  // the imported visit, shown
        // What is said next is about the new visit (as for "New visit").
        app.statuses.clear_messages();
        app.status_visit = app.session->visit();
      });
}

}  // namespace

ImportPickerPlace import_files_in(const fs::path& folder, const std::string& label, int depth,
                                  std::size_t limit) {
  ImportPickerPlace place;
  place.label = label;
  std::error_code ec;
  fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path& path = it->path();
    const bool hidden = path.filename().string().rfind('.', 0) == 0;
    if (it->is_directory(ec)) {
      if (hidden || it.depth() + 1 >= depth) it.disable_recursion_pending();
      continue;
    }
    if (hidden || !it->is_regular_file(ec)) continue;
    const std::string format = storage::imported_surface_format_by_name(path);
    if (format.empty()) continue;
    if (place.files.size() == limit) {
      place.more = true;
      break;
    }
    place.files.push_back(
        {path, path.lexically_relative(folder).string(), format, it->file_size(ec)});
  }
  std::sort(place.files.begin(), place.files.end(),
            [](const auto& a, const auto& b) { return a.shown < b.shown; });
  return place;
}

void draw_import_picker(AppState& app) {
  if (!app.services.imports || !app.session) return;
  ImportPickerState& p = app.project.import;
  const bool idle = !app.task.running() && !app.session->read_only();
  if (!p.open) {
    if (app.targets.button("Import a 3D image", 0, idle)) {
      p.open = true;
      look(app);
    }
    return;
  }
  ImGui::Separator();
  heading("Import a 3D image");
  paragraph("A scan or a model made elsewhere becomes a new visit (" +
            storage::imported_surface_extensions() + ").");
  if (app.targets.button_in_row("Look again", idle)) look(app);
  if (app.targets.button_in_row("Close the list")) p.open = false;
  ImGui::PushStyleVar(ImGuiStyleVar_ButtonTextAlign, ImVec2(0, 0.5f));
  for (const ImportPickerPlace& place : p.places) {
    label(place.label + ":");
    if (place.files.empty()) note("No 3D image files here.");
    for (std::size_t i = 0; i < place.files.size(); ++i) {
      const ImportPickerFile& f = place.files[i];
      const std::string text = f.shown + ", " + f.format + ", " + size_words(f.bytes);
      const std::string shown =
          shortened(text, ImGui::GetContentRegionAvail().x - 2 * ImGui::GetStyle().FramePadding.x);
      const bool tapped =
          app.targets.button(shown + "##import " + place.label + std::to_string(i), -1, idle);
      // Scripts name a file by its path under the folder.
      app.targets.record("Import " + f.shown, ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                         idle);
      if (tapped) {
        const ImportPickerFile chosen = f;  // the list may be read again
        ImGui::PopStyleVar();
        start_import(app, chosen);
        return;
      }
    }
    if (place.more) note("More files than listed: put the one to import nearer the top.");
  }
  ImGui::PopStyleVar();
}

}  // namespace rockface::ui
