#pragma once
// The office web server's log-ins (issue 46): each session is one libpq
// connection opened AS the person's own PostgreSQL role, so the server's
// row-level security decides everything a page shows. A session is named by
// a random 256-bit token (the cookie) and ends after `idle` without a
// request, at log-out, or when its connection is lost. The password goes to
// libpq once and is kept nowhere.
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "storage/office/pg_connection.h"

namespace rockface::app::office_web {

struct OfficeSession {
  // One request at a time on the connection (libpq's connections are not
  // shared between threads).
  std::mutex lock;
  storage::office::Connection db;
  std::string role;
  std::string csrf;  // sent with every POST in X-Rockface-CSRF
  // This session's exports and reports, removed with it (the pulled
  // copies and drive pages are shared: office_shared_cache.h).
  std::filesystem::path folder;

  explicit OfficeSession(storage::office::Connection c) : db(std::move(c)) {}
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
  SessionStore(std::string server, std::chrono::milliseconds idle,
               std::filesystem::path work_folder);
  ~SessionStore();

  // Opens a connection as `role` with `password` and keeps it if the role
  // may read the office's pages (a member of rockface_office,
  // rockface_tunnel_office or rockface_admin) and is not a tablet's (a
  // member of rockface_tablet and of no office role). Returns the token.
  // The connection is made read-only: nothing on the web changes the
  // database.
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
  std::mutex lock_;
  std::map<std::string, Entry> sessions_;
};

}  // namespace rockface::app::office_web
