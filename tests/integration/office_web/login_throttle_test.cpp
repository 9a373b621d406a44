// The log-in rate limit's counting (firmware-app/office/login_throttle.h)
// on a clock the test sets: per source address, per role, the sliding
// window and the wait it announces.
#include "firmware-app/office/login_throttle.h"

#include <gtest/gtest.h>

namespace rockface::app::office_web {
namespace {

using std::chrono::seconds;
using Clock = LoginThrottle::Clock;

TEST(OfficeLoginThrottle, FiveFailuresFromOneAddressWaitTillTheFirstLeavesTheMinute) {
  LoginThrottle t(5, seconds(60));
  const Clock::time_point t0 = Clock::now();
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(t.retry_after("10.0.0.1", "role_" + std::to_string(i), t0 + seconds(i)), 0) << i;
    t.failed("10.0.0.1", "role_" + std::to_string(i), t0 + seconds(i));
  }
  // Any role from that address: the first failure (t0) leaves at t0 + 60 s.
  EXPECT_EQ(t.retry_after("10.0.0.1", "someone_else", t0 + seconds(10)), 50);
  EXPECT_EQ(t.retry_after("10.0.0.1", "someone_else", t0 + seconds(59)), 1);
  EXPECT_EQ(t.retry_after("10.0.0.1", "someone_else", t0 + seconds(60)), 0);
  // Another address, another role: not held.
  EXPECT_EQ(t.retry_after("10.0.0.2", "someone_else", t0 + seconds(10)), 0);
}

TEST(OfficeLoginThrottle, FiveFailuresForOneRoleFromManyAddressesHoldTheRole) {
  LoginThrottle t(5, seconds(60));
  const Clock::time_point t0 = Clock::now();
  for (int i = 0; i < 5; ++i) t.failed("10.0.0." + std::to_string(i), "chief", t0);
  EXPECT_EQ(t.retry_after("10.0.9.9", "chief", t0 + seconds(30)), 30);
  EXPECT_EQ(t.retry_after("10.0.9.9", "engineer", t0 + seconds(30)), 0);
  EXPECT_EQ(t.retry_after("10.0.9.9", "chief", t0 + seconds(60)), 0);
}

TEST(OfficeLoginThrottle, FourFailuresAreNotHeld) {
  LoginThrottle t(5, seconds(60));
  const Clock::time_point t0 = Clock::now();
  for (int i = 0; i < 4; ++i) t.failed("10.0.0.1", "chief", t0);
  EXPECT_EQ(t.retry_after("10.0.0.1", "chief", t0), 0);
}

}  // namespace
}  // namespace rockface::app::office_web
