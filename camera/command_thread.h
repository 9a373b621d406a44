#pragma once
// One thread that owns a resource and runs commands on it in order.
// libgphoto2 is not thread-safe: every call on a camera goes through the
// camera's own CommandThread, whatever thread asked for it. call() blocks
// the caller until its command has run and returns its result or rethrows
// its exception.
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>

namespace rockface::camera {

class CommandThread {
 public:
  CommandThread() : worker_([this] { serve(); }) {}
  ~CommandThread() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    worker_.join();  // commands already queued still run
  }
  CommandThread(const CommandThread&) = delete;
  CommandThread& operator=(const CommandThread&) = delete;

  template <class F>
  std::invoke_result_t<F> call(F&& f) {
    using R = std::invoke_result_t<F>;
    if (std::this_thread::get_id() == worker_.get_id()) return f();  // nested call
    auto task = std::make_shared<std::packaged_task<R()>>(std::forward<F>(f));
    std::future<R> result = task->get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.emplace_back([task] { (*task)(); });
    }
    wake_.notify_one();
    return result.get();
  }

 private:
  void serve() {
    for (;;) {
      std::function<void()> command;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;
        command = std::move(queue_.front());
        queue_.pop_front();
      }
      command();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> queue_;
  bool stopping_ = false;
  std::thread worker_;  // last: starts after the members it uses
};

}  // namespace rockface::camera
