#pragma once
// The rounds along the drive with each round's over- and underbreak kept
// on the office server (issue 46: the first rounds request of a
// 3,000-visit drive measured 3,000 meshes, 753 s; storage/office/
// round_figures.h). The rounds' rock mass and support are read from a copy
// of the drive without photographs or meshes, their over- and underbreak
// as kept; only rounds with no figures kept for their current inputs (new
// or re-synced visits, a new design, an earlier face placed since) are
// measured, on a copy with meshes, and kept for every later request and
// every later server. office_rounds_worker.h runs these in the background.
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "firmware-app/office/office_shared_cache.h"
#include "storage/office/connection_pool.h"
#include "storage/office/pg_connection.h"

namespace rockface::app::office_web {

// A drive's rounds without their over- and underbreak, and what each
// round's figures rest on.
struct RoundsBase {
  std::string stamp;    // of the copy they were read from
  nlohmann::json page;  // office_rounds.h's rounds_page, no excavation keys
  // By visit uuid: the kept figures that still hold, the round's inputs now
  // (read before the copy: older inputs only make a round measured again
  // later), the rounds to measure.
  std::map<std::string, nlohmann::json> figures;
  std::map<std::string, std::string> inputs;
  std::vector<std::string> to_measure;
};

// Read on `db` (acting as the person's role) from the shared copy without
// photographs or meshes; `db` goes back to the pool once the copy's rows
// are read, before the rounds are worked out. Throws InputError when the
// role may not read the tunnel.
RoundsBase read_rounds_base(SharedOfficeCache& cache, RequestConnection& db,
                            const std::string& tunnel);

// Measures `base.to_measure` on a copy with meshes (photographs left out)
// and keeps their figures on the server, a batch at a time: `connect`
// lends a connection acting as `role` for each step that needs the server
// (never across a measurement), `measured` hears each batch's figures (by
// visit uuid), `stopping` is asked between rounds, `log` hears a failure to
// keep figures (the figures are shown all the same).
void measure_rounds(
    SharedOfficeCache& cache, const std::function<RequestConnection()>& connect,
    const std::string& tunnel, const std::string& role, const RoundsBase& base,
    const std::function<void(const std::map<std::string, nlohmann::json>&)>& measured,
    const std::function<bool()>& stopping, const std::function<void(const std::string&)>& log);

// The rounds page: `base`'s rounds with their figures where in `figures`;
// the others marked `"measuring": true` ("being measured…"), their count
// in the page's "measuring".
nlohmann::json rounds_with_figures(const nlohmann::json& base,
                                   const std::map<std::string, nlohmann::json>& figures);

// The rounds after a sync, before the drive is read again: each placed
// visit of `drive` (office_pages.h's drive_page at the new state) with its
// round as shown before (`base` with `figures`), unless `changed` (visits
// whose records a sync wrote since, visits_synced_after) names it or it
// was not a round then — those "measuring" as in rounds_being_read. The
// page's "reading" true: the worker reads the drive again. A sync that
// changed the tunnel's or a project's own records ("" in `changed`) shows
// when the drive has been read again (every round may then change; the
// rounds stay shown as they were meanwhile, never blank).
nlohmann::json rounds_after_sync(const nlohmann::json& base,
                                 const std::map<std::string, nlohmann::json>& figures,
                                 const nlohmann::json& drive, const std::set<std::string>& changed);

// The rounds as the drive page lists them before their copy was read
// (office_pages.h's drive_page: each placed visit by chainage), every one
// "measuring", the page's "reading" true.
nlohmann::json rounds_being_read(const nlohmann::json& drive);

}  // namespace rockface::app::office_web
