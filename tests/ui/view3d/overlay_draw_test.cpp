// What is drawn on the 3D image lies on it (issue 27): the demo project's
// Mapping and Blocks screens rendered headless (surfaceless EGL, Mesa) at
// the two tablet sizes, 1280 x 800 and 1920 x 1200. Every vertex of every
// trace and block the renderer drew is put back onto the stored,
// full-resolution surface (core/measure's picker) and must lie on it; and in
// the picture no pixel of a trace's or a block's colour lies outside the
// model's silhouette (off the mesh, over the background).
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "firmware-app/services/ui_services.h"
#include "storage/project/project_store.h"
#include "tests/ui/demo_project.h"
#include "ui/platform/headless_session.h"
#include "ui/view3d/overlay_blocks.h"
#include "ui/view3d/overlay_traces.h"
#include "ui/widgets/widgets.h"

namespace {

namespace fs = std::filesystem;
using rockface::test::demo_project;
using namespace rockface::ui;

// A decimated model: the software renderer's cost grows with triangles, and
// the checks hold at any budget (the tolerance below follows the cell).
constexpr std::size_t kTriangles = 20000;

struct Size {
  int width, height;
  float scale;  // 1 = a 1280 x 800 tablet
};
const Size kSizes[] = {{1280, 800, 1.0f}, {1920, 1200, 1.5f}};

// The legend's swatches have the lines' colours and sit over the background
// by design: they are flat marks, not drawn on the 3D image.
bool in_flat_mark(const ModelView& v, int x, int y) {
  for (const auto& [name, r] : v.flat_marks())
    if (x >= r.first.x && x <= r.second.x && y >= r.first.y && y <= r.second.y) return true;
  return false;
}

// The demo project with one more trace, T1 drawn on three times as long
// (past the 3D image at both ends, into the air beyond the face's edges and
// in front of it): what a trace mapped on another pair's 3D image, or one
// picked across the whole photograph, looks like against this image.
const fs::path& demo_with_long_trace() {
  static const fs::path project = [] {
    const fs::path p = rockface::test::copy_of_demo("overlay");
    auto store = rockface::storage::ProjectStore::open(p);
    const auto visit = *store.latest_visit();
    const auto measurements = store.list_measurements(visit);
    for (const auto& m : measurements)
      if (m.kind == rockface::storage::Measurement::Kind::trace && m.label == "T1") {
        rockface::storage::Measurement t = m;
        t.id = 0;
        t.label = "T9";
        const Eigen::Vector3d a = m.points.front(), b = m.points.back();
        t.points = {a - (b - a), a, b, b + (b - a)};
        t.pixels.clear();
        t.photo.clear();
        t.photo_capture_id.reset();
        store.save_measurements(visit, {t});
      }
    return p;
  }();
  return project;
}

class OverlayDraw : public ::testing::TestWithParam<Size> {
 protected:
  void SetUp() override {
    UiOptions options;
    options.project = demo_with_long_trace();
    options.scale = GetParam().scale;
    options.max_display_triangles = kTriangles;
    FieldServices services;
    services.trace_map = &trace_map_;  // the Mapping screen's blocks
    session_ =
        std::make_unique<HeadlessSession>(options, services, GetParam().width, GetParam().height);
    session_->settle();
    ASSERT_TRUE(session_->state().model_view.has_model());
  }
  AppState& app() { return session_->state(); }
  const ModelView& view() { return session_->state().model_view; }

  // How far a drawn vertex may be from the stored surface: the displayed
  // surface is the stored one decimated by vertex clustering, each vertex
  // moved by at most a cell's diagonal, and a point inside a displayed
  // triangle is further within the stored surface's own point spacing of
  // the stored triangles under it.
  double on_surface_tolerance() {
    return std::sqrt(3.0) * view().display_mesh().cell + view().surface()->median_edge_length();
  }

  // The distance from a point to the stored surface along the drape
  // direction, or nothing when the surface is not within `reach`.
  std::optional<double> off_surface(const Eigen::Vector3d& p, double reach) {
    const Eigen::Vector3d d = view().drape()->direction();
    const auto hit = view().picker()->pick(rockface::measure::Ray{p + d * reach, -d});
    if (!hit || hit->distance > 2 * reach) return std::nullopt;
    return std::abs(hit->distance - reach);
  }

  // Checks every vertex of the drawn lines and fills whose label starts
  // with `prefix`; returns how many were checked.
  int check_vertices(const std::string& prefix) {
    const double tol = on_surface_tolerance();
    int checked = 0, off = 0;
    auto check = [&](const std::string& what, const Eigen::Vector3d& p) {
      ++checked;
      if (!off_surface(p, tol) && ++off <= 5) {
        ADD_FAILURE() << what << ": vertex (" << p.transpose() << ") drawn off the mesh (beyond "
                      << tol << " m)";
      }
    };
    const OverlayScene& drawn = view().drawn_overlay();
    for (const auto& l : drawn.lines)
      if (l.what.rfind(prefix, 0) == 0)
        for (const auto& p : l.points) check(l.what, p);
    for (const auto& f : drawn.fills)
      if (f.what.rfind(prefix, 0) == 0)
        for (const auto& p : f.triangles) check(f.what, p);
    EXPECT_EQ(off, 0) << off << " of " << checked << " vertices of " << prefix << " off the mesh";
    return checked;
  }

