#pragma once
// Trace proposals on the Mapping screen (issue 25): "Find traces" asks the
// ProposalRunner for the lines of the 3D image on display that look like
// joint traces; they are drawn over the model (and over its photograph, in
// the side panel) coloured by confidence. A tap on one selects it; then
//  - Accept stores it as a trace exactly like a hand-marked one (the same
//    save, the same blocks update), with origin "proposed";
//  - Correct shows its two ends as handles: drag them where the trace really
//    ends and the path between them is traced again (least-cost tracing
//    through the photograph's dark line, core/measure/least_cost_trace.h);
//    Save correction stores it with origin "corrected";
//  - Reject hides it for the rest of the session (this model).
// Each proposal's screen position is recorded as a touch target named
// "proposal P3" (what a script taps).
#include <array>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <imgui.h>
#include <Eigen/Core>

#include "core/measure/proposals/trace_proposals.h"
#include "storage/project/project_records.h"

namespace rockface::ui {

struct AppState;
class PictureTexture;

// Find traces running: the worker appends each batch of proposals as it
// is measured; the screen takes what is new at each frame.
struct ArrivingProposals {
  std::mutex mutex;
  std::vector<measure::TraceProposal> proposals;
};

struct ProposalsState {
  storage::RecordId model_id = 0;  // the model the proposals were found on
  std::shared_ptr<const measure::ProposalResult> result;
  // While Find traces runs: the batches so far, how many of them `result`
  // holds, and whether `result` is made of them (unnamed proposals, named
  // "found N" by arrival, until the whole result replaces them).
  std::shared_ptr<ArrivingProposals> arriving;
  storage::RecordId arriving_model = 0;
  std::size_t arrived = 0;
  bool provisional = false;
  std::set<std::string> rejected, accepted;  // hidden for the session
  // Hidden too: proposals that lie along a trace already stored on this
  // model (the geologist mapped it by hand or accepted it before).
  std::set<std::string> mapped;
  std::optional<std::size_t> selected;  // index into result->proposals
  std::string problem;                  // why there are none (the runner's error)
  // Correcting the selected proposal: its ends on the model (dragged), the
  // handle being dragged (0, 1) or -1, and the path traced between them.
  std::optional<std::array<Eigen::Vector3d, 2>> ends;
  int dragging = -1;
  std::optional<measure::TraceMeasurement> corrected;
  std::string correction_problem;
  // The photograph with the proposals drawn, for the side panel.
  std::shared_ptr<PictureTexture> photo;
  bool photo_stale = true;
};

// Side panel: Find traces, the list, Accept / Correct / Reject, the photograph.
void draw_proposal_panel(AppState& app);
// Over the model panel (inside its clip rectangle): the proposals, the
// selected one wider, the correction's handles and path; records each
// proposal's touch target.
void draw_proposals_on_model(AppState& app);
// Before the model panel is drawn: the correction's handles as drag
// targets placed over it (so that dragging one does not turn the model).
void drag_proposal_ends(AppState& app);
// A tap on the model: selects the proposal under it (true) or leaves the
// tap to trace marking (false).
bool tap_proposal(AppState& app, ImVec2 tap);

}  // namespace rockface::ui
