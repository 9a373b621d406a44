// The walk's checks themselves (tests/ui/app/text_walk_test.cpp runs them on
// every screen): they must catch text drawn past the record (ImGui's own
// table headers, a slider's value), a touch target under 9 mm, and a
// library's field path shown on the screen; and must pass what the tablet's
// wrappers draw. A bare ImGui context (no GL): the font atlas is built on
// the CPU and draw data read back as ImGui::Render leaves it.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>
#include <imgui.h>

#include "core/measure/mesh_picker.h"
#include "tests/support/test_paths.h"
#include "ui/app/text_check.h"
#include "ui/app/text_coverage.h"
#include "ui/mapping/trace_marker.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/widgets.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_table.h"
#include "ui/widgets/widgets_text.h"

namespace {

using namespace rockface::ui;

// One ImGui frame at 1280 x 800 in the daylight theme at scale 1 (150 dpi).
class Frame {
 public:
  Frame() {
    ImGui::CreateContext();
    targets.set_dpi(kScaleOneDpi);
    apply_theme(Theme::daylight, 1.0f, targets.target_px());
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the working folder
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = ImVec2(1280, 800);
    io.DeltaTime = 1.0f / 60;
    ImGui::NewFrame();
    targets.begin_frame();
    clear_drawn_text();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("walk check", nullptr, ImGuiWindowFlags_NoDecoration);
  }
  ~Frame() { ImGui::DestroyContext(); }

  // Ends the frame; what was drawn and not recorded.
  std::string unrecorded() {
    ImGui::End();
    ImGui::Render();
    std::string all;
    for (const UnrecordedText& u : unrecorded_text_in_last_frame(drawn_text())) all += u.characters;
    return all;
  }

