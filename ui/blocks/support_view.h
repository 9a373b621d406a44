#pragma once
// Issue 44 on the tablet: the Blocks screen's Support view. The round's
// support as `rockface support` finds it (SupportRunner, on the worker):
// what the Q chart, Bieniawski's RMR89 table and the designer's classes
// propose, side by side; the checks of the proposed and the chosen class on
// the visit's wedges and moving blocks; the decision stored with the visit
// (who, when, the class chosen, why when it is not the proposed one, the
// changes made to the class), and the form to make it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/support_decision.h"
#include "storage/project/project_records.h"
#include "ui/app/field_services.h"

namespace rockface::ui {

struct AppState;

struct SupportViewState {
  bool open = false;  // the Blocks screen shows the Support view instead of the blocks
  // What the proposals were read for; a new project or visit clears them.
  std::filesystem::path file;
  std::optional<storage::RecordId> visit;
  bool requested = false;  // read once per visit when the view opens
  std::optional<SupportProposals> proposals;
  std::string message;  // why there are none, or why a decision was refused
  // The decision being made: the class, who, why, and the changes made to
  // the class for this round (each with what, from, to and why).
  std::string chosen, by, reason;
  std::vector<analysis::SupportChange> changes;
};

void draw_support_view(AppState& app);

}  // namespace rockface::ui
