// The worker's task and the frame that takes its outcome: an outcome is
// never dropped by a task started before it was taken (a saved trace whose
// screen update was lost when the map's blocks update started in the same
// frame the save finished).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/common/progress.h"
#include "ui/app/background_task.h"

namespace rockface::ui {
namespace {

TEST(BackgroundTask, IsBusyUntilItsOutcomeIsTakenAndDropsNone) {
  BackgroundTask task;
  int first_then = 0, second_then = 0;
  ASSERT_TRUE(task.start(
      "first", [](Progress&) { return std::string("first done"); },
      [&](const TaskOutcome& o) {
        EXPECT_EQ(o.message, "first done");
        ++first_then;
      }));
  task.wait();  // the worker has ended; its outcome is not taken yet
  EXPECT_TRUE(task.running()) << "busy until the outcome is taken";
  EXPECT_FALSE(task.start(
      "second", [](Progress&) { return std::string("second done"); },
      [&](const TaskOutcome&) { ++second_then; }))
      << "a second task would drop the first one's outcome";
  const auto first = task.take_outcome();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->title, "first");
  EXPECT_EQ(first_then, 1);
  EXPECT_FALSE(task.running());
  ASSERT_TRUE(task.start(
      "second", [](Progress&) { return std::string("second done"); },
      [&](const TaskOutcome&) { ++second_then; }));
  task.wait();
  const auto second = task.take_outcome();
  ASSERT_TRUE(second);
  EXPECT_EQ(second->message, "second done");
  EXPECT_EQ(second_then, 1);
  EXPECT_FALSE(task.take_outcome()) << "an outcome is taken once";
}

TEST(BackgroundTask, AThenMayStartTheNextTask) {
  BackgroundTask task;
  bool started_from_then = false;
  ASSERT_TRUE(task.start(
      "edit", [](Progress&) { return std::string("stored"); },
      [&](const TaskOutcome&) {
        started_from_then =
            task.start("blocks", [](Progress&) { return std::string("blocks updated"); });
      }));
  task.wait();
  ASSERT_TRUE(task.take_outcome());
  EXPECT_TRUE(started_from_then);
  task.wait();
  const auto blocks = task.take_outcome();
  ASSERT_TRUE(blocks);
  EXPECT_EQ(blocks->title, "blocks");
}

TEST(BackgroundTask, AFailureIsAnOutcomeWithItsMessage) {
  BackgroundTask task;
  ASSERT_TRUE(task.start("analysis", [](Progress&) -> std::string {
    throw std::runtime_error("no joints in visit 3");
  }));
  task.wait();
  const auto outcome = task.take_outcome();
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->kind, TaskOutcome::Kind::failed);
  EXPECT_EQ(outcome->message, "no joints in visit 3");
  EXPECT_FALSE(task.running());
}

}  // namespace
}  // namespace rockface::ui
