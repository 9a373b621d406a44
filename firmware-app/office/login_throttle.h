#pragma once
// The office's log-in rate limit (issue 46): a guessed password costs a
// minute after a few tries. Failed log-ins are counted per source address
// and per role over a sliding window; once either holds `max_failures`,
// further log-ins from that address or for that role are refused (HTTP 429
// with Retry-After) without asking PostgreSQL, until the oldest failure
// leaves the window. A success clears nothing: an attacker's own good
// log-in must not reset the count of its guesses at another role.
#include <chrono>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace rockface::app::office_web {

class LoginThrottle {
 public:
  using Clock = std::chrono::steady_clock;

  explicit LoginThrottle(int max_failures = 5,
                         std::chrono::seconds window = std::chrono::seconds(60));

  // Whole seconds to wait before the next log-in from `address` or as
  // `role` may be tried; 0 when it may be tried now.
  int retry_after(const std::string& address, const std::string& role,
                  Clock::time_point now = Clock::now());
  void failed(const std::string& address, const std::string& role,
              Clock::time_point now = Clock::now());
  // The same for a log-in that brought a known browser's token for its
  // role (known_browsers.h): counted and held by the token alone.
  int retry_after_known(const std::string& token, Clock::time_point now = Clock::now());
  void failed_known(const std::string& token, Clock::time_point now = Clock::now());

 private:
  int wait_for(const std::string& key, Clock::time_point now);
  void forget_old(Clock::time_point now);

  int max_failures_;
  std::chrono::seconds window_;
  std::mutex lock_;
  // "a:ADDR" / "r:ROLE" / "k:TOKEN"
  std::map<std::string, std::deque<Clock::time_point>> failures_;
};

}  // namespace rockface::app::office_web
