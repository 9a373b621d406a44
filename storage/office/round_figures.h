#pragma once
// Each round's over- and underbreak kept on the office server (schema
// version 3, rockface.round_figures; issue 46): computed once from a
// visit's 3D image and kept with the inputs it was computed from, so the
// office's rounds along a drive never measure a kept round again — not on
// a second request, not in a restarted web server. The inputs are the
// latest revisions of the records a round's figures are read from (the
// visit, its captures, models and placement; the tunnel's projects and
// tunnel records), by their content hashes: a new revision of any of them
// (a visit re-synced with a new 3D image or placement, a new design) gives
// other inputs, and the round is measured again.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "storage/office/pg_connection.h"

namespace rockface::storage::office {

// The inputs of every visit's round of the tunnel, by the visit's uuid, as
// the role `c` acts as may read them.
std::map<std::string, std::string> round_inputs(Connection& c, std::int64_t tunnel_id);

// The visits (uuids) of the tunnel with a record revision synced after
// `synced_at` (the server's timestamptz as text, e.g. the stamp's
// max(synced_at)): what a sync since brought or changed. A revision of a
// record of no visit (the tunnel, a project) adds "" to the set; an empty
// `synced_at` takes every revision. As the role `c` acts as may read them.
std::set<std::string> visits_synced_after(Connection& c, std::int64_t tunnel_id,
                                          const std::string& synced_at);

struct KeptRound {
  std::string inputs;
  std::string figures;  // JSON text, as kept
};
// The kept figures of the tunnel's visits the role may read, by visit uuid.
std::map<std::string, KeptRound> read_kept_rounds(Connection& c, std::int64_t tunnel_id);

// Keeps rounds' figures (visit uuid -> inputs and figures), in one
// transaction acting as the office web server's group (rockface_web: the
// connection's session role must be a member, as the web server's service
// role is), then acts as `role` again. A connection whose default
// transactions are read-only is fine: this one is read-write.
void keep_rounds(Connection& c, const std::map<std::string, KeptRound>& rounds,
                 const std::string& role);

}  // namespace rockface::storage::office
