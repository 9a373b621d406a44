#pragma once
// Independent work items on all cores (issue 17): blocks are analysed one by
// one, each by pure functions of its own input, so a small pool of
// std::threads takes items from a shared counter and each result goes to
// its own slot. The results, their order and every number in them are those
// of the single-threaded run; only the time changes.
//
// The number of threads: ROCKFACE_THREADS from the environment when set (1:
// everything on the calling thread, as before), else every hardware thread.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rockface {

inline unsigned analysis_threads() {
  if (const char* env = std::getenv("ROCKFACE_THREADS")) {
    const long n = std::strtol(env, nullptr, 10);
    if (n >= 1) return static_cast<unsigned>(std::min<long>(n, 256));
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

// Calls f(i) for every i in [0, n), on up to `threads` threads (0: the
// default above). f must only write what belongs to item i. An exception
// from any item stops the others from starting new items and is rethrown
// here; when several throw, the one of the lowest item wins, so the error
// is the one the single-threaded run would have stopped at.
template <class F>
void parallel_for(size_t n, F&& f, unsigned threads = 0) {
  if (threads == 0) threads = analysis_threads();
  threads = static_cast<unsigned>(std::min<size_t>(threads, n));
  if (threads <= 1) {
    for (size_t i = 0; i < n; ++i) f(i);
    return;
  }
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex m;
  size_t error_item = n;
  std::exception_ptr error;
  auto work = [&] {
    for (;;) {
      const size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= n || failed.load(std::memory_order_relaxed)) return;
      try {
        f(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(m);
        if (i < error_item) {
          error_item = i;
          error = std::current_exception();
        }
        failed.store(true, std::memory_order_relaxed);
      }
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace rockface
