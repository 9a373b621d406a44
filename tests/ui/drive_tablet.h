#pragma once
// The tablet at 1280 x 800 on a tunnel-drive project (drive_project.h), with
// the field workflows' runners and no sync or camera: the set-up of the
// tablet's tunnel suites (wedges, support, drive chart, excavation).
#include <filesystem>

#include "firmware-app/services/ui_services.h"
#include "ui/platform/headless_session.h"

namespace rockface::test {

inline ui::UiOptions drive_tablet_options(const std::filesystem::path& project) {
  ui::UiOptions options;
  options.project = project;
  options.max_display_triangles = 20000;
  return options;
}

inline ui::FieldServices drive_tablet_services(app::FieldRunners& runners) {
  ui::FieldServices services = runners.services();
  services.sync = nullptr;
  services.camera = nullptr;
  return services;
}

struct DriveTablet {
  explicit DriveTablet(const std::filesystem::path& project)
      : session(drive_tablet_options(project), drive_tablet_services(runners), 1280, 800) {
    session.settle();
  }
  // A screen's view: its tab and the view's button tapped, then the frames
  // run until the tablet is idle.
  void show(const char* screen, const char* view) {
    session.tap(screen);
    session.tap(view);
    session.settle();
  }
  // The Blocks screen's Wedges view with its wedges found on the visit.
  void find_wedges() {
    session.tap("Blocks");
    session.tap("Wedges view");
    session.tap("Find wedges");
    session.settle();
  }

  app::FieldRunners runners{""};  // before the session, which holds its runners
  ui::HeadlessSession session;
};

}  // namespace rockface::test
