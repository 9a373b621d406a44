#pragma once
// The rounds along the drive with each round's over- and underbreak kept
// on the office server (issue 46: the first rounds request of a
// 3,000-visit drive measured 3,000 meshes, 753 s; storage/office/
// round_figures.h). A request reads the rock mass and support from a copy
// of the drive without photographs or meshes and the over- and underbreak
// as kept; only rounds with no figures kept for their current inputs (new
// or re-synced visits, a new design, an earlier face placed since) are
// measured, on a copy with meshes, and kept for every later request and
// every later server.
#include <functional>
#include <string>

#include "firmware-app/office/office_shared_cache.h"
#include "storage/office/pg_connection.h"

namespace rockface::app::office_web {

struct RoundsCount {
  int kept = 0;      // rounds whose figures were read as kept
  int measured = 0;  // rounds measured for this page (and kept)
};

// The rounds page's JSON text (office_rounds.h) for the role `db` acts as
// (`role`: acted as again after the figures are kept). `log` hears a
// failure to keep figures (the page is served all the same).
std::string kept_rounds_page(SharedOfficeCache& cache, storage::office::Connection& db,
                             const std::string& tunnel, const std::string& role,
                             const std::function<void(const std::string&)>& log,
                             RoundsCount* count = nullptr);

}  // namespace rockface::app::office_web
