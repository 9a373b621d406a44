// Every screen of the demo project and of a visit photographed as three
// pairs, walked with the field services of the `rockface` program at the
// sizes of two tablets (1280 x 800 at 150 dpi, 1920 x 1200 at 225 dpi), in
// portrait, and in the tunnel theme. Every string drawn in every frame of
// the walk (ui/widgets/widgets_text.h records them) must fit the space it had, not
// look like a report key or JSON, name no library's field path
// ("trace.pixels[784]"), and carry no number of more than six significant
// digits; no text may be drawn that was not recorded (the glyphs of each
// frame's draw data are read back: ui/app/text_coverage.h); every touch target
// (buttons, table rows, sliders and their grabs, boxes, choices, markers on
// the model, a popup's Close) is 9 mm at the tablet's density; no string
// shows a machine's folder.
//
// Panels scroll by a drag of the finger (ui/widgets/widgets_scroll.h): on every
// screen the walk drags each panel until every target scrolled out of view
// has been in view (an open choice's list too), checking each frame there.
// The scroll bars are skipped: they are thin position indicators, not
// touch targets (a tap on one moves nothing: tests/ui/widgets/drag_scroll_test.cpp).
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/rockmass/classification_form.h"
#include "firmware-app/services/ui_services.h"
#include "tests/ui/demo_project.h"
#include "ui/app/text_check.h"
#include "ui/app/text_coverage.h"
#include "ui/app/ui_driver_scroll.h"
#include "ui/mapping/map_blocks.h"
#include "ui/platform/headless_session.h"
#include "ui/view3d/overlay_text.h"

namespace {

namespace fs = std::filesystem;
using namespace rockface::ui;

// The model view's cost grows with triangles, and what is checked is text.
constexpr std::size_t kTriangles = 20000;

struct Tablet {
  int width, height;
  float scale;  // the layout of a 10" 1280 x 800 tablet at this density
  Theme theme;
  std::string name;
};

// The services `rockface ui` composes (app::FieldRunners), without the
// office server: its panel needs a PostgreSQL server (tests/storage/office taps it).
struct Services {
  rockface::app::FieldRunners runners{rockface::test::demo_scene()};
  FieldServices all() {
    FieldServices s = runners.services();
    s.sync = nullptr;
    return s;
  }
};

class Walk {
 public:
  Walk(const fs::path& project, const Tablet& tablet) : tablet_(tablet) {
    const fs::path settings = rockface::test::ui_test_dir() / ("walk-" + tablet.name + ".json");
    save_ui_settings(settings, UiSettings{tablet.theme, {}});
    UiOptions options;
    options.project = project;
    options.scale = tablet.scale;
    options.max_display_triangles = kTriangles;
    options.settings_file = settings;
    session_ =
        std::make_unique<HeadlessSession>(options, services_.all(), tablet.width, tablet.height);
    session_->settle();
    check("opening");
  }

  HeadlessSession& s() { return *session_; }

  // Checks the last frame's strings and buttons.
  void check(const std::string& where) {
    const AppState& app = session_->state();
    const std::string at = tablet_.name + ", " + screen_name(app.screen) + " (" + where + ")";
    for (const DrawnText& d : drawn_text()) {
      if (const std::string why = text_problem(d); !why.empty()) problems_.insert(at + ": " + why);
      for (const char* folder : {"/work/", "/home/", "/tmp/"})
        if (d.text.find(folder) != std::string::npos)
          problems_.insert(at + ": \"" + d.text + "\" shows a machine's folder");
      ++strings_;
    }
    // Text drawn that the record does not hold: unseen by the checks above.
    for (const UnrecordedText& u : unrecorded_text_in_last_frame(drawn_text()))
      problems_.insert(at + ": \"" + u.characters + "\" drawn in " + u.panel +
                       " without being recorded");
    // Words drawn straight onto a picture (ui/view3d/overlay_text.h) lie inside it.
    for (const PlacedText& p : placed_texts())
      if (const std::string why = placement_problem(p); !why.empty())
        problems_.insert(at + ": " + why);
    // Every touch target 9 mm at the density the scale stands for, less half
    // a pixel of ImGui's rounding of item rectangles.
    for (const std::string& small : small_touch_targets(app.targets, 0.5f))
      problems_.insert(at + ": " + small);
    targets_ += static_cast<int>(app.targets.all().size());
    for (const auto& [label, r] : app.targets.all())
      if (r.touch && shown_whole(r)) seen_whole_.insert(label);
  }

