#include "ui/mapping/map_blocks.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <imgui.h>

#include "core/common/number_format.h"
#include "ui/app/app_state.h"
#include "ui/view3d/overlay_text.h"
#include "ui/widgets/format.h"
#include "ui/widgets/widgets.h"
#include "ui/widgets/widgets_table.h"

namespace rockface::ui {

namespace {

constexpr std::array<analysis::BlockVerdict, 4> kFiniteVerdicts{
    analysis::BlockVerdict::moves, analysis::BlockVerdict::marginal, analysis::BlockVerdict::holds,
    analysis::BlockVerdict::keyed};

int count_of(const MapVerdicts& v, analysis::BlockVerdict verdict) {
  int n = 0;
  for (const auto& b : v.blocks) n += b.verdict == verdict;
  return n;
}

std::string blocks_in_words(const MapVerdicts& v) {
  const int infinite = count_of(v, analysis::BlockVerdict::infinite);
  const int finite = static_cast<int>(v.blocks.size()) - infinite;
  std::string s = std::to_string(finite) + (finite == 1 ? " finite block" : " finite blocks");
  std::string parts;
  for (const analysis::BlockVerdict verdict : kFiniteVerdicts)
    if (const int n = count_of(v, verdict)) {
      parts += parts.empty() ? "" : ", ";
      parts += std::to_string(n) + " " + analysis::verdict_name(verdict);
    }
  if (!parts.empty()) s += " (" + parts + ")";
  if (infinite) s += "; " + std::to_string(infinite) + " not finite";
  return s;
}

}  // namespace

std::shared_ptr<const MapVerdicts> update_map_blocks(const FieldServices& services,
                                                     const std::filesystem::path& project,
                                                     storage::RecordId visit, Progress& progress) {
  if (!services.trace_map) return nullptr;
  return std::make_shared<const MapVerdicts>(services.trace_map->update(project, visit, progress));
}

std::string map_blocks_summary(const MapVerdicts& v) {
  return blocks_in_words(v) + ", updated in " + format_fixed(v.milliseconds, 0, " ms");
}

void refresh_map_blocks(AppState& app) {
  MapBlocksState& m = app.mapping.blocks;
  if (!app.services.trace_map || !app.session || !app.session->visit()) return;
  const storage::RecordId visit = *app.session->visit();
  if (m.visit != visit) {
    m = MapBlocksState{};
    m.visit = visit;
  }
  if (!m.stale || app.task.running()) return;
  m.stale = false;  // a failure is kept in `problem` until the next edit
  const FieldServices services = app.services;
  const auto file = app.session->file();
  auto result = std::make_shared<std::shared_ptr<const MapVerdicts>>();
  app.task.start(
      "Blocks on the map",
      [services, file, visit, result](Progress& progress) {
        *result = update_map_blocks(services, file, visit, progress);
        return *result ? map_blocks_summary(**result) : std::string("no trace map service");
      },
      [&app, visit, result](const TaskOutcome& outcome) {
        MapBlocksState& state = app.mapping.blocks;
        if (state.visit != visit) return;
        if (outcome.kind == TaskOutcome::Kind::done) {
          state.verdicts = *result;
          state.problem.clear();
        } else if (outcome.kind == TaskOutcome::Kind::failed) {
          state.verdicts.reset();
          state.problem = outcome.message;
        } else {
          state.stale = true;  // cancelled: try again when the worker is free
        }
      });
}

namespace {

// A map block's loop laid on the 3D image (datum-relative, as the surface).
const BlockOnFace* laid_map_block(AppState& app, const MapBlock& b) {
  const SurfaceDrape* drape = app.model_view.drape();
  if (!drape || !app.session || b.outline.size() < 3) return nullptr;
  std::vector<Eigen::Vector3d> loop;
  for (const auto& p : b.outline) loop.push_back(p - app.session->info().datum);
  return &app.model_view.block_cache().get(loop, *drape);
}

}  // namespace

void add_map_blocks_to_overlay(AppState& app) {
  const auto& v = app.mapping.blocks.verdicts;
  if (!v) return;
  int number = 0;
  for (const auto& b : v->blocks) {
    ++number;
    // A loop that is not finite is no block: counted in the panel, not drawn.
    if (b.verdict == analysis::BlockVerdict::infinite) continue;
    if (const BlockOnFace* laid = laid_map_block(app, b))
      add_block_to_overlay(app.model_view.overlay(), "TB" + std::to_string(number), *laid,
                           verdict_colour(b.verdict), true, 3.0f * app.targets.scale());
  }
}

namespace {

struct MapMarker {
  int number = 0;  // "TB<number>": the block's place in the verdicts
  const MapBlock* block = nullptr;
  ImVec2 at;  // the marker's centre on the screen
};

// The markers of the finite blocks laid on the 3D image and in its view.
std::vector<MapMarker> map_markers(AppState& app) {
  std::vector<MapMarker> out;
  const auto& v = app.mapping.blocks.verdicts;
  if (!v) return out;
  int number = 0;
  for (const auto& b : v->blocks) {
    ++number;
    if (b.verdict == analysis::BlockVerdict::infinite) continue;
    const BlockOnFace* laid = laid_map_block(app, b);
    if (!laid || !laid->centre) continue;  // not on the 3D image
    if (const auto centre = app.model_view.to_screen(*laid->centre))
      out.push_back({number, &b, *centre});
  }
  return out;
}

const MapBlock* selected_block(const MapBlocksState& m) {
  if (!m.selected || !m.verdicts || m.selected_of != m.verdicts.get()) return nullptr;
  const int k = *m.selected - 1;
  if (k < 0 || k >= static_cast<int>(m.verdicts->blocks.size())) return nullptr;
  return &m.verdicts->blocks[static_cast<std::size_t>(k)];
}

}  // namespace

bool tap_map_block(AppState& app, ImVec2 tap) {
  MapBlocksState& m = app.mapping.blocks;
  if (!m.verdicts || app.mapping.outlining || !app.mapping.marker.taps().empty()) return false;
  // The nearest marker whose disc (a touch target) holds the tap.
  const float half = 0.5f * app.targets.target_px();
  float nearest = half * half;
  std::optional<int> hit;
  for (const MapMarker& k : map_markers(app)) {
    const float dx = tap.x - k.at.x, dy = tap.y - k.at.y;
    if (dx * dx + dy * dy <= nearest) {
      nearest = dx * dx + dy * dy;
      hit = k.number;
    }
  }
  if (!hit) return false;
  const bool again = selected_block(m) && m.selected == hit;
  m.selected = again ? std::nullopt : hit;
  m.selected_of = m.verdicts.get();
  return true;
}

std::string selected_map_block_in_words(const MapBlocksState& m) {
  const MapBlock* b = selected_block(m);
  if (!b) return {};
  std::string s = "TB" + std::to_string(*m.selected) + " " + analysis::verdict_name(b->verdict);
  std::string parts;
  if (!b->mode.empty() && b->mode != "none") parts = b->mode;
  if (b->factor_of_safety && std::isfinite(*b->factor_of_safety))
    parts += (parts.empty() ? "" : ", ") + std::string("factor of safety ") +
             format::text(format::FactorOfSafety{*b->factor_of_safety});
  parts += (parts.empty() ? "" : ", ") + std::string("margin ") +
           format::text(format::Angle{b->margin_deg});
  return s + ": " + parts;
}

void draw_map_blocks_on_model(AppState& app) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  const float half = 0.5f * app.targets.target_px();
  const MapBlocksState& m = app.mapping.blocks;
  const MapBlock* chosen = selected_block(m);
  const TextArea area = app.model_view.text_area();
  for (const MapMarker& k : map_markers(app)) {
    const ImU32 colour = verdict_colour(k.block->verdict);
    // A disc as wide as a gloved thumb around the dot: where a tap takes it.
    draw->AddCircleFilled(k.at, half, (colour & 0x00FFFFFFu) | (70u << 24), 40);
    draw->AddCircle(k.at, half - 1.5f * s, colour, 40, 2 * s);
    draw->AddCircleFilled(k.at, 7 * s, colour, 16);
    const bool is_chosen = chosen == k.block;
    if (is_chosen) draw->AddCircle(k.at, half + 2 * s, IM_COL32(255, 255, 255, 255), 40, 3 * s);
    const std::string label = "TB" + std::to_string(k.number);
    app.targets.record("map block " + label, ImVec2(k.at.x - half, k.at.y - half),
                       ImVec2(k.at.x + half, k.at.y + half));
    // The selected block says its verdict beside its marker.
    const std::string text =
        is_chosen ? label + " " + std::string(analysis::verdict_name(k.block->verdict)) : label;
    if (const auto at = label_beside(k.at, half, ImGui::CalcTextSize(text.c_str()), area))
      draw_text(draw, *at, IM_COL32(255, 255, 255, 255), text, area, TextHalo::dark);
  }
}

