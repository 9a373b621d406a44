#pragma once
// A change the geologist makes to the chosen class for one round (issue
// 44), as typed: `--change "bolt spacing: 1.5 m -> 1.2 m: wedge W3 below
// FoS 1.5"` on the command line, four fields on the tablet. Each change
// names what was changed, from what to what, and why; one without any of
// them is refused (the decision's record must stand on its own).
#include <string>

#include "core/analysis/support_decision.h"

namespace rockface::app {

// "WHAT: FROM -> TO: REASON" (spaces around the fields trimmed; the reason
// may hold further colons). Throws InputError(where) naming the missing
// part.
analysis::SupportChange parse_support_change(const std::string& text, const std::string& where);

// Throws InputError(where) when a field is empty.
void require_complete(const analysis::SupportChange& change, const std::string& where);

// "bolt spacing 1.5 m -> 1.2 m (wedge W3 below FoS 1.5)"
std::string support_change_words(const analysis::SupportChange& change);

}  // namespace rockface::app
