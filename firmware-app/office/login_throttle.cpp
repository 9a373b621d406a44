#include "firmware-app/office/login_throttle.h"

#include <algorithm>

namespace rockface::app::office_web {

LoginThrottle::LoginThrottle(int max_failures, std::chrono::seconds window)
    : max_failures_(max_failures), window_(window) {}

int LoginThrottle::wait_for(const std::string& key, Clock::time_point now) {
  const auto it = failures_.find(key);
  if (it == failures_.end()) return 0;
  auto& times = it->second;
  while (!times.empty() && now - times.front() >= window_) times.pop_front();
  if (static_cast<int>(times.size()) < max_failures_) return 0;
  // The oldest failure that keeps the count at the limit must leave the
  // window; rounded up so that a client waiting that long is let in.
  const auto wait = times[times.size() - static_cast<std::size_t>(max_failures_)] + window_ - now;
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(wait).count();
  return static_cast<int>(std::max<long long>(1, (ms + 999) / 1000));
}

int LoginThrottle::retry_after(const std::string& address, const std::string& role,
                               Clock::time_point now) {
  std::lock_guard guard(lock_);
  return std::max(wait_for("a:" + address, now), wait_for("r:" + role, now));
}

void LoginThrottle::failed(const std::string& address, const std::string& role,
                           Clock::time_point now) {
  std::lock_guard guard(lock_);
  // Bounded: names tried once (a scan of role names) leave with their window.
  if (failures_.size() > 4096) forget_old(now);
  failures_["a:" + address].push_back(now);
  failures_["r:" + role].push_back(now);
}

int LoginThrottle::retry_after_known(const std::string& token, Clock::time_point now) {
  std::lock_guard guard(lock_);
  return wait_for("k:" + token, now);
}

void LoginThrottle::failed_known(const std::string& token, Clock::time_point now) {
  std::lock_guard guard(lock_);
  if (failures_.size() > 4096) forget_old(now);
  failures_["k:" + token].push_back(now);
}

void LoginThrottle::forget_old(Clock::time_point now) {
  for (auto it = failures_.begin(); it != failures_.end();) {
    auto& times = it->second;
    while (!times.empty() && now - times.front() >= window_) times.pop_front();
    it = times.empty() ? failures_.erase(it) : std::next(it);
  }
}

}  // namespace rockface::app::office_web