void draw_map_blocks_panel(AppState& app) {
  if (!app.services.trace_map) return;
  const MapBlocksState& m = app.mapping.blocks;
  ImGui::Separator();
  heading("Blocks on the map");
  if (!m.problem.empty()) {
    paragraph("No blocks: " + m.problem);
    return;
  }
  if (!m.verdicts) {
    paragraph("Updating after the last trace …");
    return;
  }
  const MapVerdicts& v = *m.verdicts;
  paragraph(blocks_in_words(v) + ", from " + format::count(v.traces, "trace", "traces") + ".");
  if (const std::string chosen = selected_map_block_in_words(m); !chosen.empty())
    paragraph(chosen + ".", verdict_text_colour(selected_block(m)->verdict));
  else
    note("Tap a block's marker on the image for its verdict.");
  note("Updated in " + format::text(format::Duration{v.milliseconds / 1000}) + " (" +
       format::count(v.recomputed) + " of " +
       format::count(v.recomputed + v.reused, "region", "regions") + " computed again).");
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingStretchProp;
  // A row is a touch target high when a verdict is shortened to a tap that
  // shows it whole (ui/widgets/widgets_text.h): the table shows its header and up
  // to four whole rows of that height, and drags to scroll the rest.
  const float pad = 2 * ImGui::GetStyle().CellPadding.y;
  const float header = ImGui::GetTextLineHeightWithSpacing() + pad;
  const float row = std::max(ImGui::GetTextLineHeightWithSpacing(), touch_target_px()) + pad;
  const int finite =
      static_cast<int>(v.blocks.size()) - count_of(v, analysis::BlockVerdict::infinite);
  const float rows = std::min<float>(4.5f, static_cast<float>(std::max(finite, 1)));
  if (ImGui::BeginTable("map blocks", 4, flags, ImVec2(0, header + rows * row + pad))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    // Weights, not content: a shortened cell must not shrink its column.
    ImGui::TableSetupColumn("Block", ImGuiTableColumnFlags_WidthStretch, 1.2f);
    // "Verdict (margin)" does not fit the side panel's column: the note
    // below the table says what the angle in brackets is.
    ImGui::TableSetupColumn("Verdict", ImGuiTableColumnFlags_WidthStretch, 2.2f);
    ImGui::TableSetupColumn("Mode", ImGuiTableColumnFlags_WidthStretch, 1.4f);
    ImGui::TableSetupColumn("FoS", ImGuiTableColumnFlags_WidthStretch, 0.9f);
    table_headers_row();
    int number = 0;
    for (const auto& b : v.blocks) {
      ++number;
      if (b.verdict == analysis::BlockVerdict::infinite) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      label("TB" + std::to_string(number));
      ImGui::TableNextColumn();
      label(std::string(analysis::verdict_name(b.verdict)) + " (" +
                format::text(format::Angle{b.margin_deg}) + ")",
            verdict_text_colour(b.verdict));
      ImGui::TableNextColumn();
      label(b.mode);
      ImGui::TableNextColumn();
      label(b.factor_of_safety && std::isfinite(*b.factor_of_safety)
                ? format::text(format::FactorOfSafety{*b.factor_of_safety})
                : format::unknown());
    }
    ImGui::EndTable();
    note(
        "The angle beside each verdict is its margin: how far the block is from the other "
        "verdict.");
  }
  for (const auto& n : v.notes) note(n);
}

}  // namespace rockface::ui
