// The screens on the headless renderer (surfaceless EGL, Mesa's software
// renderer) with the demo project loaded. Pictures are checked against what
// the project says: blocks drawn where and as many as the stored analysis
// has, the model drawn and moved by gestures, a read-only project saying why.
#include <sqlite3.h>

#include <cmath>
#include <fstream>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "storage/project/project_store.h"
#include "storage/report/report.h"
#include "tests/ui/demo_project.h"
#include "ui/app/ui_script.h"
#include "ui/mapping/trace_marker.h"
#include "ui/platform/headless_session.h"
#include "ui/view3d/display_mesh.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::copy_of_demo;
using rockface::test::demo_project;
using namespace rockface::ui;

// Small viewport and a decimated model: the software renderer's cost grows
// with pixels and triangles, and neither changes what is checked.
constexpr int kWidth = 800, kHeight = 500;
constexpr float kScale = 0.6f;
constexpr std::size_t kTriangles = 20000;

std::unique_ptr<HeadlessSession> open_session(const fs::path& project) {
  UiOptions options;
  options.project = project;
  options.scale = kScale;
  options.max_display_triangles = kTriangles;
  auto s = std::make_unique<HeadlessSession>(options, FieldServices{}, kWidth, kHeight);
  s->settle();  // the model loads on the worker
  return s;
}

cv::Vec3b bgr(ImU32 c) {
  return {static_cast<uchar>((c >> IM_COL32_B_SHIFT) & 0xFF),
          static_cast<uchar>((c >> IM_COL32_G_SHIFT) & 0xFF),
          static_cast<uchar>((c >> IM_COL32_R_SHIFT) & 0xFF)};
}

// Pixels of the model panel that are not the panel's clear colour.
int model_pixels(const cv::Mat& shot, const ModelView& view) {
  const cv::Vec3b clear(51, 46, 46);  // ModelRenderer's clear colour (0.18, 0.18, 0.2), BGR
  int n = 0;
  for (int y = static_cast<int>(view.panel_min().y) + 1; y < static_cast<int>(view.panel_max().y);
       ++y)
    for (int x = static_cast<int>(view.panel_min().x) + 1; x < static_cast<int>(view.panel_max().x);
         ++x) {
      const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
      if (cv::norm(cv::Vec3i(p) - cv::Vec3i(clear), cv::NORM_L1) > 6) ++n;
    }
  return n;
}

// A solid disc of `colour` centred at c: every pixel within 60 % of the
// marker radius has exactly that colour (an outline or a line is thinner).
bool solid_disc(const cv::Mat& shot, ImVec2 c, float radius, const cv::Vec3b& colour) {
  const int r = static_cast<int>(radius * 0.6f);
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > r * r) continue;
      const int x = static_cast<int>(std::lround(c.x)) + dx,
                y = static_cast<int>(std::lround(c.y)) + dy;
      if (x < 0 || y < 0 || x >= shot.cols || y >= shot.rows) return false;
      if (shot.at<cv::Vec3b>(y, x) != colour) return false;
    }
  return true;
}

TEST(UiScreens, EachScreenRendersWithTheDemoProjectLoaded) {
  auto s = open_session(demo_project());
  ASSERT_TRUE(s->state().session);
  ASSERT_TRUE(s->state().model_view.has_model());
  // Each screen's own control is on the screen after tapping its tab.
  const std::vector<std::pair<std::string, std::string>> screens = {
      {"Project", "Resume last visit"},
      {"Capture", "Shoot left"},
      {"Model", "Reset view"},
      {"Mapping", "Undo"},
      {"Blocks", "Run analysis"}};
  for (const auto& [tab, control] : screens) {
    s->tap(tab);
    EXPECT_TRUE(s->state().targets.find(control)) << tab << " lacks " << control;
    const cv::Mat shot = s->screenshot();
    ASSERT_EQ(shot.cols, kWidth);
    // Not a blank frame: the theme's white plus text, buttons and (on the
    // model screens) the photograph.
    cv::Mat grey;
    cv::cvtColor(shot, grey, cv::COLOR_BGR2GRAY);
    cv::Scalar mean, stddev;
    cv::meanStdDev(grey, mean, stddev);
    EXPECT_GT(stddev[0], 10) << tab;
  }
  s->tap("Model");
  const int drawn = model_pixels(s->screenshot(), s->state().model_view);
  const ImVec2 a = s->state().model_view.panel_min(), b = s->state().model_view.panel_max();
  // The face fills a good part of the panel when framed.
  EXPECT_GT(drawn, 0.2 * (b.x - a.x) * (b.y - a.y));
}

