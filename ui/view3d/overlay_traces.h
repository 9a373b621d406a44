#pragma once
// The traces on the 3D image: each stored trace of the visit in its joint's
// colour and the trace being marked, laid on the drawn surface and clipped
// to it (a stored trace whose picks run past the 3D image is drawn only
// where the image is).
#include <string>
#include <vector>

#include <imgui.h>

#include "storage/project/project_records.h"

namespace rockface::ui {

struct AppState;

// The colour of a joint's traces: its place among the visit's joints picks
// one of a palette apart from the verdicts' colours; a trace of no joint
// (or of a joint the visit lacks) is kTraceColour.
ImU32 joint_colour(const std::string& joint_label, const std::vector<storage::Joint>& joints);

// Adds the visit's stored traces and the marker's trace to the model view's
// overlay (call before ModelView::draw).
void add_traces_to_overlay(AppState& app);

}  // namespace rockface::ui
