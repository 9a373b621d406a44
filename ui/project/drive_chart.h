#pragma once
// Issue 39: the joints along the drive on the Project screen, drawn with the
// tablet's own font at the screen's size (not a print picture scaled down):
// two panels against chainage, dip direction above and dip below; every
// placed visit's measured joints as open rings, the sets where the joints
// form them as coloured tracks, a set that turned ringed in black; the title
// on its own line above the panels, the legend beside them.
#include "ui/app/field_services.h"
#include "ui/widgets/widgets.h"

namespace rockface::ui {

struct DriveChartDrawn {
  int joint_marks = 0;  // joints drawn (each in both panels, counted once)
  int set_marks = 0;    // set points drawn (likewise)
};

// Draws at the cursor, `width` px wide; returns what it drew.
DriveChartDrawn draw_drive_chart(const DriveJoints& drive, float width);

}  // namespace rockface::ui
