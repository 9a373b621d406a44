#include "ui/platform/texture_generation.h"

#include <atomic>

namespace rockface::ui {

namespace {
std::atomic<std::uint64_t> generation{0};
}  // namespace

void note_texture_changed() {
  generation.fetch_add(1, std::memory_order_relaxed);
}

std::uint64_t texture_generation() {
  return generation.load(std::memory_order_relaxed);
}

}  // namespace rockface::ui
