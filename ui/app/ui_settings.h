#pragma once
// What the tablet remembers between runs, per tablet and not per project:
// the theme (daylight or tunnel). A project file travels (to the office, to
// a colleague's tablet) and the light at one face says nothing about the
// next user's; so it lives in a settings file of the tablet,
// $XDG_CONFIG_HOME/rockface/ui.json (else ~/.config/rockface/ui.json),
// `{"theme": "tunnel", "geologist": "Anna Berger"}`. The geologist who
// carries the tablet is the tablet's too: each new visit begun on it takes
// that name, whichever project it is in.
#include <filesystem>
#include <string>

#include "ui/widgets/theme.h"

namespace rockface::ui {

struct UiSettings {
  Theme theme = Theme::daylight;
  // The geologist who uses this tablet (issue 46): set once, carried to
  // each new visit begun here; "" none (storage/project/visit_geologist.h).
  std::string geologist;
};

// The tablet's settings file; empty when neither XDG_CONFIG_HOME nor HOME
// is set (nothing is remembered then).
std::filesystem::path default_settings_file();

// Defaults when the file does not exist. Throws InputError naming the file
// and field when it exists but is not a settings file.
UiSettings load_ui_settings(const std::filesystem::path& file);
// Creates the folder; throws Error naming the file when it cannot write.
void save_ui_settings(const std::filesystem::path& file, const UiSettings& settings);

}  // namespace rockface::ui
