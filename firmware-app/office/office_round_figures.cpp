#include "firmware-app/office/office_round_figures.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>

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

// A round's figures as shown: the page's keys of round_excavation's.
constexpr const char* kFigureKeys[] = {"excavation_text", "overbreak_m3", "underbreak_m3"};

// A batch of measured rounds is kept and shown after this many rounds or
// this long, whichever comes first: the page fills in while the rest are
// measured, and the server takes a few writes a minute, not one a round.
constexpr std::size_t kBatchRounds = 25;
constexpr std::chrono::seconds kBatchTime{5};

}  // namespace

RoundsBase read_rounds_base(SharedOfficeCache& cache, RequestConnection& db,
                            const std::string& tunnel) {
  const auto readable = readable_tunnels(db.db());
  const auto id = readable.by_name.find(tunnel);
  if (id == readable.by_name.end())
    throw InputError("tunnel " + tunnel, "no such tunnel for this log-in");
  RoundsBase out;
  // Read before the copy the rounds are measured on: inputs older than
  // that copy only make a round measured again later; the copy older than
  // the inputs is caught by its stamp when the figures are kept.
  out.inputs = office::round_inputs(db.db(), id->second);
  const std::map<std::string, office::KeptRound> kept =
      office::read_kept_rounds(db.db(), id->second);

  PullScope figures_only;
  figures_only.photographs = false;
  figures_only.meshes = false;
  const auto copy = cache.pulled(db, tunnel, figures_only);
  out.stamp = copy->stamp;
  std::map<storage::RecordId, std::string> uuids;
  for (const auto& [uuid, v] : copy->visit_ids) uuids[v] = uuid;
  auto uuid_of = [&](storage::RecordId v) {
    const auto it = uuids.find(v);
    return it == uuids.end() ? std::string() : it->second;
  };

  storage::ProjectStore store = open_copy(*copy);
  const auto placements = store.list_visit_placements();
  const auto tunnel_record = store.load_tunnel();
  const DriveFaces drive =
      drive_faces(store, tunnel_record ? tunnel_record->drive : tunnel::Drive::ascending);
  // The rounds whose kept figures hold: same inputs, same earlier face.
  for (const auto& p : placements) {
    const std::string uuid = uuid_of(p.visit_id);
    const auto k = kept.find(uuid);
    const auto in = out.inputs.find(uuid);
    if (k != kept.end() && in != out.inputs.end() && k->second.inputs == in->second) {
      json f = json::parse(k->second.figures);
      if (kept_excavation_holds(f, drive, p.visit_id)) {
        out.figures[uuid] = std::move(f);
        continue;
      }
    }
    out.to_measure.push_back(uuid);
  }
  out.page = rounds_page(store, uuid_of, [](storage::RecordId) { return json::object(); });
  return out;
}

