#pragma once
// The office server's heavy work (a pulled copy's build, a visit page put
// together) a few at a time: as many as the machine has cores (issue 46's
// load run: fifty people opening visits at once built fifty copies at once
// on two cores, each took fifty times as long, and the drive's light
// requests waited for the CPU behind them). A request waits for a slot
// holding no database connection.
#include <algorithm>
#include <semaphore>
#include <thread>

namespace rockface::app::office_web {

class CpuSlots {
 public:
  static constexpr std::ptrdiff_t kMost = 64;
  CpuSlots() : free_(std::clamp<std::ptrdiff_t>(std::thread::hardware_concurrency(), 1, kMost)) {}

  // Holds one slot while it lives.
  class Slot {
   public:
    explicit Slot(CpuSlots& s) : s_(s) { s_.free_.acquire(); }
    ~Slot() { s_.free_.release(); }
    Slot(const Slot&) = delete;
    Slot& operator=(const Slot&) = delete;

   private:
    CpuSlots& s_;
  };

 private:
  std::counting_semaphore<kMost> free_;
};

}  // namespace rockface::app::office_web
