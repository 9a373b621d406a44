#include "ui/app/work_queue.h"

#include <utility>

namespace rockface::ui {

WorkQueue::~WorkQueue() {
  // At shutdown the waiting jobs are not started (their input stays where
  // the caller keeps it); the running one is cancelled and joined.
  waiting_.clear();
  task_.cancel();
  wait();
}

void WorkQueue::add(std::string title, BackgroundTask::Work work, BackgroundTask::Then then) {
  waiting_.push_back({std::move(title), std::move(work), std::move(then), false});
  poll();
}

std::optional<TaskOutcome> WorkQueue::poll() {
  std::optional<TaskOutcome> outcome = task_.take_outcome();
  if (!task_.running() && !waiting_.empty()) {
    Job next = std::move(waiting_.front());
    waiting_.pop_front();
    task_.start(std::move(next.title), std::move(next.work), std::move(next.then), next.cancelled);
  }
  return outcome;
}

WorkQueueStatus WorkQueue::status() const {
  return {task_.status(), waiting_.size()};
}

void WorkQueue::cancel() {
  for (Job& j : waiting_) j.cancelled = true;
  task_.cancel();
}

}  // namespace rockface::ui
