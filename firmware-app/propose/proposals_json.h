#pragma once
// PROPOSALS.json (rockface-proposals/1, docs/scene-extensions.md): the
// facets found on a visit's 3D image with their planes, sigmas, areas and
// outlines; the joint sets they form with Fisher K and spacing; the
// clusters that are not sets and why; the knobs used; the trace proposals.
#include <string>

#include "core/common/preset.h"
#include "firmware-app/propose/propose_workflow.h"

namespace rockface::app {

std::string proposals_json(const ProposeResult& result, Preset preset);

// The result in a few lines for the terminal: one per set, then the count
// of facets and what is not a set.
std::vector<std::string> proposals_summary(const ProposeResult& result);

}  // namespace rockface::app
