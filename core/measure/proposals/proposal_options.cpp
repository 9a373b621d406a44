// The trace-proposal knobs per preset (DESIGN.md "Accuracy costs time").
// What each costs and finds is measured in tools/bench/trace_proposals_bench.cpp
// and written in docs/accuracy-cost.md ("Trace proposals").
#include "core/measure/proposals/trace_proposals.h"

namespace rockface::measure {

ProposalOptions proposal_options(Preset preset) {
  ProposalOptions o;
  switch (preset) {
    case Preset::fast:
      // One scale, 3 px across a 2 cm trace: a 24 Mpx photograph is read
      // at about a sixth of its width.
      o.line_widths_m = {0.02};
      o.pixels_per_line = 3.0;
      o.measure.sample_step_px = 4.0;
      break;
    case Preset::standard:
      o.line_widths_m = {0.02, 0.04};
      o.pixels_per_line = 4.0;
      break;
    case Preset::precise:
      // Hairline joints too, and the photograph read finer.
      o.line_widths_m = {0.01, 0.02, 0.04};
      o.pixels_per_line = 4.0;
      o.min_length_m = 0.2;
      break;
  }
  return o;
}

const char* proposal_cue_name(ProposalCue cue) {
  switch (cue) {
    case ProposalCue::dark_line:
      return "dark line";
    case ProposalCue::fold:
      return "fold";
    case ProposalCue::both:
      return "dark line and fold";
  }
  return "dark line";
}

}  // namespace rockface::measure
