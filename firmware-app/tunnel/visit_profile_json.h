#pragma once
// A visit's profile in numbers (`rockface profile --json`): the tunnel, how
// the visit was placed, the round, and per cross-section the over- and
// underbreak areas, with the volumes of the round, the deepest underbreak
// and where it is, and the underbreak beyond tolerance.
#include <string>
#include <vector>

#include "firmware-app/tunnel/visit_profile.h"

namespace rockface::app {

std::string visit_profile_json(const VisitProfile& profile);

// The summary lines the verb prints and the tablet shows.
std::vector<std::string> visit_profile_summary(const VisitProfile& profile);

}  // namespace rockface::app
