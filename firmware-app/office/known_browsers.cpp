#include "firmware-app/office/known_browsers.h"

#include "firmware-app/office/web_security.h"

namespace rockface::app::office_web {

std::string KnownBrowsers::remember(const std::string& role, Clock::time_point now) {
  const std::string token = random_token();
  std::lock_guard guard(lock_);
  if (known_.size() >= kLimit) {
    auto oldest = known_.begin();
    for (auto it = known_.begin(); it != known_.end(); ++it)
      if (it->second.given < oldest->second.given) oldest = it;
    known_.erase(oldest);
  }
  known_[token] = {role, now};
  return token;
}

bool KnownBrowsers::vouches(const std::string& token, const std::string& role,
                            Clock::time_point now) {
  if (token.size() != 64) return false;
  std::lock_guard guard(lock_);
  const auto it = known_.find(token);
  if (it == known_.end()) return false;
  if (now - it->second.given > kKept) {
    known_.erase(it);
    return false;
  }
  return tokens_equal(it->second.role, role);
}

}  // namespace rockface::app::office_web
