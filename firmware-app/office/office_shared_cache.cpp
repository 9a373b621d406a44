#include "firmware-app/office/office_shared_cache.h"

#include <optional>
#include <system_error>

#include "core/common/error.h"
#include "core/common/progress.h"
#include "firmware-app/office/test_gate.h"
#include "firmware-app/office/web_security.h"
#include "storage/office/pull_project.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"

namespace rockface::app::office_web {

namespace office = storage::office;

ReadableTunnels readable_tunnels(office::Connection& c) {
  // Row-level security answers: the tunnels this role may read, no more.
  const office::Result r =
      c.query("SELECT id, name FROM rockface.tunnel ORDER BY id", {}, "reading the tunnels");
  ReadableTunnels out;
  for (int i = 0; i < r.rows(); ++i) {
    out.key += (i ? "," : "") + std::to_string(r.int64(i, 0));
    out.by_name[r.text(i, 1)] = r.int64(i, 0);
  }
  return out;
}

namespace {

// The drive's faces (round_start.h's drive_faces, as a copy of the whole
// tunnel gives them) from the visits read beside a copy of some visits:
// the tunnel's drive direction from the copy's tunnel record.
DriveFaces drive_faces_of(const std::filesystem::path& copy,
                          const std::vector<office::ServerDriveVisit>& visits) {
  DriveFaces out;
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(copy, read);
  if (const auto tunnel = store.load_tunnel()) out.tunnel_drive = tunnel->drive;
  for (const auto& v : visits)
    if (!v.heading.empty()) out.headings[v.pulled_id] = v.heading;
  for (const auto& v : visits)
    if (v.chainage) out.faces.push_back({v.pulled_id, *v.chainage, v.heading, v.started_at});
  return out;
}

}  // namespace

SharedPull::~SharedPull() {
  std::error_code ec;
  std::filesystem::remove(file, ec);
}

SharedOfficeCache::SharedOfficeCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

template <typename Entry>
std::shared_ptr<Entry> SharedOfficeCache::entry(std::map<std::string, std::shared_ptr<Entry>>& map,
                                                const std::string& key, std::size_t limit) {
  std::lock_guard guard(lock_);
  auto& e = map[key];
  if (!e) {
    e = std::make_shared<Entry>();
    // The least recently used goes; a session still reading it keeps its
    // own reference until it is done.
    while (map.size() > limit) {
      auto oldest = map.end();
      for (auto it = map.begin(); it != map.end(); ++it)
        if (it->first != key && (oldest == map.end() || it->second->used < oldest->second->used))
          oldest = it;
      map.erase(oldest);
    }
  }
  e->used = ++clock_;
  return e;
}

std::pair<std::string, std::string> SharedOfficeCache::checked_stamp(RequestConnection& db,
                                                                     const std::string& tunnel) {
  const ReadableTunnels readable = readable_tunnels(db.db());
  // The same answer as for a tunnel that does not exist.
  if (!readable.by_name.count(tunnel))
    throw InputError("tunnel " + tunnel, "no such tunnel for this log-in");
  const std::string key = readable.key + '\n' + tunnel;
  const auto now = std::chrono::steady_clock::now();
  {
    std::lock_guard guard(lock_);
    const auto it = stamps_.find(key);
    if (it != stamps_.end() && now - it->second.asked < kStampFresh) return {key, it->second.value};
  }
  const std::string value = tunnel_stamp(db.db(), tunnel);
  std::lock_guard guard(lock_);
  stamps_[key] = {value, now};
  return {key, value};
}

std::string SharedOfficeCache::stamp(RequestConnection& db, const std::string& tunnel) {
  return checked_stamp(db, tunnel).second;
}

std::string SharedOfficeCache::drive(RequestConnection& db, const std::string& tunnel,
                                     const DriveFilter& filter) {
  const auto checked = checked_stamp(db, tunnel);
  const std::string& key = checked.first;
  const std::string& stamp = checked.second;
  const auto page = entry(
      pages_,
      key + '\n' + filter.from + '\n' + filter.to + '\n' + filter.tablet + '\n' + filter.heading,
      kDrivePages);
  auto current = [&]() -> std::optional<std::string> {
    std::lock_guard guard(page->data);
    if (!page->json.empty() && page->stamp == stamp) return page->json;
    return std::nullopt;
  };
  if (auto ready = current()) return *ready;
  std::unique_lock build(page->build, std::try_to_lock);
  if (!build.owns_lock()) {
    {
      std::lock_guard guard(page->data);
      if (!page->json.empty()) return page->json;  // an older state, while the build runs
    }
    // Nothing to show yet: wait for the build under way, the connection
    // back in the pool meanwhile.
    db.release();
    build.lock();
    if (auto ready = current()) return *ready;
  }
  // Built on this request's connection: its role reads the same tunnels as
  // every session that shares the key.
  DriveRead read = read_drive_page(db.db(), tunnel, filter);
  // The sets are tracked along the drive without the connection.
  db.release();
  nlohmann::json built = drive_page(std::move(read));
  // The stamp the page polls against is the one it is kept under.
  built["stamp"] = stamp;
  std::string text = built.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard guard(page->data);
  page->stamp = stamp;
  page->json = text;
  return text;
}

std::shared_ptr<const SharedPull> SharedOfficeCache::pulled(RequestConnection& db,
                                                            const std::string& tunnel,
                                                            const PullScope& scope) {
  const auto [key, stamp] = checked_stamp(db, tunnel);
  std::string scoped = key + (scope.photographs ? "" : "\nwithout photographs") +
                       (scope.meshes ? "" : "\nwithout meshes");
  for (const std::string& v : scope.visits) scoped += "\nvisit " + v;
  const auto pull = scope.visits.empty() ? entry(pulls_, scoped, kPulledCopies)
                                         : entry(visit_pulls_, scoped, kVisitCopies);
  std::unique_lock build(pull->build, std::try_to_lock);
  if (!build.owns_lock()) {
    // Another request builds this copy: wait for it without a connection.
    db.release();
    build.lock();
  }
  if (pull->copy && pull->copy->stamp == stamp && std::filesystem::exists(pull->copy->file)) {
    db.release();
    return pull->copy;
  }
  pull->copy = make_copy(db, tunnel, stamp, scope);
  return pull->copy;
}

std::shared_ptr<const SharedPull> SharedOfficeCache::pulled_once(RequestConnection& db,
                                                                 const std::string& tunnel,
                                                                 const PullScope& scope) {
  return make_copy(db, tunnel, checked_stamp(db, tunnel).second, scope);
}

std::shared_ptr<const SharedPull> SharedOfficeCache::make_copy(RequestConnection& db,
                                                               const std::string& tunnel,
                                                               const std::string& stamp,
                                                               const PullScope& scope) {
  std::filesystem::create_directories(folder_);
  auto copy = std::make_shared<SharedPull>();
  copy->file = folder_ / ("tunnel-" + random_token().substr(0, 32) + ".rockface");
  copy->stamp = stamp;
  NoProgress quiet;
  office::PullOptions options;
  options.photographs = scope.photographs;
  options.meshes = scope.meshes;
  options.visits = scope.visits;
  // The server's rows and blobs in one snapshot; then the connection goes
  // back to the pool while the copy is built (no database needed).
  office::PullRead read = office::read_pull(db.db(), tunnel, copy->file, quiet, options);
  db.release();
  test_gate("copy-build");
  {
    CpuSlots::Slot slot(cpu_slots_);
    office::build_pulled_project(read, quiet);
  }
  {
    storage::sqlite::Connection db(copy->file, storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement st(db, "SELECT id, uuid FROM visit WHERE uuid IS NOT NULL",
                                  "reading the pulled visits' uuids");
    while (st.step()) copy->visit_ids[st.column_text(1)] = st.column_int(0);
  }
  if (!scope.visits.empty()) copy->drive = drive_faces_of(copy->file, read.drive_visits);
  return copy;
}

}  // namespace rockface::app::office_web
