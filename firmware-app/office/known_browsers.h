#pragma once
// Browsers that have logged in as a role (issue 46: the log-in limit's
// count per role let anyone lock a person out of their own role for a
// minute by guessing at it five times). A successful log-in leaves a
// random token in the browser (an HttpOnly cookie, web_security.h); a
// log-in that brings the token of the role it logs in as is not held by
// the role's or the address's count — a stranger's guesses no longer keep
// the person out — but by the token's own (login_throttle.h), so a stolen
// token still guesses no faster. Kept in this process's memory (a restart
// forgets them: the role's count then holds everyone again), bounded.
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace rockface::app::office_web {

class KnownBrowsers {
 public:
  using Clock = std::chrono::steady_clock;
  // A month: a person who logs in every week keeps theirs.
  static constexpr std::chrono::hours kKept{24 * 30};
  // The oldest tokens go beyond this many.
  static constexpr std::size_t kLimit = 10000;

  // A new token for a browser that has just logged in as `role`.
  std::string remember(const std::string& role, Clock::time_point now = Clock::now());
  // Whether `token` was given to a browser that logged in as `role`, and
  // not longer ago than kKept.
  bool vouches(const std::string& token, const std::string& role,
               Clock::time_point now = Clock::now());

 private:
  struct Known {
    std::string role;
    Clock::time_point given;
  };
  std::mutex lock_;
  std::map<std::string, Known> known_;
};

}  // namespace rockface::app::office_web