// Issue 42: the range pole's length is typed (in millimetres, as the pole
// is marked), not dragged on a slider that could not say 1.500 m; a length
// no pole has is not taken, and says why.
TEST(UiScreens, TheRangePolesLengthIsTypedInMillimetres) {
  auto s = open_session(demo_project());
  s->tap("Capture");
  s->tap("Type pole length");
  for (const char* key : {"1", "5", "0", "0"}) s->tap(key);
  s->tap("Set pole length");
  EXPECT_FLOAT_EQ(s->state().capture.range_pole_m, 1.5f);
  EXPECT_FALSE(s->state().capture.typing_pole);

  s->tap("Type pole length");
  for (const char* key : {"5", "0"}) s->tap(key);  // 50 mm: a pole's metres typed as mm?
  s->screenshot();
  const auto set = s->state().targets.find("Set pole length");
  ASSERT_TRUE(set);
  EXPECT_FALSE(set->enabled) << "a 5 cm pole was offered to set";
  s->tap("Cancel pole length");
  EXPECT_FLOAT_EQ(s->state().capture.range_pole_m, 1.5f) << "a cancelled entry changed the length";
}

TEST(UiScreens, TheModelIsDrawnWhereTheOverlaysProjectIt) {
  // The GLES renderer and the overlays (targets, traces, blocks) use the
  // same camera: the rendered silhouette's bounding box is the box of the
  // projected vertices.
  auto s = open_session(demo_project());
  s->tap("Model");
  const ModelView& view = s->state().model_view;
  const cv::Mat shot = s->screenshot();
  const cv::Vec3b clear(51, 46, 46);
  cv::Rect2f rendered;
  bool first = true;
  for (int y = static_cast<int>(view.panel_min().y) + 1;
       y < static_cast<int>(view.panel_max().y) - 1; ++y)
    for (int x = static_cast<int>(view.panel_min().x) + 1;
         x < static_cast<int>(view.panel_max().x) - 1; ++x) {
      const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
      if (cv::norm(cv::Vec3i(p) - cv::Vec3i(clear), cv::NORM_L1) <= 6) continue;
      // The range pole's target markers (yellow, kTargetColour, blended with
      // the dark background (46, 46, 51) at their edges: blue falls, red
      // and green rise; seen (61, 59, 47) at a circle's faint edge) are drawn over the model and
      // reach past its silhouette where a target sits at the edge of the 3D image (the demo's lower
      // target).
      if (p[0] < 60 && p[1] > p[0] + 6 && p[2] > p[0] + 6) continue;
      // The legend, scale bar and north arrow are flat marks over the panel.
      bool flat = false;
      for (const auto& [name, r] : view.flat_marks())
        flat = flat || (x >= r.first.x && x <= r.second.x && y >= r.first.y && y <= r.second.y);
      if (flat) continue;
      const cv::Rect2f px(static_cast<float>(x), static_cast<float>(y), 1, 1);
      rendered = first ? px : (rendered | px);
      first = false;
    }
  ASSERT_FALSE(first);
  const DisplayMesh& mesh = view.display_mesh();
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
  for (std::size_t i = 0; i < mesh.positions.size(); i += 3) {
    const Eigen::Vector3d p =
        mesh.centre +
        Eigen::Vector3d(mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]);
    const auto q = view.to_screen(p);
    ASSERT_TRUE(q);
    x0 = std::min(x0, q->x), y0 = std::min(y0, q->y), x1 = std::max(x1, q->x),
    y1 = std::max(y1, q->y);
  }
  // Within 2 px: pixel centres vs. vertex positions, and the float shader
  // against the double projection.
  EXPECT_NEAR(rendered.x, x0, 2);
  EXPECT_NEAR(rendered.y, y0, 2);
  EXPECT_NEAR(rendered.x + rendered.width, x1, 2);
  EXPECT_NEAR(rendered.y + rendered.height, y1, 2);
}

