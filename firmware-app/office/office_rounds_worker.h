#pragma once
// The drive's rounds answered at once (issue 46: the first rounds request
// of a fresh server on a 3,000-visit drive took 284 s with every round's
// figures kept, 552 s with none). A request gets the rounds as far as they
// are read: before the drive's copy is read, the placed visits of the
// drive page, every round "measuring"; then the rock mass and support of
// every round with the over- and underbreak kept on the server; the rounds
// not kept yet are measured by one background worker
// (office_round_figures.h), kept on the server a batch at a time and shown
// to the next request. The page polls until no round is "measuring".
// After a tablet syncs, the drive is read again in the background: the
// rounds already shown stay, the visits the sync brought or changed (by
// their records' revisions on the server) are "measuring" until read and
// measured — never the whole drive "reading…" again, nor a restart needed.
//
// Bounded: one worker thread for the whole server, at most kQueued drives
// waiting, kDrives drives' states kept (the least recently asked dropped
// first); a drive is queued once however many people ask.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "firmware-app/office/office_shared_cache.h"
#include "storage/office/connection_pool.h"
#include "storage/office/pg_connection.h"

namespace rockface::app::office_web {

struct RoundsCount {
  int kept = 0;       // rounds whose figures were read as kept
  int measured = 0;   // rounds this server measured (and kept) so far
  int measuring = 0;  // rounds still being measured
};

class RoundsWorker {
 public:
  static constexpr std::size_t kQueued = 16;
  static constexpr std::size_t kDrives = 32;

  // `log` hears what failed in the background (the page still answers).
  RoundsWorker(SharedOfficeCache& cache, storage::office::ConnectionPool& pool,
               std::function<void(const std::string&)> log);
  // Stops the worker between two rounds (a pull under way ends first).
  ~RoundsWorker();
  RoundsWorker(const RoundsWorker&) = delete;
  RoundsWorker& operator=(const RoundsWorker&) = delete;

  // The rounds page's JSON text for the role `db` acts as (`role`), never
  // waiting for a pull or a measurement. Throws InputError when the role
  // may not read the tunnel.
  std::string page(RequestConnection& db, const std::string& tunnel, const std::string& role,
                   RoundsCount* count = nullptr);

 private:
  // One drive as the sessions of the same readable tunnels see it.
  struct Drive {
    std::string tunnel, role;  // what the worker reads it as
    std::string stamp;         // the server's state last asked
    // The rounds as read at base_stamp, with their figures; after a sync
    // (stamp moved on) shown until the worker has read the drive again,
    // but for the visits the sync brought or changed (`changed`, their
    // uuids, asked of the server once per sync).
    std::string base_stamp;
    std::optional<nlohmann::json> base;
    std::map<std::string, nlohmann::json> figures;  // by visit uuid
    std::optional<std::set<std::string>> changed;
    int kept = 0, measured = 0;
    bool queued = false;  // waiting for the worker or under way
    std::string text;     // the page once every round is in
    std::uint64_t used = 0;
  };

  void run();
  void work(const std::string& key);
  void queue(const std::string& key, Drive& d);

  SharedOfficeCache& cache_;
  storage::office::ConnectionPool& pool_;
  std::function<void(const std::string&)> log_;
  std::mutex lock_;  // guards everything below, never held while reading or measuring
  std::condition_variable wake_;
  std::map<std::string, Drive> drives_;
  std::deque<std::string> queue_;
  std::uint64_t clock_ = 0;
  bool stop_ = false;
  std::thread thread_;  // last: started when the rest is ready
};

}  // namespace rockface::app::office_web
