#include "ui/app/background_task.h"

#include <exception>
#include <utility>

#include "core/common/error.h"

namespace rockface::ui {

class BackgroundTask::Reporter final : public Progress {
 public:
  explicit Reporter(BackgroundTask& task) : task_(task) {}
  void report(std::string_view stage, double fraction) override {
    std::lock_guard<std::mutex> lock(task_.mutex_);
    task_.status_.stage = std::string(stage);
    task_.status_.fraction = fraction;
  }
  bool cancel_requested() const override { return task_.cancel_.load(); }

 private:
  BackgroundTask& task_;
};

BackgroundTask::~BackgroundTask() {
  cancel();
  wait();
}

bool BackgroundTask::start(std::string title, Work work, Then then, bool cancelled) {
  if (running()) return false;
  join_finished();
  then_ = std::move(then);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_ = TaskStatus{true, cancelled, title, "starting", 0, 0};
    outcome_.reset();
    started_at_ = std::chrono::steady_clock::now();
  }
  ++started_;
  cancel_ = cancelled;
  running_ = true;
  thread_ = std::thread([this, title = std::move(title), work = std::move(work)] {
    Reporter reporter(*this);
    TaskOutcome outcome;
    outcome.title = title;
    try {
      outcome.message = work(reporter);
    } catch (const Cancelled&) {
      outcome.kind = TaskOutcome::Kind::cancelled;
      outcome.message = "cancelled; what was saved before stays saved";
    } catch (const std::exception& e) {
      outcome.kind = TaskOutcome::Kind::failed;
      outcome.message = e.what();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      status_.running = false;
      outcome_ = std::move(outcome);
      outcome_pending_ = true;  // before running_ goes false: never both false with it untaken
    }
    running_ = false;
  });
  return true;
}

void BackgroundTask::cancel() {
  if (!running_.load()) return;
  cancel_ = true;
  std::lock_guard<std::mutex> lock(mutex_);
  status_.cancelling = true;
}

TaskStatus BackgroundTask::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  TaskStatus out = status_;
  if (out.running)
    out.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at_).count();
  return out;
}

std::optional<TaskOutcome> BackgroundTask::take_outcome() {
  std::optional<TaskOutcome> outcome;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome = std::exchange(outcome_, std::nullopt);
  }
  if (!outcome) return outcome;
  join_finished();
  // Idle again before `then` runs: a `then` may start the next task.
  auto then = std::exchange(then_, nullptr);
  outcome_pending_ = false;
  if (then) then(*outcome);
  return outcome;
}

void BackgroundTask::wait() {
  join_finished();
}

void BackgroundTask::join_finished() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace rockface::ui
