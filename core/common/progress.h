#pragma once
// Progress and cancellation for long work (reconstruction, block search,
// stability). core defines the interface; the UI and the command line
// implement it. Workers call step() at natural break points; a cancelled
// request surfaces as a Cancelled exception thrown from step().
#include <atomic>
#include <string_view>

#include "core/common/error.h"

namespace rockface {

class Progress {
 public:
  virtual ~Progress() = default;
  // stage: a short human name ("dense matching"); fraction in [0, 1].
  virtual void report(std::string_view stage, double fraction) = 0;
  virtual bool cancel_requested() const = 0;

  // Reports and throws Cancelled when the user asked to stop.
  void step(std::string_view stage, double fraction) {
    report(stage, fraction);
    if (cancel_requested()) throw Cancelled();
  }
};

// For callers that want neither reports nor cancellation.
class NoProgress final : public Progress {
 public:
  void report(std::string_view, double) override {}
  bool cancel_requested() const override { return false; }
};

// A cancel flag another thread may set; reports are dropped.
class CancelFlag : public Progress {
 public:
  void report(std::string_view, double) override {}
  bool cancel_requested() const override { return flag_.load(std::memory_order_relaxed); }
  void cancel() { flag_.store(true, std::memory_order_relaxed); }

 private:
  std::atomic<bool> flag_{false};
};

}  // namespace rockface
