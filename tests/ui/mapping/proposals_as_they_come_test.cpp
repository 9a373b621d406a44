// Issue 45: the tablet's Find traces shows the first proposals while the
// rest are still being found, on the demo project with the program's own
// proposal runner. The runner is held after its first batch (the work is
// the real one; only its pace is the test's), so the screen is seen in the
// state a geologist sees for the seconds the facets take on a 24 Mpx
// model: the longest chains' proposals drawn and listed, none of them
// offered to store yet; a proposal rejected then stays rejected under the
// name the whole result gives it, and every early proposal is one of the
// whole result's. A second runner holds the facet search where it starts:
// the first batch must be on the screen by then.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string_view>
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

// The program's proposal runner with its facet search held where it starts
// (the first progress report of a "facets" stage) until the test lets it go
// on: what the screen shows then is what a geologist sees while the facets
// of a 24 Mpx model are sought.
class HeldAtTheFacets final : public ui::ProposalRunner {
 public:
  explicit HeldAtTheFacets(ui::ProposalRunner& real) : real_(real) {}

  measure::ProposalResult propose(const ui::ProposalInput& input, Progress& progress,
                                  const Batch& batch) override {
    Gate gate(progress, *this);
    return real_.propose(input, gate, [&](const std::vector<measure::TraceProposal>& b) {
      batch(b);
      std::lock_guard<std::mutex> lock(mutex_);
      ++batches_;
    });
  }
  // Waits (bounded) until the facet search starts; false when it never did.
  bool wait_facets(std::chrono::seconds limit) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, limit, [this] { return batches_before_facets_ >= 0; });
  }
  // The batches handed to the screen before the facet search started.
  int batches_before_facets() {
    std::lock_guard<std::mutex> lock(mutex_);
    return batches_before_facets_;
  }
  void release() {
    std::lock_guard<std::mutex> lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }

 private:
  // The worker's progress, held at the first "facets" stage.
  class Gate final : public Progress {
   public:
    Gate(Progress& outer, HeldAtTheFacets& held) : outer_(outer), held_(held) {}
    void report(std::string_view stage, double fraction) override {
      outer_.report(stage, fraction);
      if (stage.rfind("facets", 0) != 0) return;
      std::unique_lock<std::mutex> lock(held_.mutex_);
      if (held_.batches_before_facets_ < 0) {
        held_.batches_before_facets_ = held_.batches_;
        held_.changed_.notify_all();
      }
      held_.changed_.wait(lock, [this] { return held_.released_; });
    }
    bool cancel_requested() const override { return outer_.cancel_requested(); }

   private:
    Progress& outer_;
    HeldAtTheFacets& held_;
  };

  ui::ProposalRunner& real_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int batches_ = 0;
  int batches_before_facets_ = -1;  // -1: the facet search has not started
  bool released_ = false;
};

// Lets the runner go on however the test ends: a held worker would keep the
// session's task (and its destructor's join) waiting for ever.
template <typename Held>
struct ReleaseOnExit {
  Held& held;
  ~ReleaseOnExit() { held.release(); }
};

bool shown(const ui::ProposalsState& s, const measure::TraceProposal& p) {
  return !s.rejected.count(p.id) && !s.accepted.count(p.id) && !s.mapped.count(p.id);
}

// The program's runners with the proposals held by `held`; no office, no
// camera.
ui::FieldServices services_proposing_with(app::FieldRunners& runners, ui::ProposalRunner& held) {
  ui::FieldServices services = runners.services();
  services.proposals = &held;
  services.sync = nullptr;
  services.camera = nullptr;
  return services;
}

// A small viewport and a decimated model: the software renderer's cost.
ui::UiOptions mapping_options(const fs::path& project) {
  ui::UiOptions options;
  options.project = project;
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  return options;
}

TEST(UiProposals, TheFirstProposalsShowWhileTheRestAreFound) {
  const fs::path project = copy_of_demo("proposals-as-they-come");
  app::FieldRunners runners{""};
  HeldAfterFirstBatch held(runners.proposals);
  ui::HeadlessSession session(mapping_options(project), services_proposing_with(runners, held), 800,
                              500);
  const ReleaseOnExit<HeldAfterFirstBatch> release_on_exit{held};
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

// Issue 45: the first proposals are on the screen before the facets are
// sought (the seconds a 24 Mpx model's facets take are not waited for).
// The facet search is held where it starts: the first batch must already
// be drawn and listed then. Were the batch to come after the facets, the
// held search would give the screen nothing.
TEST(UiProposals, TheFirstProposalsAreOnTheScreenBeforeTheFacetsAreSought) {
  const fs::path project = copy_of_demo("proposals-before-facets");
  app::FieldRunners runners{""};
  HeldAtTheFacets held(runners.proposals);
  ui::HeadlessSession session(mapping_options(project), services_proposing_with(runners, held), 800,
                              500);
  const ReleaseOnExit<HeldAtTheFacets> release_on_exit{held};
  session.settle();
  session.tap("Mapping");
  session.settle();
  ASSERT_TRUE(session.state().model_view.has_model());

  session.tap("Find traces");
  // The demo model's cues and first chains take a few seconds on 2 cores;
  // a minute means the facet search never started.
  ASSERT_TRUE(held.wait_facets(std::chrono::seconds(60))) << "the facets were never sought";
  EXPECT_GE(held.batches_before_facets(), 1) << "the first batch waited for the facets";
  session.frame();
  session.frame();
  ASSERT_TRUE(session.state().task.running()) << "the facet search is held: the task goes on";
  const ui::ProposalsState& s = session.state().mapping.proposals;
  ASSERT_TRUE(s.provisional) << "no proposal on the screen while the facets are sought";
  ASSERT_TRUE(s.result);
  ASSERT_FALSE(s.result->proposals.empty());
  // Drawn on the model: at least one that no hand-mapped trace hides.
  bool drawn = false;
  for (const auto& p : s.result->proposals)
    drawn = drawn || (shown(s, p) && session.state().targets.find("proposal " + p.id));
  EXPECT_TRUE(drawn) << "the first proposals are listed but none is drawn";

  held.release();
  session.settle();
  session.frame();
  EXPECT_FALSE(s.provisional);
  ASSERT_TRUE(s.result);
  EXPECT_GE(s.result->proposals.size(), 1u);
  fs::remove(project);
}

}  // namespace
