#include "firmware-app/office/office_round_figures.h"

#include <map>
#include <set>

#include "core/common/error.h"
#include "firmware-app/office/office_rounds.h"
#include "storage/office/round_figures.h"
#include "storage/project/project_store.h"

namespace rockface::app::office_web {

namespace office = storage::office;
using nlohmann::json;

namespace {

storage::ProjectStore open_copy(const SharedPull& copy) {
  storage::OpenOptions read;
  read.read_only = true;
  return storage::ProjectStore::open(copy.file, read);
}

std::map<storage::RecordId, std::string> uuids_of(const SharedPull& copy) {
  std::map<storage::RecordId, std::string> out;
  for (const auto& [uuid, id] : copy.visit_ids) out[id] = uuid;
  return out;
}

}  // namespace

std::string kept_rounds_page(SharedOfficeCache& cache, office::Connection& db,
                             const std::string& tunnel, const std::string& role,
                             const std::function<void(const std::string&)>& log,
                             RoundsCount* count) {
  PullScope figures_only;
  figures_only.photographs = false;
  figures_only.meshes = false;
  const auto copy = cache.pulled(db, tunnel, figures_only);
  std::lock_guard guard(copy->derived_lock);
  std::string& text = copy->derived["rounds"];
  if (!text.empty()) return text;

  const auto readable = readable_tunnels(db);
  const auto id = readable.by_name.find(tunnel);
  if (id == readable.by_name.end())
    throw InputError("tunnel " + tunnel, "no such tunnel for this log-in");
  // Read before the copy the rounds are measured on: inputs older than
  // that copy only make a round measured again later; the copy older than
  // the inputs is caught by its stamp below.
  const std::map<std::string, std::string> inputs = office::round_inputs(db, id->second);
  std::map<std::string, office::KeptRound> kept = office::read_kept_rounds(db, id->second);

  storage::ProjectStore store = open_copy(*copy);
  const auto uuids = uuids_of(*copy);
  const auto placements = store.list_visit_placements();
  auto uuid_of = [&](storage::RecordId v) {
    const auto it = uuids.find(v);
    return it == uuids.end() ? std::string() : it->second;
  };
  // The rounds whose kept figures hold: same inputs, same earlier face.
  std::map<std::string, json> figures;
  std::set<std::string> to_measure;
  for (const auto& p : placements) {
    const std::string uuid = uuid_of(p.visit_id);
    const auto k = kept.find(uuid);
    const auto in = inputs.find(uuid);
    if (k != kept.end() && in != inputs.end() && k->second.inputs == in->second) {
      json f = json::parse(k->second.figures);
      if (kept_excavation_holds(f, placements, p.visit_id)) {
        figures[uuid] = std::move(f);
        continue;
      }
    }
    to_measure.insert(uuid);
  }

  if (!to_measure.empty()) {
    // Measured on a copy with the meshes, photographs still left out: after
    // a sync, of the visits to measure only (with the drive's placements,
    // where each round starts), used once; when most of the drive is to
    // be measured, of the whole drive, shared.
    PullScope with_meshes;
    with_meshes.photographs = false;
    const bool most = to_measure.size() * 2 > placements.size();
    if (!most) with_meshes.visits.assign(to_measure.begin(), to_measure.end());
    const auto meshes =
        most ? cache.pulled(db, tunnel, with_meshes) : cache.pulled_once(db, tunnel, with_meshes);
    storage::ProjectStore measured_store = open_copy(*meshes);
    std::map<std::string, office::KeptRound> fresh;
    for (const std::string& uuid : to_measure) {
      const auto v = meshes->visit_ids.find(uuid);
      if (v == meshes->visit_ids.end()) continue;  // synced away between the two copies
      json f = round_excavation(measured_store, v->second);
      const auto in = inputs.find(uuid);
      if (in != inputs.end())
        fresh[uuid] = {in->second, f.dump(-1, ' ', false, json::error_handler_t::replace)};
      figures[uuid] = std::move(f);
    }
    try {
      // Kept only when nothing synced since the copy was pulled (its
      // stamp, asked of the server now, not the shared second-old one).
      if (tunnel_stamp(db, tunnel) == meshes->stamp)
        office::keep_rounds(db, fresh, role);
      else
        log("the rounds' figures of tunnel " + tunnel + " not kept: a tablet synced meanwhile");
    } catch (const std::exception& e) {
      log(std::string("keeping the rounds' figures: ") + e.what());
    }
  }
  if (count) {
    count->measured = static_cast<int>(to_measure.size());
    count->kept = static_cast<int>(figures.size()) - count->measured;
  }
  text = rounds_page(store, uuid_of, [&](storage::RecordId v) {
           const auto it = figures.find(uuid_of(v));
           return it == figures.end() ? json{{"excavation_text", "not evaluated: synced meanwhile"}}
                                      : it->second;
         }).dump(-1, ' ', false, json::error_handler_t::replace);
  return text;
}

}  // namespace rockface::app::office_web
