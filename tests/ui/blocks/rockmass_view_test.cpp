// The Blocks screen's Rock mass view on the headless renderer: the form's
// out-of-range value refused by name before anything reaches the worker,
// a valid form handed to the runner with the visit, and the lines it
// returns shown.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"

namespace {

using namespace rockface::ui;

// Stands for firmware-app's runner: records what it was asked.
class RecordingRunner final : public RockMassRunner {
 public:
  std::vector<std::string> figures(
      const std::filesystem::path&, rockface::storage::RecordId visit,
      const std::optional<rockface::rockmass::ClassificationForm>& save,
      rockface::Progress&) override {
    ++calls;
    visit_id = visit;
    saved = save;
    return {"RMR89 incomplete: stand-in", "Q 11.7 (good)"};
  }
  int calls = 0;
  rockface::storage::RecordId visit_id = 0;
  std::optional<rockface::rockmass::ClassificationForm> saved;
};

TEST(UiRockMassView, AFormValueOutOfRangeIsRefusedByNameAndAValidOneSaved) {
  UiOptions options;
  options.project = rockface::test::copy_of_demo("rockmass-view");
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  RecordingRunner runner;
  FieldServices services;
  services.rockmass = &runner;
  auto s = std::make_unique<HeadlessSession>(options, services, 800, 500);
  s->settle();
  s->tap("Blocks");
  ASSERT_TRUE(s->state().targets.find("Rock mass"));
  s->tap("Rock mass");
  ASSERT_TRUE(s->state().blocks.rockmass.open);
  s->frame();
  ASSERT_TRUE(s->state().targets.find("Save form"));

  s->state().blocks.rockmass.form.ja = 50;  // Ja's table ends at 20
  s->tap("Save form");
  s->settle();
  EXPECT_EQ(runner.calls, 0);
  EXPECT_NE(s->state().blocks.rockmass.refusal.find("Ja"), std::string::npos)
      << s->state().blocks.rockmass.refusal;

  s->state().blocks.rockmass.form.ja = 1.0;
  s->state().blocks.rockmass.form.jr = 1.5;
  s->tap("Save form");
  s->settle();
  EXPECT_EQ(runner.calls, 1);
  EXPECT_TRUE(s->state().blocks.rockmass.refusal.empty());
  ASSERT_TRUE(runner.saved);
  EXPECT_EQ(*runner.saved->ja, 1.0);
  EXPECT_EQ(runner.visit_id, *s->state().session->visit());
  ASSERT_EQ(s->state().blocks.rockmass.lines.size(), 2u);
  EXPECT_EQ(s->state().blocks.rockmass.lines[1], "Q 11.7 (good)");
}

}  // namespace