void measure_rounds(SharedOfficeCache& cache, const std::function<RequestConnection()>& connect,
                    const std::string& tunnel, const std::string& role, const RoundsBase& base,
                    const std::function<void(const std::map<std::string, json>&)>& measured,
                    const std::function<bool()>& stopping,
                    const std::function<void(const std::string&)>& log) {
  if (base.to_measure.empty()) return;
  // Measured on a copy with the meshes, photographs still left out: after
  // a sync, of the visits to measure only (with the drive's placements,
  // where each round starts), used once; when most of the drive is to be
  // measured, of the whole drive, shared.
  PullScope with_meshes;
  with_meshes.photographs = false;
  const bool most = base.to_measure.size() * 2 > base.figures.size() + base.to_measure.size();
  if (!most) with_meshes.visits = base.to_measure;
  std::shared_ptr<const SharedPull> meshes;
  {
    auto lease = connect();
    meshes = most ? cache.pulled(lease, tunnel, with_meshes)
                  : cache.pulled_once(lease, tunnel, with_meshes);
  }
  std::optional<storage::ProjectStore> store = open_copy(*meshes);
  const std::string stamp = meshes->stamp;
  // Every round's start read from one reading of the drive's faces.
  const auto tunnel_record = store->load_tunnel();
  const DriveFaces drive =
      drive_faces(*store, tunnel_record ? tunnel_record->drive : tunnel::Drive::ascending);

  std::map<std::string, json> shown;
  std::map<std::string, office::KeptRound> fresh;
  auto keep = [&] {
    if (fresh.empty()) return;
    try {
      auto lease = connect();
      // Kept only when nothing synced since the copy was pulled (its
      // stamp, asked of the server now, not the shared second-old one).
      if (tunnel_stamp(lease.db(), tunnel) == stamp)
        office::keep_rounds(lease.db(), fresh, role);
      else
        log("the rounds' figures of tunnel " + tunnel + " not kept: a tablet synced meanwhile");
    } catch (const std::exception& e) {
      log(std::string("keeping the rounds' figures: ") + e.what());
    }
    fresh.clear();
  };
  auto batch_start = std::chrono::steady_clock::now();
  for (const std::string& uuid : base.to_measure) {
    if (stopping()) return;
    const auto v = meshes->visit_ids.find(uuid);
    json f;
    if (v == meshes->visit_ids.end()) {
      // Synced away between the two copies: the next copy has it right.
      f["excavation_text"] = "not evaluated: synced meanwhile";
    } else {
      try {
        f = round_excavation(*store, v->second, &drive);
        const auto in = base.inputs.find(uuid);
        if (in != base.inputs.end())
          fresh[uuid] = {in->second, f.dump(-1, ' ', false, json::error_handler_t::replace)};
      } catch (const std::exception& e) {
        // Shown, not kept: the next server tries again; the other rounds go
        // on being measured (a bad round never holds up the rest).
        f = json{{"excavation_text", std::string("not evaluated: ") + e.what()}};
        log("measuring the round of visit " + uuid + ": " + e.what());
      }
    }
    shown[uuid] = std::move(f);
    if (shown.size() >= kBatchRounds ||
        std::chrono::steady_clock::now() - batch_start >= kBatchTime) {
      keep();
      measured(shown);
      shown.clear();
      batch_start = std::chrono::steady_clock::now();
    }
  }
  keep();
  // A copy made for these rounds alone is gone before the last batch is
  // shown: a page that has every round finds no copy left behind.
  store.reset();
  meshes.reset();
  if (!shown.empty()) measured(shown);
}

json rounds_with_figures(const json& base, const std::map<std::string, json>& figures) {
  json out = base;
  int measuring = 0;
  for (json& round : out["rounds"]) {
    const auto f = figures.find(round.value("visit", ""));
    if (f == figures.end()) {
      round["measuring"] = true;
      round["excavation_text"] = "being measured…";
      ++measuring;
      continue;
    }
    for (const char* key : kFigureKeys)
      if (f->second.contains(key)) round[key] = f->second.at(key);
  }
  out["measuring"] = measuring;
  return out;
}

json rounds_being_read(const json& drive) {
  std::vector<const json*> placed;
  for (const json& v : drive.at("visits"))
    if (v.contains("chainage")) placed.push_back(&v);
  // By chainage, as the rounds are listed once read.
  std::stable_sort(placed.begin(), placed.end(), [](const json* a, const json* b) {
    return a->at("chainage").get<double>() < b->at("chainage").get<double>();
  });
  json rounds = json::array();
  for (const json* v : placed) {
    json round;
    round["visit"] = v->at("id");
    round["chainage"] = v->at("chainage");
    round["chainage_text"] = v->at("chainage_text");
    for (const char* key : {"rmr_text", "q_text", "proposed", "decided"}) round[key] = "reading…";
    round["decided_by"] = "";
    round["excavation_text"] = "being measured…";
    round["measuring"] = true;
    rounds.push_back(std::move(round));
  }
  json out;
  out["measuring"] = static_cast<int>(rounds.size());
  out["rounds"] = std::move(rounds);
  out["reading"] = true;
  return out;
}

json rounds_after_sync(const json& base, const std::map<std::string, json>& figures,
                       const json& drive, const std::set<std::string>& changed) {
  const json shown = rounds_with_figures(base, figures);
  std::map<std::string, const json*> before;
  for (const json& round : shown.at("rounds")) {
    const std::string uuid = round.value("visit", "");
    if (!uuid.empty()) before[uuid] = &round;
  }
  json out = rounds_being_read(drive);
  int measuring = 0;
  for (json& round : out["rounds"]) {
    const std::string uuid = round.value("visit", "");
    const auto it = before.find(uuid);
    // Moved along the drive: read again.
    if (it != before.end() && !changed.count(uuid) &&
        it->second->value("chainage", 0.0) == round.value("chainage", 0.0))
      round = *it->second;
    if (round.value("measuring", false)) ++measuring;
  }
  out["measuring"] = measuring;
  return out;
}

}  // namespace rockface::app::office_web
