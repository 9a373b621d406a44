#pragma once
// The office web server's log-ins (issue 46): a person logs in with their
// own PostgreSQL role and password, checked by PostgreSQL on a connection
// of their own that closes once the log-in is checked; their requests then
// run on the server's bounded pool of connections, each acting as their
// role (storage/office/connection_pool.h), so the server's row-level
// security decides everything a page shows and fifty people do not hold
// fifty connections. A session is named by a random 256-bit token (the
// cookie) and ends after `idle` without a request, or at log-out. The
// password goes to libpq once and is kept nowhere.
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "storage/office/connection_pool.h"

namespace rockface::app::office_web {

struct OfficeSession {
  // One request of a person at a time: a person's browser asking for ten
  // photographs at once holds one of the pool's connections, not ten.
  std::mutex lock;
  std::string role;
  std::string csrf;  // sent with every POST in X-Rockface-CSRF
  // This session's exports and reports, removed with it (the pulled
  // copies and drive pages are shared: office_shared_cache.h).
  std::filesystem::path folder;

  OfficeSession() = default;
  // Removes the folder: the last request on a closed session ends before
  // it goes.
  ~OfficeSession();
  OfficeSession(const OfficeSession&) = delete;
  OfficeSession& operator=(const OfficeSession&) = delete;
};

// Why a log-in was refused, in the words the page shows (never which of
// role or password was wrong).
class LoginRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The database could not take the log-in (too many connections, not
// reachable): not a wrong password, so not counted against the address or
// the role (login_throttle.h). `what()` is the server's reason for the log,
// never a password.
class LoginUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SessionStore {
 public:
  // `server`: the database as the pool reaches it; the log-ins' user and
  // password override its user. `pool`: the connections the sessions'
  // requests run on.
  SessionStore(std::string server, std::chrono::milliseconds idle,
               std::filesystem::path work_folder, storage::office::ConnectionPool& pool);
  ~SessionStore();

  // Connects as `role` with `password` (PostgreSQL checks it) and keeps a
  // session if the role may read the office's pages (a member of
  // rockface_office, rockface_tunnel_office or rockface_admin) and is not a
  // tablet's (a member of rockface_tablet and of no office role), and the
  // pool may act as it. Returns the token. The pool's connections are
  // read-only: nothing on the web changes the database.
  std::string log_in(const std::string& role, const std::string& password);
  // The session of a token, its idle clock restarted; null when unknown or
  // expired (an expired session is closed here).
  std::shared_ptr<OfficeSession> find(const std::string& token);
  void log_out(const std::string& token);
  // Closes every session idle longer than `idle`.
  void expire();
  std::chrono::milliseconds idle() const { return idle_; }
  std::size_t count();

 private:
  struct Entry {
    std::shared_ptr<OfficeSession> session;
    std::chrono::steady_clock::time_point last_used;
  };

  std::string server_;
  std::chrono::milliseconds idle_;
  std::filesystem::path work_folder_;
  storage::office::ConnectionPool& pool_;
  std::mutex lock_;
  std::map<std::string, Entry> sessions_;
};

}  // namespace rockface::app::office_web