  TouchTargets targets;
};

std::string without_spaces(std::string s) {
  s.erase(std::remove(s.begin(), s.end(), ' '), s.end());
  return s;
}

TEST(TextCoverage, RecordedTextPasses) {
  Frame f;
  label("Dip / dip direction 63° / 112°");
  paragraph("A paragraph long enough to wrap at the panel's edge is recorded whole, every line.");
  f.targets.button("Save trace");
  ImGui::Separator();
  EXPECT_EQ(f.unrecorded(), "");
}

TEST(TextCoverage, TextDrawnPastTheRecordIsCaught) {
  Frame f;
  label("seen");
  ImGui::TextUnformatted("unseen");
  EXPECT_EQ(f.unrecorded(), "unseen");
}

TEST(TextCoverage, ImGuisOwnTableHeadersAreCaughtAndTheWrapperRecordsThem) {
  {
    Frame f;
    ASSERT_TRUE(ImGui::BeginTable("t", 2));
    ImGui::TableSetupColumn("Block");
    ImGui::TableSetupColumn("FoS");
    ImGui::TableHeadersRow();
    ImGui::EndTable();
    EXPECT_EQ(f.unrecorded(), "BlockFoS");
  }
  {
    Frame f;
    ASSERT_TRUE(ImGui::BeginTable("t", 2));
    ImGui::TableSetupColumn("Block");
    ImGui::TableSetupColumn("FoS");
    table_headers_row();
    ImGui::EndTable();
    EXPECT_EQ(f.unrecorded(), "");
    // Recorded with its column's width.
    const auto& drawn = drawn_text();
    ASSERT_EQ(drawn.size(), 2u);
    EXPECT_EQ(drawn[1].text, "FoS");
    EXPECT_GT(drawn[1].available, drawn[1].width);
  }
}

TEST(TextCoverage, ASlidersValueIsCaughtUnlessDrawnByTheWrapper) {
  {
    Frame f;
    float d = 12;
    ImGui::SliderFloat("##d", &d, 2, 100, "%.0f m");
    EXPECT_EQ(without_spaces(f.unrecorded()), "12m");
  }
  {
    Frame f;
    float d = 12;
    slider(f.targets, "distance", &d, 2, 100, "%.0f m");
    EXPECT_EQ(f.unrecorded(), "");
    EXPECT_EQ(drawn_text().back().text, "12 m");
  }
}

TEST(TextCoverage, AHaloedLabelOnAPictureCountsOnce) {
  Frame f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 at(300, 300);
  // draw_text's dark halo: eight copies one pixel around the label.
  draw_text(draw, at, IM_COL32(255, 255, 255, 255), "5 m", {ImVec2(0, 0), ImVec2(1280, 800)},
            TextHalo::dark);
  // A second, separate "5 m" drawn unrecorded is still caught.
  draw->AddText(ImVec2(600, 300), IM_COL32(0, 0, 0, 255), "5 m");
  EXPECT_EQ(without_spaces(f.unrecorded()), "5m");
}

TEST(TouchTargetCheck, ATargetUnder9mmIsCaught) {
  Frame f;
  // 18 px: the old block marker, 3 mm at 150 dpi.
  f.targets.record("block B1", ImVec2(100, 100), ImVec2(118, 118));
  f.targets.button("Save trace");
  const auto small = small_touch_targets(f.targets);
  ASSERT_EQ(small.size(), 1u);
  EXPECT_NE(small[0].find("block B1"), std::string::npos) << small[0];
  EXPECT_NE(small[0].find("18 x 18 px"), std::string::npos) << small[0];
  // A shown area is not a touch target.
  f.targets.record_area("read-only notice", ImVec2(0, 0), ImVec2(300, 20));
  EXPECT_EQ(small_touch_targets(f.targets).size(), 1u);
  // At 225 dpi, 9 mm is 80 px: a 56 px button made for 150 dpi fails.
  TouchTargets denser;
  denser.set_dpi(225);
  denser.record("Save trace", ImVec2(0, 0), ImVec2(120, 56));
  EXPECT_EQ(small_touch_targets(denser).size(), 1u);
  f.unrecorded();
}

TEST(TouchTargetCheck, TheWrappersControlsAreThumbTargets) {
  Frame f;
  float t = 0.5f;
  slider(f.targets, "motion time", &t, 0, 1, "%.2f s");
  bool entered = true;
  checkbox(f.targets, "UCS entered", "", &entered);
  choice(f.targets, "roughness", "rough", {"not entered", "smooth", "rough"}, 2);
  double chainage = 12.5;
  number_field(f.targets, "Chainage (m)", &chainage, "%.2f", 220, 0.1);
  EXPECT_TRUE(collapsing_section(f.targets, "Entered on site (form)", true));
  const float least = touch_target_px_at(kScaleOneDpi);
  for (const char* name : {"motion time", "motion time grab", "UCS entered", "roughness",
                           "Chainage (m) -", "Chainage (m) +", "Entered on site (form)"}) {
    const auto r = f.targets.find(name);
    ASSERT_TRUE(r) << name;
    EXPECT_GE(std::min(r->max.x - r->min.x, r->max.y - r->min.y) + 0.5f, least) << name;
  }
  std::string all;
  for (const auto& s : small_touch_targets(f.targets)) all += s + "\n";
  EXPECT_TRUE(all.empty()) << all;
  EXPECT_EQ(f.unrecorded(), "");
}

TEST(TouchTargetCheck, TheGrabOfASliderIsWhereImGuiDrawsIt) {
  // ImGui 1.86: inset 2 px, GrabMinSize wide, at the value's fraction.
  const GrabRect g = slider_grab(ImVec2(0, 0), ImVec2(404, 60), 0.5f, 56);
  EXPECT_FLOAT_EQ(g.min.x, 2 + 0.5f * (400 - 56));
  EXPECT_FLOAT_EQ(g.max.x - g.min.x, 56);
  EXPECT_FLOAT_EQ(g.max.y - g.min.y, 56);
}

TEST(TextCheck, ALibrarysFieldPathIsCaught) {
  EXPECT_TRUE(
      looks_like_field_path("trace.pixels[784]: no surface of the 3D image under this pick"));
  EXPECT_TRUE(looks_like_field_path("Error: picks.traces[2] is bad"));
  EXPECT_FALSE(looks_like_field_path("This tap is off the 3D surface: tap on the rock."));
  EXPECT_FALSE(looks_like_field_path("pixels[3]"));          // no owner: not a field path
  EXPECT_FALSE(looks_like_field_path("Fig. 2 [3] joints"));  // a reference, not a path
  EXPECT_NE(text_problem({"traces.pixels[7]: no surface", 10, 100, "p"}).find("field path"),
            std::string::npos);
}

TEST(TraceMarkerWords, EveryRefusalIsSaidInWordsWithWhatToDo) {
  using Mode = TraceMarker::Mode;
  for (const auto& [mode, reason] : std::vector<std::pair<Mode, std::string>>{
           {Mode::two_taps, "no surface of the 3D image under this pick"},
           {Mode::points, "no surface of the 3D image under this pick"},
           {Mode::two_taps, "all picks are the same pixel: a trace needs two points"},
           {Mode::two_taps, "the two ends are the same pixel"},
           {Mode::two_taps, "pixel is outside the image or not a number"},
           {Mode::two_taps, "trace ends: no path between the two ends"},
           {Mode::points, "coordinate is not a number"},
           {Mode::points, "a trace needs at least 2 points, got 1"},
           {Mode::points, "something new"}}) {
    const std::string words = trace_problem_in_words(mode, reason);
    EXPECT_FALSE(looks_like_field_path(words)) << words;
    EXPECT_FALSE(looks_like_key(words)) << words;
    // What to do: every message asks for a tap or an undo.
    EXPECT_TRUE(words.find("tap") != std::string::npos || words.find("Tap") != std::string::npos)
        << words;
  }
}

TEST(TraceMarkerWords, ATapOffTheSurfaceSaysSoAndKeepsNoTap) {
  rockface::photogrammetry::SurfaceMesh mesh;
  mesh.vertices = {{0, 0, 5}, {1, 0, 5}, {1, 1, 5}, {0, 1, 5}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const rockface::measure::MeshPicker picker(mesh);
  TraceContext context;
  context.picker = &picker;
  TraceMarker marker;
  EXPECT_TRUE(marker.tap({Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d::UnitZ()}, context));
  EXPECT_FALSE(marker.tap({Eigen::Vector3d(3, 3, 0), Eigen::Vector3d::UnitZ()}, context));
  EXPECT_EQ(marker.taps().size(), 1u);
  EXPECT_EQ(marker.problem(), "This tap is off the 3D surface: tap on the rock.");
  EXPECT_FALSE(marker.detail().empty());
}

}  // namespace

namespace {

// Code the walk does not reach (a tunnel visit's panel, the office panel)
// is held to the same rule by reading it: no screen calls ImGui's text and
// control widgets directly, only the recording wrappers of ui/widgets*.
TEST(TextCoverage, NoScreenDrawsTextOrControlsPastTheWrappers) {
  namespace fs = std::filesystem;
  const std::regex direct(
      R"(ImGui::(Text|TextUnformatted|TextColored|TextWrapped|TextDisabled|LabelText|BulletText|)"
      R"(TableHeadersRow|TableHeader|SliderFloat|SliderInt|SliderAngle|DragFloat|DragInt|Checkbox|)"
      R"(BeginCombo|Combo|InputText|InputDouble|InputFloat|InputInt|CollapsingHeader|Selectable|)"
      R"(Button|SmallButton|ProgressBar|RadioButton|MenuItem|SetTooltip|TreeNode|BeginTabItem|)"
      R"(BeginPopupModal)\(|->AddText\()");
  // The dark halo of a label on the 3D image: copies of a label recorded
  // once through draw_text (the glyph check counts a halo once).
  const std::regex halo(R"(if \(dx \|\| dy\) draw->AddText\()");
  const fs::path ui = fs::path(ROCKFACE_SOURCE_DIR) / "ui";
  int files = 0;
  std::string found;
  for (const auto& entry : fs::recursive_directory_iterator(ui)) {
    if (entry.path().extension() != ".cpp" && entry.path().extension() != ".h") continue;
    // The recorders themselves: ui/widgets* and ui/overlay_text (words drawn
    // onto a picture, recorded with the box they must lie in).
    if (entry.path().filename().string().rfind("widgets", 0) == 0 ||
        entry.path().filename() == "overlay_text.cpp")
      continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      if (std::regex_search(line, direct) && !std::regex_search(line, halo))
        found += entry.path().lexically_relative(ui).string() + ":" + std::to_string(n) + ": " +
                 line + "\n";
  }
  EXPECT_GT(files, 50) << "ui/ not found at " << ui;
  EXPECT_TRUE(found.empty()) << "ImGui drawn past the recording wrappers:\n" << found;
}

}  // namespace