  // Brings every touch target of the screen that a drag can reach into
  // view, as a finger scrolls its panel, and checks the frame there. A
  // target cut only by the 3D image's edge is no drag's business.
  void sweep(const std::string& where) {
    std::set<std::string> tried;
    for (;;) {
      std::string next;
      for (const auto& [label, r] : session_->state().targets.all())
        if (r.touch && !shown_whole(r) && scrolled_out_of_view(r) && !tried.count(label) &&
            !seen_whole_.count(label)) {
          next = label;
          break;
        }
      if (next.empty()) return;
      tried.insert(next);
      try {
        drags_ += session_->bring_into_view(next, where);
      } catch (const rockface::InputError& e) {
        problems_.insert(std::string(tablet_.name) + " (" + where + "): " + e.what());
        continue;
      }
      session_->frame();
      check(where + ", dragged to " + next);
    }
  }

  void tap(const std::string& label, const std::string& where = "") {
    session_->tap(label);
    session_->frame();
    check(where.empty() ? "after " + label : where);
  }
  void tap_and_wait(const std::string& label) {
    session_->tap(label);
    session_->settle();
    check("after " + label);
  }

  // The strings checked so far (a walk that saw nothing proves nothing).
  int strings() const { return strings_; }
  int targets() const { return targets_; }
  // The drags made to bring targets into view, and every touch target seen
  // whole at a check.
  int drags() const { return drags_; }
  void count_map_block_tap() { ++map_block_taps_; }
  int map_block_taps() const { return map_block_taps_; }
  const std::set<std::string>& seen_whole() const { return seen_whole_; }
  const std::set<std::string>& problems() const { return problems_; }