TEST(UiScreens, BlocksOnTheModelAreTheStoredAnalysisColouredByVerdict) {
  auto s = open_session(demo_project());
  s->tap("Blocks");
  const cv::Mat shot = s->screenshot();
  auto store = rockface::storage::ProjectStore::open(demo_project());
  const auto runs = store.list_analyses(store.latest_visit());
  ASSERT_FALSE(runs.empty());
  const auto run = store.load_analysis(runs.back().id);
  ASSERT_FALSE(run.blocks.empty());
  // Count the verdict markers in the picture; every block of the stored
  // analysis has one, of its verdict's colour.
  const float radius = 9 * kScale;
  int markers = 0;
  std::set<std::string> verdicts;
  for (const auto& stored : run.blocks) {
    const BlockView v = make_block_view(stored);
    const auto target = s->state().targets.find("block " + v.block.id);
    ASSERT_TRUE(target) << v.block.id << " not drawn";
    if (solid_disc(shot, target->centre(), radius, bgr(verdict_colour(v.verdict)))) ++markers;
    verdicts.insert(rockface::analysis::verdict_name(v.verdict));
  }
  EXPECT_EQ(markers, static_cast<int>(run.blocks.size()));
  // The demo's keyblock, from the traces picked in the photograph, moves.
  EXPECT_TRUE(verdicts.count("moves"));
  // And the table has one row per block.
  for (const auto& stored : run.blocks)
    EXPECT_TRUE(s->state().targets.find("row " + stored.id)) << stored.id;
}

TEST(UiScreens, TappingABlockShowsItsReport) {
  auto s = open_session(demo_project());
  s->tap("Blocks");
  const auto& blocks = s->state().session->blocks();
  std::size_t moving = blocks.size();
  for (std::size_t i = 0; i < blocks.size(); ++i)
    if (blocks[i].verdict == rockface::analysis::BlockVerdict::moves) moving = i;
  ASSERT_LT(moving, blocks.size());
  s->tap("row " + blocks[moving].block.id);
  ASSERT_TRUE(s->state().blocks.selected_block);
  EXPECT_EQ(*s->state().blocks.selected_block, moving);
  // A tap on the model outside every block clears the selection; one on a
  // block's marker selects a block whose outline holds the tap.
  const ImVec2 corner(s->state().model_view.panel_min().x + 3,
                      s->state().model_view.panel_min().y + 3);
  s->tap(corner.x, corner.y);
  EXPECT_FALSE(s->state().blocks.selected_block);
  s->tap("block " + blocks[moving].block.id);
  EXPECT_TRUE(s->state().blocks.selected_block);
}

TEST(UiScreens, PinchZoomsAndDragOrbitsTheModel) {
  auto s = open_session(demo_project());
  s->tap("Model");
  const ModelView& view = s->state().model_view;
  const cv::Mat before = s->screenshot();
  const int drawn = model_pixels(before, view);
  const Eigen::Vector2f centre((view.panel_min().x + view.panel_max().x) / 2,
                               (view.panel_min().y + view.panel_max().y) / 2);
  s->pinch(centre, 60, 120, 4);  // spread doubled: the model appears twice as large
  const int zoomed = model_pixels(s->screenshot(), view);
  EXPECT_GT(zoomed, 1.5 * drawn);
  s->state().model_view.camera().zoom(0.5f);  // back to the framed view
  s->drag(centre, centre + Eigen::Vector2f(120, 0), 6);
  const cv::Mat turned = s->screenshot();
  cv::Mat diff;
  cv::absdiff(before, turned, diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), 1000);  // the view turned
}

