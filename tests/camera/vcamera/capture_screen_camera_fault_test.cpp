// Issue 42: the Capture screen when the DSLR stops answering mid-shot, on
// libgphoto2's virtual D750 (tools/virtual-camera.sh) with the program's
// own runners (the DSLR found on USB, as `rockface ui` takes it). The left
// shot is taken but its download comes back short (the virtual camera's
// card file cut halfway: virtual_d750.h CardCutMidShot): the screen says what failed
// and where, and that the picture waits on the camera's card; once the
// camera answers, Shoot left fetches that picture (not a new one), the
// right shot is a new picture, and the pair is stored.
#include <cstdlib>
#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/camera/vcamera/virtual_d750.h"
#include "ui/app/app_state.h"
#include "ui/platform/headless_session.h"

namespace rockface {
namespace {

namespace fs = std::filesystem;

using test::bytes_of;

using CaptureScreenCameraFault = test::VirtualD750Fixture;

TEST_F(CaptureScreenCameraFault, AShotTheCameraCouldNotSendIsFetchedNotTakenAgain) {
  const test::VirtualD750& d750 = d750_;
  // The tablet's spool in the camera's folder, not the shared one.
  ::setenv("TMPDIR", d750.folder.c_str(), 1);
  const fs::path project = d750.folder / "site.rockface";
  storage::RecordId visit = 0;
  {
    storage::ProjectInfo info;
    info.name = "virtual D750";
    auto store = storage::ProjectStore::create(project, info);
    visit = store.begin_visit("tablet");
  }
  app::FieldRunners runners("");  // the first DSLR libgphoto2 finds
  ui::FieldServices services = runners.services();
  services.sync = nullptr;
  services.reconstruction = nullptr;  // stored, not reconstructed: no calibration here
  ui::UiOptions options;
  options.project = project;
  ui::HeadlessSession s(options, services, 1280, 800);
  s.settle();
  ui::AppState& app = s.state();
  s.tap("Capture");
  s.tap("Connect camera");
  s.settle();
  ASSERT_TRUE(app.capture.camera) << app.capture.connection;

  auto cut = std::make_unique<test::CardCutMidShot>(d750);
  s.tap("Shoot left");
  s.settle();
  s.frame();
  EXPECT_FALSE(app.capture.left);
  const auto capture_screen = static_cast<std::size_t>(ui::Screen::capture);
  const auto& errors = app.statuses.errors(capture_screen);
  ASSERT_FALSE(errors.empty());
  const std::string said = errors.back();
  const std::vector<std::string> pending = app.capture.camera->pending_downloads();
  ASSERT_EQ(pending.size(), 1u) << said;
  // What and where: the download of that picture failed; it is on the card,
  // and how to get it.
  EXPECT_NE(said.find("Downloading " + pending[0]), std::string::npos) << said;
  EXPECT_NE(said.find("The picture is on the camera's card (" +
                      fs::path(pending[0]).filename().string() + ")"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("tap Shoot left again"), std::string::npos) << said;

  // The camera answers again.
  ASSERT_TRUE(cut->cut());
  cut->restore();
  cut.reset();
  s.tap("Shoot left");
  s.settle();
  ASSERT_TRUE(app.capture.left) << app.statuses.line(capture_screen);
  EXPECT_EQ(app.capture.left->image.camera_path, pending[0]);
  EXPECT_EQ(bytes_of(app.capture.left->image.saved_path), d750.card_jpeg);
  EXPECT_NE(app.statuses.message(capture_screen).find("fetched from the camera's card"),
            std::string::npos)
      << app.statuses.message(capture_screen);
  EXPECT_TRUE(app.capture.camera->pending_downloads().empty());
  s.tap("Shoot right");
  s.settle();
  ASSERT_TRUE(app.capture.right) << app.statuses.line(capture_screen);
  EXPECT_NE(app.capture.right->image.camera_path, pending[0]);

  s.tap("Store pair and reconstruct");
  s.settle();
  auto store = storage::ProjectStore::open(project);
  const auto captures = store.list_captures(visit);
  ASSERT_EQ(captures.size(), 1u) << app.statuses.line(capture_screen);
  ::unsetenv("TMPDIR");
}

}  // namespace
}  // namespace rockface
