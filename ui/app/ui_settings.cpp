#include "ui/app/ui_settings.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "storage/project/visit_geologist.h"

namespace rockface::ui {

std::filesystem::path default_settings_file() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "rockface" / "ui.json";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config" / "rockface" / "ui.json";
  return {};
}

UiSettings load_ui_settings(const std::filesystem::path& file) {
  UiSettings settings;
  if (file.empty() || !std::filesystem::exists(file)) return settings;
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const auto j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(file.string(), "not a JSON object");
  if (j.contains("theme")) {
    const auto theme =
        j["theme"].is_string() ? theme_from_name(j["theme"].get<std::string>()) : std::nullopt;
    if (!theme) throw InputError(file.string() + ": theme", "expected \"daylight\" or \"tunnel\"");
    settings.theme = *theme;
  }
  if (j.contains("geologist")) {
    if (!j["geologist"].is_string())
      throw InputError(file.string() + ": geologist", "expected a name (text)");
    settings.geologist = storage::checked_geologist(j["geologist"].get<std::string>(),
                                                    file.string() + ": geologist");
  }
  return settings;
}

void save_ui_settings(const std::filesystem::path& file, const UiSettings& settings) {
  if (file.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  nlohmann::json j{{"theme", theme_name(settings.theme)}};
  if (!settings.geologist.empty()) j["geologist"] = settings.geologist;
  write_text_atomically(file, j.dump(2) + "\n");
}

}  // namespace rockface::ui