// Issue 45: a finger turning the 3D image gets the frame rate of the
// tablet's software renderer from the display mesh's turning copy (an
// eighth of the budget); the whole is drawn again when the finger stops.
TEST(UiScreens, TurningDrawsTheTurningCopyAndTheWholeAgainAfter) {
  auto s = open_session(demo_project());
  s->tap("Model");
  const ModelView& view = s->state().model_view;
  const int whole = static_cast<int>(view.display_mesh().triangle_count());
  const int copy = static_cast<int>(view.display_mesh().turning_indices.size() / 3);
  ASSERT_GT(copy, 0);
  EXPECT_LE(copy, static_cast<int>(kTriangles / kTurningBudgetDivisor));
  EXPECT_EQ(view.drawn_triangles(), whole);
  const Eigen::Vector2f centre((view.panel_min().x + view.panel_max().x) / 2,
                               (view.panel_min().y + view.panel_max().y) / 2);
  TouchInput& finger = s->input();
  finger.push({TouchEvent::Kind::down, 0, centre.x(), centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();  // the press reaches ImGui
  std::vector<int> drawn;
  for (int i = 1; i <= 4; ++i) {
    finger.push({TouchEvent::Kind::move, 0, centre.x() + 30.0f * i, centre.y()});
    s->frame();
    drawn.push_back(view.drawn_triangles());
  }
  // The first move may still be within the tap's slop; the later ones turn.
  EXPECT_EQ(drawn.back(), copy);
  const cv::Mat turning = s->screenshot();
  EXPECT_GT(model_pixels(turning, view), 0);  // the copy is drawn, not a blank panel
  finger.push({TouchEvent::Kind::up, 0, centre.x() + 120.0f, centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();  // released: the view is still
  EXPECT_EQ(view.drawn_triangles(), whole);
}

// Issue 45: a still model is not drawn again each frame (the software
// renderer took both of the tablet's cores sixty times a second while
// Find traces worked beside it); a move of the view draws it again.
TEST(UiScreens, AStillModelIsNotDrawnAgainEachFrame) {
  auto s = open_session(demo_project());
  s->tap("Model");
  s->settle();
  const ModelView& view = s->state().model_view;
  const long still = view.frames_drawn();
  ASSERT_GT(still, 0);
  // The model's panel on the screen (the rest may change: status lines).
  const auto panel = [&] {
    const cv::Rect r(
        cv::Point(static_cast<int>(view.panel_min().x) + 1,
                  static_cast<int>(view.panel_min().y) + 1),
        cv::Point(static_cast<int>(view.panel_max().x), static_cast<int>(view.panel_max().y)));
    return s->screenshot()(r).clone();
  };
  const cv::Mat before = panel();
  ASSERT_GT(model_pixels(s->screenshot(), view), 0);
  for (int k = 0; k < 10; ++k) s->frame();
  EXPECT_EQ(view.frames_drawn(), still);
  cv::Mat diff;
  cv::absdiff(before, panel(), diff);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1)), 0) << "the still model's panel changed";
  const Eigen::Vector2f centre((view.panel_min().x + view.panel_max().x) / 2,
                               (view.panel_min().y + view.panel_max().y) / 2);
  TouchInput& finger = s->input();
  finger.push({TouchEvent::Kind::down, 0, centre.x(), centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();
  for (int i = 1; i <= 4; ++i) {
    finger.push({TouchEvent::Kind::move, 0, centre.x() + 30.0f * i, centre.y()});
    s->frame();
  }
  finger.push({TouchEvent::Kind::up, 0, centre.x() + 120.0f, centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();
  EXPECT_GE(view.frames_drawn(), still + 3) << "the turned view was not drawn";
  cv::absdiff(before, panel(), diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), 0) << "the turned view shows the old frame";
}

// Issue 45: a frame that would draw what the screen already shows is not
// drawn (Mesa rasterised the whole screen sixty times a second); a frame
// with anything new is, the model turned by a finger (a texture's pixels
// only) among them, and a screen drawn from its last frame is the screen
// drawn afresh.
TEST(UiScreens, AFrameThatShowsNothingNewIsNotDrawn) {
  auto s = open_session(demo_project());
  s->tap("Mapping");
  s->settle();
  const long drawn = s->frames_drawn();
  const cv::Mat still = s->screenshot();
  for (int k = 0; k < 10; ++k) s->frame();
  EXPECT_EQ(s->frames_drawn(), drawn) << "a frame with nothing new was drawn";
  s->draw_again();
  s->frame();
  EXPECT_EQ(s->frames_drawn(), drawn + 1);
  cv::Mat diff;
  cv::absdiff(still, s->screenshot(), diff);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1)), 0)
      << "the kept frame is not the screen drawn afresh";

  // The model turned: only the model view's texture changes.
  const ModelView& view = s->state().model_view;
  const Eigen::Vector2f centre((view.panel_min().x + view.panel_max().x) / 2,
                               (view.panel_min().y + view.panel_max().y) / 2);
  TouchInput& finger = s->input();
  finger.push({TouchEvent::Kind::down, 0, centre.x(), centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();
  const long before_turn = s->frames_drawn();
  for (int i = 1; i <= 4; ++i) {
    finger.push({TouchEvent::Kind::move, 0, centre.x() + 30.0f * i, centre.y()});
    s->frame();
  }
  finger.push({TouchEvent::Kind::up, 0, centre.x() + 120.0f, centre.y()});
  for (int k = 0; k < 3; ++k) s->frame();
  EXPECT_GE(s->frames_drawn(), before_turn + 3) << "the turning model was not drawn";
  const cv::Mat turned = s->screenshot();
  cv::absdiff(still, turned, diff);
  EXPECT_GT(cv::countNonZero(diff.reshape(1)), 0) << "the screen still shows the model unturned";
  s->draw_again();
  s->frame();
  cv::absdiff(turned, s->screenshot(), diff);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1)), 0) << "the turned model's screen is stale";

  // A new screen is drawn.
  const long before_tab = s->frames_drawn();
  s->tap("Blocks");
  EXPECT_GT(s->frames_drawn(), before_tab);
}

