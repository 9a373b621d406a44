#include "firmware-app/office/office_rounds_worker.h"

#include <utility>

#include "core/common/error.h"
#include "firmware-app/office/office_round_figures.h"
#include "storage/office/round_figures.h"

namespace rockface::app::office_web {

namespace office = storage::office;
using nlohmann::json;

namespace {

std::string text_of(const json& page) {
  return page.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

RoundsWorker::RoundsWorker(SharedOfficeCache& cache, office::ConnectionPool& pool,
                           std::function<void(const std::string&)> log)
    : cache_(cache), pool_(pool), log_(std::move(log)) {
  thread_ = std::thread([this] { run(); });
}

RoundsWorker::~RoundsWorker() {
  {
    std::lock_guard guard(lock_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RoundsWorker::queue(const std::string& key, Drive& d) {
  // A full queue takes nothing more: the drive's next request asks again.
  if (d.queued || queue_.size() >= kQueued) return;
  d.queued = true;
  queue_.push_back(key);
  wake_.notify_one();
}

std::string RoundsWorker::page(RequestConnection& db, const std::string& tunnel,
                               const std::string& role, RoundsCount* count) {
  const ReadableTunnels readable = readable_tunnels(db.db());
  const auto tunnel_id = readable.by_name.find(tunnel);
  if (tunnel_id == readable.by_name.end())
    throw InputError("tunnel " + tunnel, "no such tunnel for this log-in");
  const std::string stamp = cache_.stamp(db, tunnel);
  const std::string key = readable.key + '\n' + tunnel;
  // The rounds as shown before a sync, while the worker reads the drive
  // again (below).
  std::optional<json> earlier;
  std::map<std::string, json> earlier_figures;
  std::string earlier_stamp;
  std::optional<std::set<std::string>> changed;
  int kept = 0, measured = 0;
  {
    std::lock_guard guard(lock_);
    if (!drives_.count(key)) {
      // The least recently asked drive goes, unless the worker has it.
      while (drives_.size() >= kDrives) {
        auto oldest = drives_.end();
        for (auto it = drives_.begin(); it != drives_.end(); ++it)
          if (!it->second.queued &&
              (oldest == drives_.end() || it->second.used < oldest->second.used))
            oldest = it;
        if (oldest == drives_.end()) break;
        drives_.erase(oldest);
      }
    }
    Drive& d = drives_[key];
    d.used = ++clock_;
    if (d.stamp != stamp) {
      // A tablet synced: read again (a worker under way on the older state
      // queues the drive again when it sees the stamp moved). The rounds
      // read so far stay shown meanwhile, but for the visits the sync
      // brought or changed.
      d.stamp = stamp;
      d.text.clear();
      d.changed.reset();
    }
    d.tunnel = tunnel;
    d.role = role;
    if (!d.text.empty()) {
      if (count) *count = {d.kept, d.measured, 0};
      return d.text;
    }
    if (d.base && d.base_stamp == d.stamp) {
      const json page = rounds_with_figures(*d.base, d.figures);
      const int measuring = page.at("measuring").get<int>();
      if (count) *count = {d.kept, d.measured, measuring};
      std::string text = text_of(page);
      if (measuring == 0)
        d.text = text;
      else
        queue(key, d);  // a run that failed is run again; one under way is left to go on
      return text;
    }
    queue(key, d);
    if (d.base) {
      earlier = d.base;
      earlier_figures = d.figures;
      earlier_stamp = d.base_stamp;
      changed = d.changed;
      kept = d.kept;
      measured = d.measured;
    }
  }
  // Not read at this stamp yet: the drive page's placed visits (shared,
  // built once per sync) stand for the rounds meanwhile.
  const json drive = json::parse(cache_.drive(db, tunnel, {}));
  // The rounds are put together without the connection (leased again for
  // the one question below, once per sync).
  db.release();
  if (!earlier) {
    const json page = rounds_being_read(drive);
    if (count) *count = {0, 0, page.at("measuring").get<int>()};
    return text_of(page);
  }
  if (!changed) {
    // The visits whose records a sync since the shown rounds' state wrote
    // (their revisions' time on the server), asked once per sync.
    const std::string since = earlier_stamp.substr(earlier_stamp.find('/') + 1);
    changed = office::visits_synced_after(db.db(), tunnel_id->second, since);
    db.release();
    std::lock_guard guard(lock_);
    const auto it = drives_.find(key);
    if (it != drives_.end() && it->second.stamp == stamp) it->second.changed = changed;
  }
  const json page = rounds_after_sync(*earlier, earlier_figures, drive, *changed);
  if (count) *count = {kept, measured, page.at("measuring").get<int>()};
  return text_of(page);
}

void RoundsWorker::run() {
  std::unique_lock guard(lock_);
  while (true) {
    wake_.wait(guard, [&] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    const std::string key = queue_.front();
    queue_.pop_front();
    guard.unlock();
    work(key);
    guard.lock();
  }
}

void RoundsWorker::work(const std::string& key) {
  std::string tunnel, role, asked;
  {
    std::lock_guard guard(lock_);
    const auto it = drives_.find(key);
    if (it == drives_.end()) return;
    tunnel = it->second.tunnel;
    role = it->second.role;
    asked = it->second.stamp;
  }
  // The stamp whose rounds this run shows; the drive's own stamp moving
  // away from it stops the run and queues the drive again.
  std::string shown;
  bool failed = false;
  auto connect = [&] { return RequestConnection(pool_, role); };
  try {
    RoundsBase base;
    {
      auto lease = connect();
      base = read_rounds_base(cache_, lease, tunnel);
    }
    {
      std::lock_guard guard(lock_);
      const auto it = drives_.find(key);
      if (it != drives_.end() && (it->second.stamp == asked || it->second.stamp == base.stamp)) {
        Drive& d = it->second;
        d.stamp = base.stamp;
        d.base_stamp = base.stamp;
        d.base = base.page;
        d.figures = base.figures;
        d.kept = static_cast<int>(base.figures.size());
        d.measured = 0;  // of this state
        d.changed.reset();
        shown = base.stamp;
      }
    }
    if (!shown.empty()) {
      measure_rounds(
          cache_, connect, tunnel, role, base,
          [&](const std::map<std::string, json>& batch) {
            std::lock_guard guard(lock_);
            const auto it = drives_.find(key);
            if (it == drives_.end() || it->second.stamp != shown) return;
            for (const auto& [uuid, figures] : batch) it->second.figures[uuid] = figures;
            it->second.measured += static_cast<int>(batch.size());
          },
          [&] {
            std::lock_guard guard(lock_);
            const auto it = drives_.find(key);
            return stop_ || it == drives_.end() || it->second.stamp != shown;
          },
          log_);
    }
  } catch (const std::exception& e) {
    // The drive's next request queues it again.
    failed = true;
    log_("the rounds of tunnel " + tunnel + ": " + e.what());
  }
  std::lock_guard guard(lock_);
  const auto it = drives_.find(key);
  if (it == drives_.end()) return;
  it->second.queued = false;
  if (!stop_ && !failed && it->second.stamp != shown) queue(key, it->second);
}

}  // namespace rockface::app::office_web
