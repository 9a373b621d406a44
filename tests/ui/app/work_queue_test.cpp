// The queue of 3D images (issue 45): jobs run one after the other in the
// order they were added, each `then` on the caller's thread when polled,
// while the UI's own worker stays free; cancel stops the running job and
// drops those waiting.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/common/progress.h"
#include "ui/app/work_queue.h"

namespace rockface::ui {
namespace {

// Polls until the queue is idle, as frames do.
void drain(WorkQueue& q) {
  while (q.busy()) {
    q.wait();
    q.poll();
  }
}

TEST(WorkQueue, JobsRunOneAfterTheOtherInTheOrderAdded) {
  WorkQueue q;
  std::atomic<int> running{0}, most{0};
  std::vector<std::string> order, thens;
  std::mutex m;
  for (const char* name : {"pair 1", "pair 2", "pair 3"})
    q.add(
        name,
        [&, name](Progress&) {
          const int now = ++running;
          most = std::max(most.load(), now);
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          {
            std::lock_guard<std::mutex> lock(m);
            order.push_back(name);
          }
          --running;
          return std::string(name) + " done";
        },
        [&](const TaskOutcome& o) { thens.push_back(o.message); });
  EXPECT_EQ(q.status().waiting, 2u);
  drain(q);
  EXPECT_EQ(most.load(), 1) << "one job at a time";
  EXPECT_EQ(order, (std::vector<std::string>{"pair 1", "pair 2", "pair 3"}));
  EXPECT_EQ(thens, (std::vector<std::string>{"pair 1 done", "pair 2 done", "pair 3 done"}));
  EXPECT_FALSE(q.busy());
}

TEST(WorkQueue, TheUisWorkerStaysFreeWhileAJobRuns) {
  WorkQueue q;
  std::atomic<bool> release{false};
  q.add("pair 1", [&](Progress&) {
    while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return std::string("made");
  });
  BackgroundTask shot;  // the camera's call, on AppState::task
  ASSERT_TRUE(shot.start("Left shot", [](Progress&) { return std::string("captured"); }));
  shot.wait();
  const auto taken = shot.take_outcome();
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->message, "captured");
  EXPECT_TRUE(q.busy()) << "the 3D image is still being made";
  release = true;
  drain(q);
}

TEST(WorkQueue, CancelStopsTheRunningJobAndTheWaitingOnesAtTheirFirstStep) {
  WorkQueue q;
  std::atomic<bool> started{false};
  std::atomic<int> saved{0};  // what each job does before its first step (a pair stored)
  std::vector<TaskOutcome::Kind> outcomes;
  auto job = [&](Progress& p) {
    p.report("storing the pair", 0.01);  // report, not step: not a place to stop
    ++saved;
    started = true;
    for (;;) {
      p.step("working", 0.5);  // throws Cancelled once cancel() is heard
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return std::string();
  };
  auto then = [&](const TaskOutcome& o) { outcomes.push_back(o.kind); };
  q.add("pair 1", job, then);
  q.add("pair 2", job, then);
  while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  q.cancel();
  drain(q);
  EXPECT_EQ(saved.load(), 2) << "the waiting pair is stored too";
  EXPECT_EQ(outcomes, (std::vector<TaskOutcome::Kind>{TaskOutcome::Kind::cancelled,
                                                      TaskOutcome::Kind::cancelled}));
  EXPECT_FALSE(q.busy());
}

}  // namespace
}  // namespace rockface::ui