TEST(UiScreens, TappedTraceAppearsWhereTappedAndIsStoredThere) {
  const fs::path project = copy_of_demo("mapping");
  auto s = open_session(project);
  s->tap("Mapping");
  const ModelView& view = s->state().model_view;
  const auto centre = view.to_screen(view.display_mesh().centre);
  ASSERT_TRUE(centre);
  // Four taps across the middle of the face.
  std::vector<ImVec2> taps;
  for (int i = 0; i < 4; ++i) taps.emplace_back(centre->x - 60 + 40 * i, centre->y - 30 + 20 * i);
  for (const auto& t : taps) s->tap(t.x, t.y);
  const TraceMarker& marker = s->state().mapping.marker;
  ASSERT_EQ(marker.taps().size(), 4u) << marker.problem();
  // Four points give a plane or say why not; either way the screen says it.
  ASSERT_TRUE(marker.plane());
  const cv::Mat shot = s->screenshot();
  for (const auto& t : taps)
    EXPECT_TRUE(solid_disc(shot, t, 7 * kScale, bgr(kPendingTraceColour)))
        << "no trace mark at " << t.x << ", " << t.y;
  s->tap("Undo");
  EXPECT_EQ(marker.taps().size(), 3u);
  s->tap(taps[3].x, taps[3].y);
  s->tap("Save trace");
  s->settle();
  EXPECT_TRUE(marker.taps().empty());  // saved: the next trace starts
  auto store = rockface::storage::ProjectStore::open(project);
  const auto measurements = store.list_measurements(store.latest_visit());
  const auto& saved = measurements.back();
  EXPECT_EQ(saved.kind, rockface::storage::Measurement::Kind::trace);
  ASSERT_EQ(saved.points.size(), taps.size());
  for (std::size_t i = 0; i < taps.size(); ++i) {
    const auto at = view.to_screen(saved.points[i]);
    ASSERT_TRUE(at);
    // A pick lies on the tap's ray: it projects back onto the tap within
    // float rounding of the ray (well under a pixel).
    EXPECT_NEAR(at->x, taps[i].x, 0.5);
    EXPECT_NEAR(at->y, taps[i].y, 0.5);
  }
}

