#include "firmware-app/propose/kept_working_memory.h"

#include <malloc.h>

namespace rockface::app {

namespace {

// Blocks up to this size come from the heap, which is not trimmed until
// this much is free at its top: more than the search's largest block (the
// 24 Mpx photograph in float, 96 MB) and its whole working set (~0.4 GB).
constexpr int kKeptBlockBytes = 1 << 30;
constexpr int kKeptTrimBytes = 1 << 30;
// glibc's own ceilings for its adaptive limits on 64-bit systems
// (DEFAULT_MMAP_THRESHOLD_MAX, and twice it for the trim).
constexpr int kMappedBlockBytes = 32 << 20;
constexpr int kTrimBytes = 64 << 20;

}  // namespace

KeptWorkingMemory::KeptWorkingMemory() {
  mallopt(M_MMAP_THRESHOLD, kKeptBlockBytes);
  mallopt(M_TRIM_THRESHOLD, kKeptTrimBytes);
}

KeptWorkingMemory::~KeptWorkingMemory() {
  mallopt(M_MMAP_THRESHOLD, kMappedBlockBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimBytes);
  malloc_trim(0);
}

}  // namespace rockface::app
