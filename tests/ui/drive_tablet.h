#pragma once
// The tablet (field_tablet.h) on a tunnel-drive project (drive_project.h):
// the set-up of the tablet's tunnel suites (wedges, support, drive chart,
// excavation), with the taps they share.
#include <filesystem>

#include "tests/ui/field_tablet.h"

namespace rockface::test {

struct DriveTablet : FieldTablet {
  explicit DriveTablet(const std::filesystem::path& project) : FieldTablet(project) {}
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
};

}  // namespace rockface::test
