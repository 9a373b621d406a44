#include "firmware-app/office/office_sessions.h"

#include <system_error>

#include "firmware-app/office/web_security.h"

namespace rockface::app::office_web {

namespace office = storage::office;

OfficeSession::~OfficeSession() {
  std::error_code ec;
  if (!folder.empty()) std::filesystem::remove_all(folder, ec);
}

SessionStore::SessionStore(std::string server, std::chrono::milliseconds idle,
                           std::filesystem::path work_folder, office::ConnectionPool& pool)
    : server_(std::move(server)), idle_(idle), work_folder_(std::move(work_folder)), pool_(pool) {}

SessionStore::~SessionStore() = default;

std::string SessionStore::log_in(const std::string& role, const std::string& password) {
  if (!plausible_role_name(role) || password.empty())
    throw LoginRefused("the role or the password is not right");
  std::unique_ptr<office::Connection> c;
  try {
    // 10 s: an unreachable server fails the log-in rather than hanging it.
    c = std::make_unique<office::Connection>(server_, role, password, 10);
  } catch (const office::ServerError& e) {
    // A server too busy or not there says so in libpq's words (English;
    // a message in another language counts as a refusal: the safe side).
    const std::string why = e.what();
    for (const char* busy : {"too many clients", "remaining connection slots", "Connection refused",
                             "timeout expired"})
      if (why.find(busy) != std::string::npos) throw LoginUnavailable(why);
    // PostgreSQL's reason (no such role, wrong password, pg_hba) stays
    // here: the page says only that the log-in failed.
    throw LoginRefused("the role or the password is not right");
  }
  const office::Result r = c->query(
      "SELECT coalesce(bool_or(r.rolname IN ('rockface_office', 'rockface_tunnel_office', "
      "'rockface_admin')), false), coalesce(bool_or(r.rolname = 'rockface_tablet'), false) "
      "FROM pg_roles r WHERE r.rolname IN ('rockface_office', 'rockface_tunnel_office', "
      "'rockface_admin', 'rockface_tablet') AND pg_has_role(current_user, r.oid, 'MEMBER')",
      {}, "checking the role's office membership");
  const bool office_role = r.text(0, 0) == "t";
  const bool tablet_role = r.text(0, 1) == "t";
  if (!office_role)
    throw LoginRefused(tablet_role ? "a tablet's role cannot log in to the office"
                                   : "this role is not an office role of rockface");
  // The person's own connection has checked the log-in: its slot goes
  // back to the server now.
  c.reset();
  // The pool may act as this role (the role is granted to rockface_web by
  // `server add-office`): asked now, so the log-in fails rather than its
  // first page.
  try {
    pool_.acquire(role);
  } catch (const office::PoolBusy& e) {
    throw LoginUnavailable(e.what());
  } catch (const office::ServerError& e) {
    if (e.sqlstate() == "42501")
      throw LoginUnavailable("the office server's role may not act as " + role +
                             ": an administrator runs `rockface server add-office` for it (" +
                             e.what() + ")");
    throw LoginUnavailable(e.what());
  }
  auto session = std::make_shared<OfficeSession>();
  session->role = role;
  session->csrf = random_token();
  const std::string token = random_token();
  session->folder = work_folder_ / ("session-" + token.substr(0, 16));
  std::lock_guard guard(lock_);
  sessions_[token] = {session, std::chrono::steady_clock::now()};
  return token;
}

std::shared_ptr<OfficeSession> SessionStore::find(const std::string& token) {
  if (token.size() != 64) return nullptr;
  std::lock_guard guard(lock_);
  const auto it = sessions_.find(token);
  if (it == sessions_.end()) return nullptr;
  const auto now = std::chrono::steady_clock::now();
  if (now - it->second.last_used > idle_) {
    sessions_.erase(it);
    return nullptr;
  }
  it->second.last_used = now;
  return it->second.session;
}

void SessionStore::log_out(const std::string& token) {
  std::lock_guard guard(lock_);
  const auto it = sessions_.find(token);
  if (it == sessions_.end()) return;
  sessions_.erase(it);
}

void SessionStore::expire() {
  std::lock_guard guard(lock_);
  const auto now = std::chrono::steady_clock::now();
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    if (now - it->second.last_used > idle_) {
      it = sessions_.erase(it);
    } else {
      ++it;
    }
  }
}

std::size_t SessionStore::count() {
  std::lock_guard guard(lock_);
  return sessions_.size();
}

}  // namespace rockface::app::office_web
