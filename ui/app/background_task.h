#pragma once
// Long work (reconstruction, analysis, a camera shot) on a worker thread, so
// the UI thread never blocks: the screens start a task, draw its progress
// bar and cancel button every frame, and take its outcome when it is done.
// One task at a time; the worker reports through rockface::Progress and
// stops at its next step() after cancel().
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/common/progress.h"

namespace rockface::ui {

struct TaskStatus {
  bool running = false;
  bool cancelling = false;
  std::string title;  // "Analysis"
  std::string stage;  // last stage the work reported
  double fraction = 0;
  double seconds = 0;  // since the task started
};

struct TaskOutcome {
  enum class Kind { done, cancelled, failed };
  Kind kind = Kind::done;
  std::string title;
  std::string message;  // what failed, or a short summary of what was done
};

class BackgroundTask {
 public:
  // The work returns a short summary for the status line.
  using Work = std::function<std::string(Progress&)>;
  // Runs on the thread that takes the outcome (the UI thread), so it may
  // touch UI state and GL: install a loaded model, re-read the project.
  using Then = std::function<void(const TaskOutcome&)>;

  BackgroundTask() = default;
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;
  ~BackgroundTask();  // cancels and joins a running task

  // False (and nothing started) while another task runs or its outcome
  // waits to be taken.
  // `cancelled`: started with its cancel already asked (it runs until its
  // first step(): what it does before, such as saving its input, is done).
  bool start(std::string title, Work work, Then then = {}, bool cancelled = false);
  void cancel();
  TaskStatus status() const;
  // Busy until the last task's outcome is taken: a task started between
  // the worker's end and the frame that takes its outcome would otherwise
  // drop that outcome and its `then` (a saved trace's screen update).
  bool running() const { return running_.load() || outcome_pending_.load(); }
  // How many tasks were started so far: the UI notes which screen started
  // the latest (its outcome is said on that screen's status line).
  std::size_t started() const { return started_.load(); }
  // The outcome of the last task, once, after running its `then`.
  std::optional<TaskOutcome> take_outcome();
  // Blocks until the running task (if any) has finished: headless scripts
  // and shutdown only, never a frame.
  void wait();

 private:
  class Reporter;
  void join_finished();

  mutable std::mutex mutex_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> outcome_pending_{false};
  std::atomic<bool> cancel_{false};
  std::atomic<std::size_t> started_{0};
  std::chrono::steady_clock::time_point started_at_;
  TaskStatus status_;
  std::optional<TaskOutcome> outcome_;
  Then then_;
};

}  // namespace rockface::ui
