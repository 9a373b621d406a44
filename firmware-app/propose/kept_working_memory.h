#pragma once
// While trace proposals and facets are sought (issue 45), the C library
// keeps the memory the search frees for the search's next images and arrays
// instead of handing every large block back to the system at once: the
// search makes and drops a few hundred MB of working images and arrays of
// tens of MB each, and each block handed back is faulted in again page by
// page when the next one is made. On the 2-core machine under load a page
// fault costs microseconds, and the faults were more than half the CPU
// time of a 24 Mpx model's Find traces (docs/accuracy-cost.md, "This
// stop's figures (2026-11-29, fifth session)"). At the end of the scope
// the memory is handed back (malloc_trim) and the library's limits are set
// to where its own adaptive ones settle after large blocks (blocks of 32
// MB and more mapped on their own, the heap trimmed beyond 64 MB free).
namespace rockface::app {

class KeptWorkingMemory {
 public:
  KeptWorkingMemory();
  ~KeptWorkingMemory();
  KeptWorkingMemory(const KeptWorkingMemory&) = delete;
  KeptWorkingMemory& operator=(const KeptWorkingMemory&) = delete;
};

}  // namespace rockface::app
