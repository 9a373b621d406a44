#pragma once
// Tables as the tablet draws them: the header row's names go through the
// text record (ImGui's TableHeadersRow draws them unseen by the walk, and
// shortens a name too long for its column with its own "…"), and a row
// the geologist taps is a thumb target recorded with the touch targets.
#include <string>

#include "ui/widgets/widgets.h"

namespace rockface::ui {

// The header row of the current table, from its TableSetupColumn names:
// each name drawn in its column and recorded with the column's width.
void table_headers_row();

// A row a tap selects: a selectable spanning every column, `targets`'
// target edge high, recorded as touch target `name`. Call after
// TableNextRow and TableNextColumn; the row's first cell follows on the
// same line. True when tapped.
bool selectable_row(TouchTargets& targets, const std::string& name, bool selected);

}  // namespace rockface::ui