// A visit photographed as two pairs: the Mapping screen offers each pair's
// 3D image; a trace mapped on pair 2's is stored with pair 2's model and
// capture, its points in the face frame (on pair 1's surface).
TEST(UiScreens, MappingOnAFurtherPairLandsInTheFaceFrameWithThatPair) {
  const fs::path project = rockface::test::ui_test_dir() / "mapping-two-pairs.rockface";
  fs::copy_file(rockface::test::two_pair_project(), project, fs::copy_options::overwrite_existing);
  auto s = open_session(project);
  const auto& pairs = s->state().session->pairs();
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(s->state().model_view.model_id(), pairs[0].id) << "pair 1 first";
  // The pair chosen as a script would (`rockface ui --script`): its button
  // by label, then the worker loads pair 2's model.
  const UiScript script = parse_ui_script(
      R"({"steps": [{"tap": "Mapping"}, {"tap": "Pair 2"}, {"wait": "task"}]})", "steps.json");
  for (std::size_t k = 0; k < script.steps.size(); ++k)
    s->run(script.steps[k], rockface::test::ui_test_dir(), "steps[" + std::to_string(k) + "]");
  const ModelView& view = s->state().model_view;
  ASSERT_EQ(view.model_id(), pairs[1].id);
  const auto centre = view.to_screen(view.display_mesh().centre);
  ASSERT_TRUE(centre);
  for (int i = 0; i < 4; ++i) s->tap(centre->x - 60 + 40 * i, centre->y - 30 + 20 * i);
  const TraceMarker& marker = s->state().mapping.marker;
  ASSERT_EQ(marker.taps().size(), 4u) << marker.problem();
  s->tap("Save trace");
  s->settle();
  EXPECT_TRUE(marker.taps().empty());

  auto store = rockface::storage::ProjectStore::open(project);
  const auto visit = store.latest_visit();
  const auto captures = store.list_captures(visit);
  ASSERT_EQ(captures.size(), 2u);
  const auto saved = store.list_measurements(visit).back();
  EXPECT_EQ(saved.kind, rockface::storage::Measurement::Kind::trace);
  EXPECT_EQ(saved.model_id, pairs[1].id);
  EXPECT_EQ(saved.photo_capture_id, captures[1].id);
  EXPECT_EQ(saved.photo, "left");
  ASSERT_EQ(saved.pixels.size(), 4u);
  // Pair 2's left photograph (1500 x 1000) sees the taps.
  for (const auto& px : saved.pixels) {
    EXPECT_GT(px.x(), 0);
    EXPECT_LT(px.x(), 1500);
    EXPECT_GT(px.y(), 0);
    EXPECT_LT(px.y(), 1000);
  }
  // The face frame: each point lies on pair 1's 3D image too. Expected:
  // pair 2's registration onto pair 1 (surface rms ~1 cm at the fast
  // preset) plus the spacing of pair 1's vertices (~2-3 cm at the fast
  // preset's half-scale matching, a nearest vertex is within ~2 cm):
  // under 5 cm. Pair 2's own camera frame is metres away (unscaled,
  // levelled at its camera).
  const auto first = store.load_model(pairs[0].id);
  ASSERT_EQ(saved.points.size(), 4u);
  for (const auto& p : saved.points) {
    double nearest = 1e9;
    for (const auto& v : first.mesh.vertices) nearest = std::min(nearest, (v - p).norm());
    std::printf("trace point on pair 2: %.3f m from pair 1's surface\n", nearest);
    EXPECT_LT(nearest, 0.05);
  }
}

// Issue 45: a project opens without reading every photograph first (a
// project of 50 visits is gigabytes); the whole file is checked on a thread
// of its own after, and a damaged photograph found there stops the saves
// and says so, where before the tablet refused to open the project at all.
TEST(UiScreens, APhotographDamagedOnTheCardIsFoundAfterTheProjectOpened) {
  const fs::path copy = copy_of_demo("damaged-photograph");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(copy.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  ASSERT_EQ(
      sqlite3_prepare_v2(db,
                         "SELECT pageno, (SELECT page_size FROM pragma_page_size) FROM dbstat "
                         "WHERE name = 'image' AND pagetype = 'overflow' ORDER BY pageno "
                         "LIMIT 1 OFFSET 20",
                         -1, &st, nullptr),
      SQLITE_OK);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW) << "the demo has no photograph pages";
  const sqlite3_int64 page = sqlite3_column_int64(st, 0), page_size = sqlite3_column_int64(st, 1);
  sqlite3_finalize(st);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  {
    std::fstream f(copy, std::ios::in | std::ios::out | std::ios::binary);
    const std::string pattern(static_cast<std::size_t>(page_size), '\x5A');
    f.seekp((page - 1) * page_size);
    f.write(pattern.data(), static_cast<std::streamsize>(pattern.size()));
  }
  auto s = open_session(copy);
  ASSERT_TRUE(s->state().session) << s->state().statuses.line(0);
  s->state().session->wait_for_file_check();
  s->frame();
  EXPECT_TRUE(s->state().session->read_only());
  const std::string reason = s->state().session->read_only_reason();
  EXPECT_NE(reason.find("damaged"), std::string::npos) << reason;
  EXPECT_NE(reason.find(copy.string()), std::string::npos) << reason;
  EXPECT_NE(s->state().statuses.line(0).find("damaged"), std::string::npos)
      << s->state().statuses.line(0);
  s->tap("Project");
  ASSERT_TRUE(s->state().targets.find("New visit"));
  EXPECT_FALSE(s->state().targets.find("New visit")->enabled);
}

