// The Capture screen at the face's pace (issue 45): a pair stored goes to
// the queue of 3D images, and the camera shoots the next pair while it is
// being made. The program's own services (app::FieldRunners: the mock
// camera of the demo scene, the store's reconstruction); the reconstruction
// is held at a gate until the next pair is shot, so what is checked does not
// depend on how fast this machine reconstructs.
#include <unistd.h>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <thread>

#include <gtest/gtest.h>

#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/ui/demo_project.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface;
using namespace rockface::ui;

// The store's reconstruction, started only once the gate opens.
class GatedReconstruction final : public ReconstructionRunner {
 public:
  explicit GatedReconstruction(ReconstructionRunner& real) : real_(real) {}
  storage::RecordId reconstruct(const fs::path& project, storage::RecordId capture_id,
                                Preset preset, Progress& progress) override {
    entered = true;
    while (!open) {
      progress.step("waiting at the test's gate", 0.01);  // a stop is heard here
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return real_.reconstruct(project, capture_id, preset, progress);
  }
  std::atomic<bool> entered{false}, open{false};

 private:
  ReconstructionRunner& real_;
};

// Frames until `done`, at most ~30 s of this machine's frames.
void run_until(HeadlessSession& s, const std::function<bool()>& done) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!done() && std::chrono::steady_clock::now() < until) {
    s.frame();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

// The tablet's camera spools its shots under the temporary folder
// (FieldCameraConnector); other tests and other tablets' runs write the
// same names there. This test's shots go to a folder of its own.
class OwnTemporaryFolder {
 public:
  OwnTemporaryFolder()
      : dir_(fs::temp_directory_path() /
             ("rockface-capture-queue-tmp-" + std::to_string(::getpid()))) {
    const char* was = std::getenv("TMPDIR");
    if (was) was_ = was;
    fs::create_directories(dir_);
    ::setenv("TMPDIR", dir_.c_str(), 1);
  }
  ~OwnTemporaryFolder() {
    if (was_)
      ::setenv("TMPDIR", was_->c_str(), 1);
    else
      ::unsetenv("TMPDIR");
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

 private:
  fs::path dir_;
  std::optional<std::string> was_;
};

TEST(CaptureQueue, TheNextPairIsShotWhileTheLastPairsImageIsMade) {
  const OwnTemporaryFolder own_tmp;
  const fs::path project = test::copy_of_demo("capture-queue");
  std::size_t captures = 0, models = 0;
  {
    auto store = storage::ProjectStore::open(project);
    captures = store.list_captures().size();
    models = store.list_models().size();
  }
  app::FieldRunners runners{test::demo_scene()};
  GatedReconstruction gated(runners.reconstruction);
  FieldServices services = runners.services();
  services.sync = nullptr;
  services.reconstruction = &gated;
  UiOptions options;
  options.project = project;
  options.max_display_triangles = 20000;
  options.scale = 0.6f;
  HeadlessSession s(options, services, 800, 500);
  s.settle();
  AppState& app = s.state();

  s.tap("Capture");
  s.tap("Connect camera");
  s.settle();
  ASSERT_TRUE(app.capture.camera) << app.capture.connection;
  s.tap("Shoot left");
  s.settle();
  s.tap("Shoot right");
  s.settle();
  ASSERT_TRUE(app.capture.left && app.capture.right);
  // The shots as the camera left them in the tablet's spool.
  std::vector<std::string> spooled{app.capture.left->image.saved_path,
                                   app.capture.right->image.saved_path};
  for (const auto& f : spooled) ASSERT_TRUE(fs::exists(f)) << f;
  s.tap("Store pair and reconstruct");
  run_until(s, [&] { return gated.entered.load(); });
  ASSERT_TRUE(gated.entered) << "the pair went to the queue";
  EXPECT_TRUE(app.reconstructions.busy());

  // The next pair while the first one's 3D image waits at the gate. The
  // demo scene's mock camera serves one pair (its two stations): connected
  // again, it serves the pair again, as the next station's would be.
  s.tap("Reconnect");
  run_until(s, [&] { return !app.task.running(); });
  s.tap("Shoot left");
  run_until(s, [&] { return !app.task.running(); });
  EXPECT_FALSE(app.capture.stored) << "a new left shot: the next pair";
  EXPECT_FALSE(app.capture.right) << "the stored pair's right shot is not the new pair's";
  s.tap("Shoot right");
  run_until(s, [&] { return !app.task.running(); });
  ASSERT_TRUE(app.capture.left && app.capture.right);
  spooled.push_back(app.capture.left->image.saved_path);
  spooled.push_back(app.capture.right->image.saved_path);
  EXPECT_TRUE(app.reconstructions.busy()) << "the first pair's 3D image is still being made";
  // And stored behind it: two pairs in the queue.
  s.tap("Store pair and reconstruct");
  s.frame();
  EXPECT_EQ(app.reconstructions.status().waiting, 1u);

  gated.open = true;
  s.settle();
  EXPECT_FALSE(app.reconstructions.busy());
  auto store = storage::ProjectStore::open(project);
  EXPECT_EQ(store.list_captures().size(), captures + 2);
  // Each pair's shots left the spool once the pair was in the project (the
  // spool had kept every shot a tablet ever took).
  for (const auto& f : spooled) EXPECT_FALSE(fs::exists(f)) << f;
  // Both pairs reconstructed, the second tied to the visit's face (the
  // runner's rule for a further pair; face_pair_runner_test.cpp checks it
  // against the truth).
  const auto all = store.list_models();
  ASSERT_EQ(all.size(), models + 2);
  EXPECT_EQ(all.back().registration_kind, "face_images");
}

}  // namespace
