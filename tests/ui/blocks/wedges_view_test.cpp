// The Blocks screen's Wedges view on the headless renderer: the view asks
// the WedgeRunner on the worker and shows its table, row by row, and its
// picture; without a runner it says so.
#include <gtest/gtest.h>

#include "core/common/error.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::demo_project;
using namespace rockface::ui;

class FakeWedges final : public WedgeRunner {
 public:
  int calls = 0;
  bool refuse = false;
  WedgeTable wedges(const fs::path&, rockface::storage::RecordId, const WedgeForm&,
                    rockface::Progress&) override {
    ++calls;
    if (refuse) throw rockface::InputError("project", "the project has no tunnel");
    WedgeTable t;
    t.lines = {"Section horseshoe at chainage 105.00 m"};
    t.columns = {"Wedge", "Where", "Factor of safety"};
    t.rows = {{"W1", "roof", "0.00"}, {"W2", "right wall", "1.35"}};
    t.marginal = {false, true};
    t.bgr = cv::Mat(60, 80, CV_8UC3, cv::Scalar(0, 0, 255));
    return t;
  }
};

std::unique_ptr<HeadlessSession> open_session(FakeWedges& fake) {
  UiOptions options;
  options.project = demo_project();
  options.scale = 0.6f;
  options.max_display_triangles = 20000;
  FieldServices services;
  services.wedges = &fake;
  auto s = std::make_unique<HeadlessSession>(options, services, 800, 500);
  s->settle();
  return s;
}

TEST(UiWedgesView, FindWedgesShowsTheRunnersTableRowByRow) {
  FakeWedges fake;
  auto s = open_session(fake);
  s->tap("Blocks");
  s->tap("Wedges view");
  ASSERT_TRUE(s->state().blocks.wedges.open);
  s->tap("Find wedges");
  s->settle();
  EXPECT_EQ(fake.calls, 1);
  ASSERT_TRUE(s->state().blocks.wedges.table);
  s->screenshot();  // one more frame draws the table
  EXPECT_TRUE(s->state().targets.find("wedge W1"));
  EXPECT_TRUE(s->state().targets.find("wedge W2"));
  EXPECT_FALSE(s->state().blocks.wedges.picture.empty());
  // Back to the blocks.
  s->tap("Blocks view");
  EXPECT_FALSE(s->state().blocks.wedges.open);
}

TEST(UiWedgesView, ARefusalIsShownInWords) {
  FakeWedges fake;
  fake.refuse = true;
  auto s = open_session(fake);
  s->tap("Blocks");
  s->tap("Wedges view");
  s->tap("Find wedges");
  s->settle();
  EXPECT_FALSE(s->state().blocks.wedges.table);
  EXPECT_NE(s->state().blocks.wedges.message.find("no tunnel"), std::string::npos)
      << s->state().blocks.wedges.message;
}

}  // namespace
