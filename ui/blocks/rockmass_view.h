#pragma once
// The Rock mass view of the Blocks screen (issue 23): the visit's figures
// in words and units (spacing, RQD, Jv, block sizes, persistence), RMR89
// and Q with each rating's source and table, and the form for what the
// photographs cannot give (strength, joint condition, water, Jr, Ja, Jw,
// SRF, ESR, span). A value out of its table's range is refused by name
// before anything is saved; the form is saved with the visit and the
// figures made again on the worker (ui/app/field_services.h RockMassRunner).
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/rockmass/classification_form.h"
#include "storage/project/project_records.h"

namespace rockface::ui {

struct AppState;

struct RockMassState {
  bool open = false;  // the view replaces the block report on the Blocks screen
  // What was read for (project, visit); re-read when either changes.
  std::filesystem::path file;
  std::optional<storage::RecordId> visit;
  bool loaded = false;
  rockmass::ClassificationForm form;  // as being edited
  std::string refusal;                // the field refused and why; empty when none
  std::vector<std::string> lines;     // the figures and classifications
};

void draw_rockmass_view(AppState& app);

}  // namespace rockface::ui
