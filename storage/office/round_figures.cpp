#include "storage/office/round_figures.h"

namespace rockface::storage::office {

namespace {

// The kinds whose records a round's figures are read from: the round's
// own (its surface is its models' meshes, its place its placement) and the
// tunnel's (the design and the datum). visit_uuid is NULL for the latter.
constexpr const char* kRoundKinds = "{project,tunnel,visit,capture,model,visit_placement}";

}  // namespace

std::map<std::string, std::string> round_inputs(Connection& c, std::int64_t tunnel_id) {
  const Result r = c.query(
      "SELECT coalesce(visit_uuid::text, ''), "
      "md5(string_agg(kind || ' ' || uuid::text || ' ' || content_sha256, ',' "
      "ORDER BY kind, uuid)) "
      "FROM (SELECT DISTINCT ON (kind, uuid) kind, uuid, visit_uuid, content_sha256, deleted "
      "FROM rockface.record WHERE tunnel_id = $1 AND kind = ANY($2::text[]) "
      "ORDER BY kind, uuid, revision DESC) latest WHERE NOT deleted GROUP BY visit_uuid",
      {Param::of(tunnel_id), Param::of(std::string(kRoundKinds))}, "reading the rounds' inputs");
  std::string tunnel_part;
  std::map<std::string, std::string> visits;
  for (int i = 0; i < r.rows(); ++i) {
    if (r.text(i, 0).empty())
      tunnel_part = r.text(i, 1);
    else
      visits[r.text(i, 0)] = r.text(i, 1);
  }
  for (auto& [uuid, inputs] : visits) inputs = "tunnel " + tunnel_part + ", visit " + inputs;
  return visits;
}

std::set<std::string> visits_synced_after(Connection& c, std::int64_t tunnel_id,
                                          const std::string& synced_at) {
  const Result r = c.query(
      "SELECT DISTINCT coalesce(visit_uuid::text, '') FROM rockface.record WHERE tunnel_id = $1 "
      "AND synced_at > coalesce(nullif($2, '')::timestamptz, '-infinity')",
      {Param::of(tunnel_id), Param::of(synced_at)}, "reading what the tablets synced");
  std::set<std::string> out;
  for (int i = 0; i < r.rows(); ++i) out.insert(r.text(i, 0));
  return out;
}

std::map<std::string, KeptRound> read_kept_rounds(Connection& c, std::int64_t tunnel_id) {
  // Row-level security: the figures of visits the role may read.
  const Result r = c.query(
      "SELECT f.visit_uuid::text, f.inputs, f.figures::text FROM rockface.round_figures f "
      "JOIN rockface.visit v ON v.uuid = f.visit_uuid WHERE v.tunnel_id = $1",
      {Param::of(tunnel_id)}, "reading the rounds' kept figures");
  std::map<std::string, KeptRound> out;
  for (int i = 0; i < r.rows(); ++i) out[r.text(i, 0)] = {r.text(i, 1), r.text(i, 2)};
  return out;
}

void keep_rounds(Connection& c, const std::map<std::string, KeptRound>& rounds,
                 const std::string& role) {
  if (rounds.empty()) return;
  c.query("SELECT set_config('role', 'rockface_web', false)", {}, "keeping the rounds' figures");
  try {
    c.exec("BEGIN READ WRITE", "keeping the rounds' figures");
    for (const auto& [uuid, kept] : rounds)
      c.query("SELECT rockface.keep_round_figures($1::uuid, $2, $3::jsonb)",
              {Param::of(uuid), Param::of(kept.inputs), Param::of(kept.figures)},
              "keeping the figures of visit " + uuid);
    c.exec("COMMIT", "keeping the rounds' figures");
  } catch (...) {
    try {
      c.exec("ROLLBACK", "keeping the rounds' figures");
      c.query("SELECT set_config('role', $1, false)", {Param::of(role)}, "acting as " + role);
    } catch (...) {
      // The connection is closed by the pool when it comes back unusable.
    }
    throw;
  }
  c.query("SELECT set_config('role', $1, false)", {Param::of(role)}, "acting as " + role);
}

}  // namespace rockface::storage::office
