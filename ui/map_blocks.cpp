#include "ui/map_blocks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/app_state.h"
#include "ui/widgets.h"

namespace rockface::ui {

namespace {

constexpr std::array<BlockVerdict, 4> kFiniteVerdicts{BlockVerdict::moves, BlockVerdict::marginal,
                                                      BlockVerdict::holds, BlockVerdict::keyed};

int count_of(const MapVerdicts& v, BlockVerdict verdict) {
  int n = 0;
  for (const auto& b : v.blocks) n += b.verdict == verdict;
  return n;
}

std::string blocks_in_words(const MapVerdicts& v) {
  const int infinite = count_of(v, BlockVerdict::infinite);
  const int finite = static_cast<int>(v.blocks.size()) - infinite;
  std::string s = std::to_string(finite) + (finite == 1 ? " finite block" : " finite blocks");
  std::string parts;
  for (const BlockVerdict verdict : kFiniteVerdicts)
    if (const int n = count_of(v, verdict)) {
      parts += parts.empty() ? "" : ", ";
      parts += std::to_string(n) + " " + verdict_name(verdict);
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
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.0f ms", v.milliseconds);
  return blocks_in_words(v) + ", updated in " + ms;
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
    if (b.verdict == BlockVerdict::infinite) continue;
    if (const BlockOnFace* laid = laid_map_block(app, b))
      add_block_to_overlay(app.model_view.overlay(), "TB" + std::to_string(number), *laid,
                           verdict_colour(b.verdict), true, 3.0f * app.targets.scale());
  }
}

void draw_map_blocks_on_model(AppState& app) {
  const auto& v = app.mapping.blocks.verdicts;
  if (!v) return;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float s = app.targets.scale();
  int number = 0;
  for (const auto& b : v->blocks) {
    ++number;
    if (b.verdict == BlockVerdict::infinite) continue;
    const BlockOnFace* laid = laid_map_block(app, b);
    if (!laid || !laid->centre) continue;  // not on the 3D image
    const auto centre = app.model_view.to_screen(*laid->centre);
    if (!centre) continue;
    const ImU32 colour = verdict_colour(b.verdict);
    draw->AddCircleFilled(*centre, 7 * s, colour, 16);
    const std::string label = "TB" + std::to_string(number);
    draw->AddText(ImVec2(centre->x + 10 * s, centre->y - 9 * s), IM_COL32(255, 255, 255, 255),
                  label.c_str());
  }
}

void draw_map_blocks_panel(AppState& app) {
  if (!app.services.trace_map) return;
  const MapBlocksState& m = app.mapping.blocks;
  ImGui::Separator();
  ImGui::TextUnformatted("Blocks on the map");
  if (!m.problem.empty()) {
    ImGui::TextWrapped("No blocks: %s", m.problem.c_str());
    return;
  }
  if (!m.verdicts) {
    ImGui::TextWrapped("Updating after the last trace ...");
    return;
  }
  const MapVerdicts& v = *m.verdicts;
  ImGui::TextWrapped("%s, from %d traces.", blocks_in_words(v).c_str(), v.traces);
  ImGui::TextWrapped("Updated in %.0f ms (%d of %d regions computed again).", v.milliseconds,
                     v.recomputed, v.recomputed + v.reused);
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                                ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
  const float rows = std::min<float>(6.5f, 1.5f + static_cast<float>(v.blocks.size()));
  if (ImGui::BeginTable("map blocks", 4, flags,
                        ImVec2(0, rows * ImGui::GetTextLineHeightWithSpacing()))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const char* h : {"block", "verdict", "mode", "FoS"}) ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    int number = 0;
    for (const auto& b : v.blocks) {
      ++number;
      if (b.verdict == BlockVerdict::infinite) continue;
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::Text("TB%d", number);
      ImGui::TableNextColumn();
      ImGui::PushStyleColor(ImGuiCol_Text, verdict_colour(b.verdict));
      ImGui::Text("%s (%.1f°)", verdict_name(b.verdict), b.margin_deg);
      ImGui::PopStyleColor();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(b.mode.c_str());
      ImGui::TableNextColumn();
      if (b.factor_of_safety && std::isfinite(*b.factor_of_safety))
        ImGui::Text("%.2f", *b.factor_of_safety);
      else
        ImGui::TextUnformatted("-");
    }
    ImGui::EndTable();
  }
  for (const auto& n : v.notes) ImGui::TextWrapped("%s", n.c_str());
}

}  // namespace rockface::ui