TEST(UiScreens, ReadOnlyProjectSaysWhy) {
  const fs::path copy = copy_of_demo("newer");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(copy.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  auto s = open_session(copy);
  ASSERT_TRUE(s->state().session);
  EXPECT_TRUE(s->state().session->read_only());
  s->tap("Project");
  EXPECT_TRUE(s->state().targets.find("New visit"));
  EXPECT_FALSE(s->state().targets.find("New visit")->enabled);
  s->tap("Blocks");
  EXPECT_FALSE(s->state().targets.find("Run analysis")->enabled);
  // The status bar says why, on every screen.
  EXPECT_NE(s->state().session->read_only_reason().find("newer rockface"), std::string::npos)
      << s->state().session->read_only_reason();
  EXPECT_TRUE(s->state().targets.find("read-only notice"));
}

}  // namespace

// The motion after failure played on the Blocks screen: a stored block
// with `dynamics` gets Play / Pause and a time slider; playing moves the
// time on and draws the block's outline (orange) on the model.
TEST(UiScreens, BlockMotionAfterFailurePlaysOnTheModel) {
  const fs::path project = rockface::test::copy_of_demo("motion");
  std::string label;
  {
    auto store = rockface::storage::ProjectStore::open(project);
    auto run = store.load_analysis(store.list_analyses(store.latest_visit()).back().id);
    for (auto& b : run.blocks) {
      // The block as stored, in its report's JSON, given a motion.
      auto j = nlohmann::json::parse(rockface::storage::block_to_json(b));
      if (!j.contains("centroid") || !j.contains("vertices")) continue;
      // One second of motion: the block drops 0.5 m and turns 30 degrees
      // about the horizontal, sampled every 0.25 s.
      const Eigen::Vector3d c(j["centroid"][0], j["centroid"][1], j["centroid"][2]);
      nlohmann::json path = nlohmann::json::array();
      for (int k = 0; k <= 4; ++k) {
        const double t = 0.25 * k, a = 0.5 * (M_PI / 6) * t;
        path.push_back({{"t", t},
                        {"position", {c.x(), c.y(), c.z() - 0.5 * t * t}},
                        {"orientation", {std::cos(a), std::sin(a), 0, 0}},
                        {"velocity", {0, 0, -t}},
                        {"angular_velocity", {0.5, 0, 0}}});
      }
      j["dynamics"] = {
          {"trigger", "limit equilibrium: FoS 0.50 < 1"},
          {"outcome", "moving at the end"},
          {"events", {{{"time_s", 0.0}, {"kind", "slides"}, {"event", "slides on J1"}}}},
          {"path", path}};
      b.dynamics = rockface::storage::block_from_json(j.dump()).dynamics;
      label = b.id;
      break;
    }
    ASSERT_FALSE(label.empty());
    run.id = 0;
    store.save_analysis(run);
  }
  auto s = open_session(project);
  s->tap("Blocks");
  s->tap("row " + label);
  s->frame();
  ASSERT_TRUE(s->state().targets.find("Play motion")) << "no playback for " << label;
  EXPECT_TRUE(s->state().targets.find("motion time"));
  s->tap("Play motion");
  for (int i = 0; i < 20; ++i) s->frame();
  const MotionPlayback& m = s->state().blocks.motion;
  EXPECT_TRUE(m.playing || m.time >= 1.0);
  EXPECT_GT(m.time, 0.0);
  // The outline is drawn in the model panel.
  const cv::Mat shot = s->screenshot();
  const cv::Vec3b orange = bgr(IM_COL32(255, 80, 40, 255));
  int outline = 0;
  const ModelView& view = s->state().model_view;
  for (int y = static_cast<int>(view.panel_min().y); y < static_cast<int>(view.panel_max().y); ++y)
    for (int x = static_cast<int>(view.panel_min().x); x < static_cast<int>(view.panel_max().x);
         ++x)
      if (shot.at<cv::Vec3b>(y, x) == orange) ++outline;
  EXPECT_GT(outline, 30);
  // The pose at a sample time: the centroid is where the path says.
  const BlockView& b = s->state().session->blocks()[*s->state().blocks.selected_block];
  ASSERT_TRUE(b.block.dynamics);
  const Eigen::Vector3d c0 = b.block.dynamics->path.front().position;
  const auto at_half = posed_at({c0}, *b.block.dynamics, 0.5);
  ASSERT_EQ(at_half.size(), 1u);
  EXPECT_NEAR(c0.z() - at_half[0].z(), 0.125, 1e-9);  // 0.5 t^2 at t = 0.5, exact in doubles
}
