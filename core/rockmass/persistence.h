#pragma once
// Persistence of each set from its traces' lengths, with the censoring the
// window imposes (as core/measure/joint_sets.h states it): a trace whose
// end leaves the mapped area is longer than seen. The mean of all traces is
// then a lower bound; the mean of the uncensored ones is the estimate when
// at least half the traces are uncensored (else the window is too small to
// say, and only the bound is given). ISRM 1978 words for the length.
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/set_traces.h"

namespace rockface::rockmass {

struct SetPersistence {
  std::string label;
  int traces = 0, censored = 0;
  std::optional<double> mean_all_m, mean_uncensored_m, longest_m;
  std::optional<double> persistence_m;  // the estimate, where estimable
  std::optional<double> lower_bound_m;  // when censoring leaves only a bound
  std::string isrm_words;               // "low persistence (1-3 m)", ...
  std::string censoring;                // in words
};

const char* isrm_persistence_words(double length_m);

std::vector<SetPersistence> set_persistence(const std::vector<FaceTrace>& traces,
                                            const std::vector<SetInput>& sets,
                                            const SetTraces& assigned);

}  // namespace rockface::rockmass
