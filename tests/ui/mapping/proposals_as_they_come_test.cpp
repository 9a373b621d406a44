// Issue 45: the tablet's Find traces shows the first proposals while the
// rest are still being found, on the demo project with the program's own
// proposal runner. The runner is held after its first batch (the work is
// the real one; only its pace is the test's), so the screen is seen in the
// state a geologist sees for the seconds the facets take on a 24 Mpx
// model: the longest chains' proposals drawn and listed, none of them
// offered to store yet; a proposal rejected then stays rejected under the
// name the whole result gives it, and every early proposal is one of the
// whole result's.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "firmware-app/services/ui_services.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::test;

// The program's proposal runner, held after its first batch until the
// test lets it go on.
class HeldAfterFirstBatch final : public ui::ProposalRunner {
 public:
  explicit HeldAfterFirstBatch(ui::ProposalRunner& real) : real_(real) {}

  measure::ProposalResult propose(const ui::ProposalInput& input, Progress& progress,
                                  const Batch& batch) override {
    return real_.propose(input, progress, [&](const std::vector<measure::TraceProposal>& b) {
      batch(b);
      std::unique_lock<std::mutex> lock(mutex_);
      if (batches_++ == 0) {
        first_ = b;
        changed_.notify_all();
        changed_.wait(lock, [this] { return released_; });
      }
    });
  }
  // Waits (bounded) for the first batch; false when it never came.
  bool wait_first(std::chrono::seconds limit) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, limit, [this] { return batches_ > 0; });
  }
  void release() {
    std::lock_guard<std::mutex> lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }
  std::vector<measure::TraceProposal> first() {
    std::lock_guard<std::mutex> lock(mutex_);
    return first_;
  }
  int batches() {
    std::lock_guard<std::mutex> lock(mutex_);
    return batches_;
  }

 private:
  ui::ProposalRunner& real_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int batches_ = 0;
  bool released_ = false;
  std::vector<measure::TraceProposal> first_;
};

// Lets the runner go on however the test ends: a held worker would keep the
// session's task (and its destructor's join) waiting for ever.
struct ReleaseOnExit {
  HeldAfterFirstBatch& held;
  ~ReleaseOnExit() { held.release(); }
};

bool shown(const ui::ProposalsState& s, const measure::TraceProposal& p) {
  return !s.rejected.count(p.id) && !s.accepted.count(p.id) && !s.mapped.count(p.id);
}

TEST(UiProposals, TheFirstProposalsShowWhileTheRestAreFound) {
  const fs::path project = copy_of_demo("proposals-as-they-come");
  app::FieldRunners runners{""};
  HeldAfterFirstBatch held(runners.proposals);
  ui::FieldServices services = runners.services();
  services.proposals = &held;
  services.sync = nullptr;
  services.camera = nullptr;
  ui::UiOptions options;
  options.project = project;
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  ui::HeadlessSession session(options, services, 800, 500);
  const ReleaseOnExit release_on_exit{held};
  session.settle();
  session.tap("Mapping");
  session.settle();
  ASSERT_TRUE(session.state().model_view.has_model());

  session.tap("Find traces");
  // The demo model's cues and first chains take a few seconds on 2 cores;
  // a minute means the first batch never came.
  ASSERT_TRUE(held.wait_first(std::chrono::seconds(60))) << "no first batch";
  session.frame();
  session.frame();
  const auto first = held.first();
  ASSERT_FALSE(first.empty()) << "the demo's longest chains are its traces";
  ASSERT_TRUE(session.state().task.running()) << "the runner is held: the search goes on";

  const ui::ProposalsState& s = session.state().mapping.proposals;
  ASSERT_TRUE(s.provisional);
  ASSERT_TRUE(s.result);
  ASSERT_EQ(s.result->proposals.size(), first.size());
  // The demo's hand-mapped traces hide the proposals along them; the first
  // batch holds at least one nobody mapped (its dark line P3).
  std::string unmapped;
  std::vector<Eigen::Vector3d> unmapped_points;
  for (const auto& p : s.result->proposals)
    if (shown(s, p)) {
      unmapped = p.id;
      unmapped_points = p.trace.points;
      break;
    }
  ASSERT_FALSE(unmapped.empty()) << "every first proposal lies along a mapped trace";
  EXPECT_EQ(unmapped.rfind("found ", 0), 0u) << unmapped << ": not yet named by rank";
  EXPECT_TRUE(session.state().targets.find("proposal " + unmapped))
      << "the early proposal is not drawn on the model";

  // Selected from the list: its figures show, but it cannot be stored
  // before all are found (the whole result names and ranks it).
  session.tap(unmapped);
  ASSERT_TRUE(s.selected);
  // (Read off the screen, not tapped: a finger's tap on a control the
  // task disables waits for the task, which the held runner never ends.)
  const auto accept = session.state().targets.find("Accept");
  ASSERT_TRUE(accept) << "no Accept for the selected proposal";
  EXPECT_FALSE(accept->enabled) << "an early proposal was offered to store";
  session.tap("Reject");
  EXPECT_TRUE(s.rejected.count(unmapped));

  held.release();
  session.settle();
  session.frame();
  ASSERT_FALSE(s.provisional);
  ASSERT_TRUE(s.result);
  // Every early proposal is one of the whole result's (the same points),
  // and the one rejected early stays rejected under its final name.
  for (const auto& e : first) {
    const measure::TraceProposal* same = nullptr;
    for (const auto& p : s.result->proposals)
      if (p.trace.points == e.trace.points) same = &p;
    ASSERT_TRUE(same) << "an early proposal of " << e.trace.length << " m is not in the result";
    EXPECT_EQ(same->id[0], 'P') << same->id;
    if (e.trace.points == unmapped_points) {
      EXPECT_TRUE(s.rejected.count(same->id)) << same->id << " was rejected as " << unmapped;
      EXPECT_FALSE(session.state().targets.find("proposal " + same->id))
          << "the rejected proposal is drawn again";
    }
  }
  EXPECT_FALSE(s.rejected.count(unmapped)) << "the early name outlived the result";
  fs::remove(project);
}

}  // namespace
