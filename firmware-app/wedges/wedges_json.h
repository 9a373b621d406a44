#pragma once
// The wedge analysis as the `rockface wedges --out` file
// (format "rockface-wedges/1", docs/scene-extensions.md) and as the lines
// the verb prints: the wedges' table in words and units.
#include <string>
#include <vector>

#include "core/tunnel/wedge_analysis.h"
#include "firmware-app/wedges/wedge_input.h"

namespace rockface::app {

std::string wedges_json(const WedgeRun& run, const tunnel::WedgeAnalysis& analysis);

// One line per wedge (and the header, the notes and the pyramids that
// form no wedge with their reasons).
std::vector<std::string> wedges_summary(const WedgeRun& run, const tunnel::WedgeAnalysis& analysis);

// The mode in words: "falls", "slides on J1", "slides on J1 and J2",
// "lifts", "stays (pushed into the rock)".
std::string wedge_mode_words(const tunnel::Wedge& w);
// A factor of safety for people: "-" none, "stable" for no mode, 2 decimals.
// "1.23", "stable" (no driving force: +infinity), "unknown" (NaN, an
// overflow), "-" (none).
std::string wedge_fos_text(const std::optional<double>& fos);

}  // namespace rockface::app