  // Pixels of one of `colours` (exactly: lines are drawn opaque, without
  // antialiasing) in the model panel that lie outside the model's
  // silhouette grown by `margin` px (a ribbon's half width reaches past the
  // silhouette where a line runs along the border of the 3D image); and how
  // many there are of them in all.
  std::pair<int, int> pixels_off_model(const cv::Mat& shot, const std::set<std::uint32_t>& colours,
                                       int margin) {
    const ModelView& v = view();
    const DisplayMesh& mesh = v.display_mesh();
    cv::Mat silhouette(shot.size(), CV_8U, cv::Scalar(0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      cv::Point corners[3];
      bool visible = true;
      for (int k = 0; k < 3; ++k) {
        const std::size_t i = 3 * mesh.indices[t + k];
        const auto q =
            v.to_screen(mesh.centre + Eigen::Vector3d(mesh.positions[i], mesh.positions[i + 1],
                                                      mesh.positions[i + 2]));
        if (!q)
          visible = false;
        else
          corners[k] =
              cv::Point(static_cast<int>(std::lround(q->x)), static_cast<int>(std::lround(q->y)));
      }
      if (visible) cv::fillConvexPoly(silhouette, corners, 3, cv::Scalar(255));
    }
    cv::dilate(
        silhouette, silhouette,
        cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * margin + 1, 2 * margin + 1)));
    int off = 0, all = 0;
    for (int y = static_cast<int>(v.panel_min().y) + 1; y < static_cast<int>(v.panel_max().y) - 1;
         ++y)
      for (int x = static_cast<int>(v.panel_min().x) + 1; x < static_cast<int>(v.panel_max().x) - 1;
           ++x) {
        const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
        const std::uint32_t rgb = p[2] | (p[1] << 8) | (p[0] << 16);
        if (!colours.count(rgb) || in_flat_mark(v, x, y)) continue;
        ++all;
        if (!silhouette.at<std::uint8_t>(y, x)) ++off;
      }
    return {off, all};
  }

  std::unique_ptr<HeadlessSession> session_;
  rockface::app::StoreTraceMapRunner trace_map_;
};

std::uint32_t rgb_of(ImU32 c) {
  return c & 0x00FFFFFFu;
}

TEST_P(OverlayDraw, TracesOnTheMappingScreenLieOnTheMesh) {
  session_->tap("Mapping");
  session_->settle();  // the map's blocks come from the worker
  session_->frame();
  const auto& measurements = app().session->measurements();
  // T9 runs past the 3D image: the clipping has something to clip.
  int stored_off = 0, stored = 0;
  std::set<std::uint32_t> colours;
  for (const auto& m : measurements)
    if (m.kind == rockface::storage::Measurement::Kind::trace) {
      colours.insert(rgb_of(joint_colour(m.joint_label, app().session->joints())));
      for (const auto& p : m.points) {
        ++stored;
        stored_off += !off_surface(p, 0.25).has_value();  // 25 cm: far off, not noise
      }
    }
  ASSERT_GT(stored, 0);
  std::printf("stored trace points off the 3D image: %d of %d\n", stored_off, stored);
  EXPECT_GT(stored_off, 0)
      << "the demo's traces no longer leave the 3D image: the test clips nothing";

  std::set<std::string> drawn;
  for (const auto& l : view().drawn_overlay().lines)
    if (l.what.rfind("trace ", 0) == 0) drawn.insert(l.what);
  // Each of the demo's traces crosses the 3D image.
  for (const auto& m : measurements) {
    if (m.kind == rockface::storage::Measurement::Kind::trace) {
      EXPECT_TRUE(drawn.count("trace " + m.label)) << m.label << " not drawn";
    }
  }
  EXPECT_GT(check_vertices("trace "), 100);
  EXPECT_GT(check_vertices("block "), 3);  // the map's block TB1, laid on the face

  const float half = 2 * app().targets.scale();  // traces are 4 px wide at scale 1
  const auto [off, all] =
      pixels_off_model(session_->screenshot(), colours, static_cast<int>(std::ceil(half)) + 1);
  EXPECT_GT(all, 200) << "no trace drawn in the picture";
  EXPECT_EQ(off, 0) << off << " of " << all << " trace pixels over the background";
}