 private:
  Tablet tablet_;
  Services services_;
  std::unique_ptr<HeadlessSession> session_;
  std::set<std::string> problems_;
  int strings_ = 0;
  int targets_ = 0;
  int drags_ = 0;
  int map_block_taps_ = 0;
  std::set<std::string> seen_whole_;
};

// Every screen and view the geologist reaches from the tabs.
void walk_every_screen(Walk& w) {
  AppState& app = w.s().state();
  w.tap("Project");
  w.sweep("the project screen");
  // The project's name, shortened at the top right, is one tap from whole.
  w.tap("Capture");
  w.tap_and_wait("Connect camera");
  w.tap_and_wait("Shoot left");
  w.tap_and_wait("Shoot right");
  w.sweep("the capture screen");
  w.tap("Model");
  w.tap("Photograph");  // the targets' rings and labels on the photograph
  w.tap("3D image");
  w.sweep("the model screen");
  // The Model tab's load of the 3D image may still run on the worker, and
  // the pair buttons are disabled until it is done.
  w.tap_and_wait("Mapping");
  for (std::size_t k = 0; k < app.session->pairs().size(); ++k) {
    const std::string pair = "Pair " + std::to_string(k + 1);
    if (app.targets.find(pair)) w.tap_and_wait(pair);
  }
  w.sweep("the mapping screen");
  // A block's marker on the 3D image is a touch target: a tap selects the
  // block and its verdict is shown in words (beside it and in the panel);
  // a second tap takes the selection back.
  for (const auto& [label, r] : std::map<std::string, TargetRect>(app.targets.all())) {
    if (label.rfind("map block ", 0) != 0 || !r.visible) continue;
    w.tap(label, "a block on the map selected");
    const std::string words = selected_map_block_in_words(app.mapping.blocks);
    EXPECT_EQ(words.rfind(label.substr(10) + " ", 0), 0u)
        << label << " selected no block: " << words;
    bool shown = false;
    for (const DrawnText& d : drawn_text()) shown = shown || d.text == words + ".";
    EXPECT_TRUE(shown) << "the Mapping screen does not show " << label << "'s verdict";
    w.tap(label, "a block on the map unselected");
    EXPECT_TRUE(selected_map_block_in_words(app.mapping.blocks).empty());
    w.count_map_block_tap();
    break;
  }
  // A trace being marked: its live fit in words.
  const ModelView& view = app.model_view;
  if (const auto centre = view.to_screen(view.display_mesh().centre)) {
    for (int i = 0; i < 4; ++i) w.s().tap(centre->x - 60 + 40 * i, centre->y - 30 + 20 * i);
    w.s().frame();
    w.check("a trace of four taps");
    // A tap off the 3D surface (the view's top left corner, beyond the
    // face): the screen says what happened and what to do, in words.
    const ImVec2 corner = view.panel_min();
    w.s().tap(corner.x + 4, corner.y + 4);
    w.s().frame();
    w.check("a tap off the surface");
    EXPECT_EQ(app.mapping.marker.problem(), "This tap is off the 3D surface: tap on the rock.");
    bool said = false;
    for (const DrawnText& d : drawn_text()) said = said || d.text == app.mapping.marker.problem();
    EXPECT_TRUE(said) << "the Mapping screen does not show why the tap was refused";
  }
  w.tap("Blocks");
  const auto& blocks = app.session->blocks();
  ASSERT_FALSE(blocks.empty());
  w.sweep("the blocks screen");
  w.tap("row " + blocks.front().block.id, "a block's report");
  w.sweep("a block's report");
  w.tap("Rock mass");
  w.sweep("the rock mass form");
  // A choice of the form open: its list scrolls by a drag like any panel,
  // and every item in it is brought into view and checked.
  w.tap("roughness", "the roughness choice open");
  w.sweep("the roughness choice open");
  std::vector<std::string> items = {"not entered"};
  for (const std::string& word : rockface::rockmass::roughness_words()) items.push_back(word);
  for (const std::string& item : items)
    EXPECT_TRUE(w.seen_whole().count("roughness: " + item))
        << "the walk never saw the roughness choice's item \"" << item << "\" in view";
  w.tap("roughness: not entered", "the roughness choice closed");
  w.tap_and_wait("Rock mass figures");
  w.tap("Block report");
  w.tap("Wedges view");
  w.tap_and_wait("Find wedges");
  w.sweep("the wedges");
  w.tap("Blocks view");
}

void expect_clean(const Walk& w) {
  EXPECT_GT(w.strings(), 200) << "the walk saw too few strings to mean anything";
  EXPECT_GT(w.targets(), 100) << "the walk saw too few touch targets to mean anything";
  // The open choice's list at least is longer than it shows.
  EXPECT_GT(w.drags(), 0) << "no panel was dragged: what is scrolled out of view went unseen";
  std::printf("drags to bring targets into view: %d\n", w.drags());
  std::string all;
  for (const auto& p : w.problems()) all += p + "\n";
  EXPECT_TRUE(w.problems().empty()) << w.problems().size() << " problems:\n" << all;
}

const std::vector<Tablet>& tablets() {
  static const std::vector<Tablet> t = {
      {1280, 800, 1.0f, Theme::daylight, "1280x800"},
      {1920, 1200, 1.5f, Theme::daylight, "1920x1200"},
  };
  return t;
}

TEST(UiTextWalk, TheDemoProjectReadsCleanOnBothTablets) {
  for (const Tablet& tablet : tablets()) {
    Walk w(rockface::test::copy_of_demo("walk-demo-" + tablet.name), tablet);
    walk_every_screen(w);
    expect_clean(w);
    // The demo's traces close finite blocks on the map: one was tapped.
    EXPECT_EQ(w.map_block_taps(), 1) << "no block's marker on the Mapping screen was tapped";
  }
}

TEST(UiTextWalk, AThreePairVisitReadsCleanOnBothTablets) {
  for (const Tablet& tablet : tablets()) {
    const fs::path project =
        rockface::test::ui_test_dir() / ("walk-three-pairs-" + tablet.name + ".rockface");
    fs::copy_file(rockface::test::three_pair_project(), project,
                  fs::copy_options::overwrite_existing);
    Walk w(project, tablet);
    ASSERT_EQ(w.s().state().session->pairs().size(), 3u);
    walk_every_screen(w);
    expect_clean(w);
  }
}

TEST(UiTextWalk, PortraitAndTheTunnelThemeReadClean) {
  for (const Tablet& tablet : {Tablet{800, 1280, 1.0f, Theme::daylight, "portrait"},
                               Tablet{1280, 800, 1.0f, Theme::tunnel, "tunnel"}}) {
    Walk w(rockface::test::copy_of_demo("walk-" + tablet.name), tablet);
    walk_every_screen(w);
    expect_clean(w);
  }
}

// The checks themselves: what they must catch.
TEST(UiTextWalk, TheChecksCatchKeysJsonLongNumbersAndOverflow) {
  EXPECT_TRUE(looks_like_key("sigma_z: 0.014"));
  EXPECT_TRUE(looks_like_key("dense: image_scale: 1"));
  EXPECT_FALSE(looks_like_key("Point precision: ± 14 mm"));
  EXPECT_FALSE(looks_like_key("FACE_E 0.49 m²"));  // an upper-case face name is not a key
  EXPECT_TRUE(looks_like_json(R"(dense: {"image_scale":1.0})"));
  EXPECT_FALSE(looks_like_json("{J1, J2}"));
  EXPECT_EQ(overlong_number("R 0.98327071179"), "0.98327071179");
  EXPECT_EQ(overlong_number("1,234,567 points"), "1,234,567");
  EXPECT_FALSE(overlong_number("150,327 points, 0.0021 m, 2026-11-26 03:45"));
  EXPECT_TRUE(text_problem({"fits", 100, 100, "panel"}).empty());
  EXPECT_NE(text_problem({"too wide", 140, 100, "panel"}).find("140 px wide in 100 px"),
            std::string::npos);
}

}  // namespace
