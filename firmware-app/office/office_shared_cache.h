#pragma once
// What the office's sessions share (issue 46, the drive under load): fifty
// people opening the same drive must not each build it, nor each pull the
// tunnel. A drive page and a pulled copy are shared by the sessions whose
// roles may read the same set of tunnels — asked of PostgreSQL under each
// session's own role on every request, so the server's row-level security
// still decides what each person sees — and at the same state of the
// server's records (tunnel_stamp). A role of one tunnel never shares with a
// role of another, or of every tunnel.
//
// Bounded: at most kDrivePages drive pages and kPulledCopies pulled copies
// are kept, the least recently used dropped first; one build of each at a
// time (the others wait for it and take its result).
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "firmware-app/office/cpu_slots.h"
#include "firmware-app/office/office_pages.h"
#include "firmware-app/office/office_sessions.h"
#include "firmware-app/office/request_connection.h"
#include "firmware-app/tunnel/round_start.h"

namespace rockface::app::office_web {

// The tunnels the session's role may read, by name, and the key of that
// set ("id,id,...": the same for every role that reads the same tunnels).
struct ReadableTunnels {
  std::string key;
  std::map<std::string, std::int64_t> by_name;
};
ReadableTunnels readable_tunnels(storage::office::Connection& c);

// A pulled copy of one tunnel shared read-only by sessions; its file is
// removed when the last session using it lets go.
struct SharedPull {
  std::filesystem::path file;
  std::string stamp;
  // The copy's visits: the server's uuid -> the id the pull gave it, read
  // from the copy itself (a sync since cannot shift them).
  std::map<std::string, std::int64_t> visit_ids;
  // A copy of some visits (PullScope::visits) holds none of the drive's
  // other visits: the drive's faces, where their rounds start, read in the
  // same snapshot under the ids a whole pull gives the visits (the copy's
  // own visits take theirs too).
  std::optional<DriveFaces> drive;
  ~SharedPull();
};

// What a pulled copy holds (storage/office/pull_project.h's PullOptions):
// the drive's rounds need no photograph, and no mesh once their figures
// are kept (office_round_figures.h); a visit page needs its visit only,
// its photographs fetched one by one when shown, and of the rest of the
// drive only what its round's start needs (SharedPull::drive).
struct PullScope {
  bool photographs = true;
  bool meshes = true;
  std::vector<std::string> visits;  // server uuids; empty: every visit
};

class SharedOfficeCache {
 public:
  static constexpr std::size_t kDrivePages = 32;
  // Copies of the whole drive (the rounds' figures; a few hundred MB at
  // 3,000 visits with meshes) and copies of a visit or two (one visit's
  // records and 3D image, and the drive's visit and placement rows):
  // fifty people open different visits.
  static constexpr std::size_t kPulledCopies = 4;
  static constexpr std::size_t kVisitCopies = 32;
  // A stamp asked this recently is taken as current: a page polled by fifty
  // people costs one query a second, and a sync shows within that.
  static constexpr std::chrono::milliseconds kStampFresh{1000};

  explicit SharedOfficeCache(std::filesystem::path folder);

  // The drive page's JSON text for the role `db` acts as (office_pages.h's
  // drive_page; `db` a pooled connection acting as the session's role).
  // Throws InputError when the role may not read the tunnel. `db` is given
  // back to the pool before waiting for another request's build.
  std::string drive(RequestConnection& db, const std::string& tunnel, const DriveFilter& filter);
  // The tunnel's stamp for the role `db` acts as (shared, kStampFresh).
  std::string stamp(RequestConnection& db, const std::string& tunnel);
  // The tunnel pulled at its current stamp, read on `db` (acting as the
  // session's role) when no session of the same readable tunnels has it,
  // holding what `scope` asks: a drive of 3,000 visits lists its rounds
  // without fetching 6,000 photographs, a visit page without the other
  // 2,999 visits. `db` is given back to the pool once the server's rows
  // are read (storage/office/pull_project.h's read_pull), before the copy
  // is built, and before waiting for another request's build of it: it is
  // not held on return.
  std::shared_ptr<const SharedPull> pulled(RequestConnection& db, const std::string& tunnel,
                                           const PullScope& scope = {});
  // The same, made for one use and not shared (the rounds measured after a
  // sync: a copy of those visits, used once); its file goes with it.
  std::shared_ptr<const SharedPull> pulled_once(RequestConnection& db, const std::string& tunnel,
                                                const PullScope& scope);
  // The slots a copy's build takes (cpu_slots.h); the server's other heavy
  // work takes them too.
  CpuSlots& cpu_slots() { return cpu_slots_; }

 private:
  struct Stamp {
    std::string value;
    std::chrono::steady_clock::time_point asked;
  };
  struct Page {
    // One build at a time. While one session builds a newer page, the
    // others get the page as it was (they poll the stamp and come back):
    // a sync never stalls every reader for the build's time.
    std::mutex build;
    std::mutex data;  // guards stamp and json
    std::string stamp, json;
    std::uint64_t used = 0;
  };
  struct Pull {
    std::mutex build;
    std::shared_ptr<const SharedPull> copy;
    std::uint64_t used = 0;
  };

  // The readable set's key and the tunnel's current stamp; throws
  // InputError when the role may not read the tunnel.
  std::pair<std::string, std::string> checked_stamp(RequestConnection& db,
                                                    const std::string& tunnel);
  std::shared_ptr<const SharedPull> make_copy(RequestConnection& db, const std::string& tunnel,
                                              const std::string& stamp, const PullScope& scope);
  template <typename Entry>
  std::shared_ptr<Entry> entry(std::map<std::string, std::shared_ptr<Entry>>& map,
                               const std::string& key, std::size_t limit);

  std::filesystem::path folder_;
  CpuSlots cpu_slots_;
  std::mutex lock_;  // guards the maps and the clock, never held while building
  std::uint64_t clock_ = 0;
  std::map<std::string, Stamp> stamps_;
  std::map<std::string, std::shared_ptr<Page>> pages_;
  std::map<std::string, std::shared_ptr<Pull>> pulls_, visit_pulls_;
};

}  // namespace rockface::app::office_web