TEST_P(OverlayDraw, BlocksOnTheBlocksScreenLieOnTheMappedFace) {
  session_->tap("Blocks");
  session_->frame();
  ASSERT_FALSE(app().session->blocks().empty());
  std::set<std::uint32_t> colours;
  std::set<std::string> drawn;
  for (const auto& b : app().session->blocks()) colours.insert(rgb_of(verdict_colour(b.verdict)));
  for (const auto& l : view().drawn_overlay().lines) drawn.insert(l.what);
  for (const auto& b : app().session->blocks()) {
    EXPECT_TRUE(drawn.count("block " + b.label + " edge")) << b.label << " not outlined";
  }
  EXPECT_GT(check_vertices("block "), 3);
  // Block outlines are 3 px wide at scale 1.
  const int margin = static_cast<int>(std::ceil(1.5f * app().targets.scale())) + 1;
  const auto [off, all] = pixels_off_model(session_->screenshot(), colours, margin);
  EXPECT_GT(all, 50) << "no block drawn in the picture";
  EXPECT_EQ(off, 0) << off << " of " << all << " block pixels over the background";
}

INSTANTIATE_TEST_SUITE_P(TabletSizes, OverlayDraw, ::testing::ValuesIn(kSizes),
                         [](const ::testing::TestParamInfo<Size>& info) {
                           return std::to_string(info.param.width) + "x" +
                                  std::to_string(info.param.height);
                         });

// A block whose footprint runs past the 3D image: the part on the image is
// tinted, the image's border inside the footprint is drawn dashed (open /
// unknown), and nothing lies beyond the image.
TEST(OverlayBlocks, AFootprintPastTheImageIsClippedAndItsOpenSideDashed) {
  UiOptions options;
  options.project = demo_project();
  options.max_display_triangles = kTriangles;
  HeadlessSession s(options, FieldServices{}, 800, 500);
  s.settle();
  const ModelView& view = s.state().model_view;
  const SurfaceDrape& drape = *view.drape();
  // A square twice the 3D image's size around its centre, on its mean plane.
  const Eigen::Vector3d c = view.display_mesh().centre;
  const Eigen::Vector3d u = drape.direction().unitOrthogonal(), w = drape.direction().cross(u);
  const double r = 2 * view.display_mesh().radius;
  const std::vector<Eigen::Vector3d> square{c - r * u - r * w, c + r * u - r * w, c + r * u + r * w,
                                            c - r * u + r * w};
  const BlockOnFace laid = lay_block(square, drape);
  // The whole image is inside: every displayed triangle is tinted, no edge of
  // the square is on it, and the image's whole border is open.
  EXPECT_EQ(laid.fill.size(), 3 * view.display_mesh().triangle_count());
  EXPECT_TRUE(laid.edges.empty());
  ASSERT_FALSE(laid.open.empty());
  for (const auto& line : laid.open) {
    for (const auto& p : line) {
      EXPECT_TRUE(drape.project(p)) << "open border off the surface";
    }
  }
  OverlayScene scene;
  add_block_to_overlay(scene, "X", laid, IM_COL32(230, 20, 20, 255), true, 3);
  bool dashed = false;
  for (const auto& l : scene.lines) dashed = dashed || l.dashed;
  EXPECT_TRUE(dashed);
}

}  // namespace

namespace {

// A block's marker on the Blocks screen is a thumb's target (9 mm at the
// tablet's density; here an 8" 1920 x 1200 tablet at 300 dpi, where 9 mm,
// 106 px, is more than the layout's 56 px x scale), and a tap anywhere on
// it selects its block.
TEST(OverlayBlocks, ABlockMarkerIsANineMillimetreTargetThatSelectsItsBlock) {
  UiOptions options;
  options.project = demo_project();
  options.max_display_triangles = kTriangles;
  options.scale = 1.5f;
  options.dpi = 300;
  HeadlessSession s(options, FieldServices{}, 1920, 1200);
  s.settle();
  s.tap("Blocks");
  s.frame();
  const auto& blocks = s.state().session->blocks();
  ASSERT_FALSE(blocks.empty());
  // ImGui rounds nothing here (the rectangle is ours): the marker is the
  // target's size to float precision.
  const float least = touch_target_px_at(300);
  for (const auto& b : blocks) {
    const auto marker = s.state().targets.find("block " + b.label);
    ASSERT_TRUE(marker) << b.label;
    EXPECT_GE(marker->max.x - marker->min.x, least - 1e-3f) << b.label;
    EXPECT_GE(marker->max.y - marker->min.y, least - 1e-3f) << b.label;
  }
  // Near the marker's rim (0.45 of its width from the centre, on the
  // diagonal: inside the ring): its block is selected.
  const auto marker = *s.state().targets.find("block " + blocks.front().label);
  const float off = 0.45f * (marker.max.x - marker.min.x) / std::sqrt(2.0f);
  s.tap(marker.centre().x + off, marker.centre().y - off);
  ASSERT_TRUE(s.state().blocks.selected_block);
  EXPECT_EQ(*s.state().blocks.selected_block, 0u);
}

}  // namespace
