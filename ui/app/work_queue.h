#pragma once
// Work that may wait its turn on a worker of its own, one job after the
// other: the 3D images of a visit's pairs (issue 45). At the face a visit is
// three pairs, and each pair's reconstruction (tens of seconds at 24 Mpx)
// runs while the geologist walks to the next station and shoots it; the
// camera's calls keep the UI's own worker (AppState::task), so a shot never
// waits for a reconstruction, and the pairs are reconstructed in the order
// they were stored. Every call is made on the UI thread; a job's `then`
// runs there too (in poll()).
#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include "ui/app/background_task.h"

namespace rockface::ui {

struct WorkQueueStatus {
  TaskStatus current;       // the running job (running false when none)
  std::size_t waiting = 0;  // jobs after it
};

class WorkQueue {
 public:
  WorkQueue() = default;
  WorkQueue(const WorkQueue&) = delete;
  WorkQueue& operator=(const WorkQueue&) = delete;
  // The waiting jobs dropped, the running one cancelled and joined: a
  // caller whose jobs hold what is not saved elsewhere cancels and drains
  // the queue first (TabletApp's destructor does).
  ~WorkQueue();

  // Starts the job now when the worker is free, else after the others.
  void add(std::string title, BackgroundTask::Work work, BackgroundTask::Then then = {});
  // Every frame: takes the finished job's outcome (running its `then`) and
  // starts the next one. Returns the outcome taken, if any.
  std::optional<TaskOutcome> poll();
  bool busy() const { return task_.running() || !waiting_.empty(); }
  WorkQueueStatus status() const;
  // Cancels the running job, and the waiting ones as they come: each still
  // runs until its first step() (a pair is stored before its 3D image's
  // first step, so stopping the 3D images never loses a pair) and its
  // `then` runs with the outcome `cancelled`.
  void cancel();
  // Blocks until the running job has finished: headless scripts and
  // shutdown only, never a frame (its outcome is then taken by poll()).
  void wait() { task_.wait(); }

 private:
  struct Job {
    std::string title;
    BackgroundTask::Work work;
    BackgroundTask::Then then;
    bool cancelled = false;
  };
  BackgroundTask task_;
  std::deque<Job> waiting_;
};

}  // namespace rockface::ui
