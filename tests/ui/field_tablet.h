#pragma once
// The tablet at 1280 x 800 with the field workflows' runners (the
// program's own services) and no sync or camera, settled on its project:
// the set-up of the suites that work a screen as the geologist does (the
// pole and north entries, the import picker; the tunnel suites through
// drive_tablet.h).
#include <filesystem>

#include "firmware-app/services/ui_services.h"
#include "ui/platform/headless_session.h"

namespace rockface::test {

// A decimated model: the software renderer's cost.
inline ui::UiOptions field_tablet_options(const std::filesystem::path& project) {
  ui::UiOptions options;
  options.project = project;
  options.max_display_triangles = 20000;
  return options;
}

inline ui::FieldServices field_tablet_services(app::FieldRunners& runners) {
  ui::FieldServices services = runners.services();
  services.sync = nullptr;
  services.camera = nullptr;
  return services;
}

struct FieldTablet {
  explicit FieldTablet(const ui::UiOptions& options)
      : session(options, field_tablet_services(runners), 1280, 800) {
    session.settle();
  }
  explicit FieldTablet(const std::filesystem::path& project)
      : FieldTablet(field_tablet_options(project)) {}

  app::FieldRunners runners{""};  // before the session, which holds its runners
  ui::HeadlessSession session;
};

}  // namespace rockface::test
