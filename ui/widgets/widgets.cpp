#include "ui/widgets/widgets.h"

#include <algorithm>

#include <imgui_internal.h>

#include "core/common/number_format.h"

namespace rockface::ui {

ImU32 verdict_colour(analysis::BlockVerdict verdict) {
  switch (verdict) {
    case analysis::BlockVerdict::moves:
      return IM_COL32(230, 20, 20, 255);
    case analysis::BlockVerdict::marginal:
      return IM_COL32(255, 140, 0, 255);
    case analysis::BlockVerdict::holds:
      return IM_COL32(240, 220, 0, 255);
    case analysis::BlockVerdict::keyed:
      return IM_COL32(20, 180, 60, 255);
    case analysis::BlockVerdict::infinite:
      return IM_COL32(150, 150, 150, 255);
  }
  return IM_COL32(0, 0, 0, 255);
}

ImU32 verdict_text_colour(analysis::BlockVerdict verdict) {
  if (ImGui::GetStyleColorVec4(ImGuiCol_WindowBg).x < 0.5f) return verdict_colour(verdict);
  switch (verdict) {
    case analysis::BlockVerdict::moves:
      return IM_COL32(190, 0, 0, 255);
    case analysis::BlockVerdict::marginal:
      return IM_COL32(180, 80, 0, 255);
    case analysis::BlockVerdict::holds:
      return IM_COL32(120, 100, 0, 255);
    case analysis::BlockVerdict::keyed:
      return IM_COL32(0, 120, 40, 255);
    case analysis::BlockVerdict::infinite:
      return IM_COL32(90, 90, 90, 255);
  }
  return IM_COL32(0, 0, 0, 255);
}

namespace {
TouchTargets*& frame_targets() {
  static TouchTargets* targets = nullptr;
  return targets;
}

// A target as drawn in the current panel: the part of it inside the
// panel's view (a row half scrolled away, a marker beyond the model view's
// edge) is where a finger reaches it; none of it, and it is not visible.
TargetRect in_view(ImVec2 min, ImVec2 max, bool enabled, bool button) {
  TargetRect r;
  r.min = min;
  r.max = max;
  r.enabled = enabled;
  r.button = button;
  r.shown_min = min;
  r.shown_max = max;
  const ImGuiContext* g = ImGui::GetCurrentContext();
  if (!g || !g->CurrentWindow) return r;
  // The panels it lies in, out to a popup or the top window.
  for (const ImGuiWindow* w = g->CurrentWindow; w;
       w = (w->Flags & ImGuiWindowFlags_ChildWindow) ? w->ParentWindow : nullptr) {
    ScrollView v;
    v.inner_min = w->InnerRect.Min;
    v.inner_max = w->InnerRect.Max;
    // Clipped by the panels around it already (ImGui's Begin).
    v.clip_min = w->InnerClipRect.Min;
    v.clip_max = w->InnerClipRect.Max;
    v.scrolls = w->ScrollMax.y > 0 || w->ScrollMax.x > 0;
    r.views.push_back(v);
  }
  const ImRect clip = g->CurrentWindow->ClipRect;
  r.shown_min = ImVec2(std::max(min.x, clip.Min.x), std::max(min.y, clip.Min.y));
  r.shown_max = ImVec2(std::min(max.x, clip.Max.x), std::min(max.y, clip.Max.y));
  r.visible = r.shown_max.x > r.shown_min.x && r.shown_max.y > r.shown_min.y;
  return r;
}

}  // namespace

void TouchTargets::begin_frame() {
  rects_.clear();
  frame_targets() = this;
  drag_scroll_.update(drag_slop_px());
}

void TouchTargets::record_dragged(const std::string& label, ImVec2 min, ImVec2 max, unsigned id) {
  TargetRect r = in_view(min, max, true, false);
  r.drags = true;
  rects_[label] = r;
  drag_scroll_.takes_drags(id);
}

void last_item_takes_drags() {
  if (frame_targets()) frame_targets()->drag_scroll().takes_drags(ImGui::GetItemID());
}

void TouchTargets::record(const std::string& label, ImVec2 min, ImVec2 max, bool enabled) {
  rects_[label] = in_view(min, max, enabled, false);
}

void TouchTargets::record_area(const std::string& label, ImVec2 min, ImVec2 max) {
  TargetRect r = in_view(min, max, true, false);
  r.touch = false;
  rects_[label] = r;
}

void record_touch_target(const std::string& label, ImVec2 min, ImVec2 max) {
  if (frame_targets()) frame_targets()->record(label, min, max);
}

float touch_target_px() {
  return frame_targets() ? frame_targets()->target_px() : ImGui::GetFrameHeight();
}

std::vector<std::string> small_touch_targets(const TouchTargets& targets, float slack_px) {
  std::vector<std::string> out;
  const float least = touch_target_px_at(targets.dpi());
  for (const auto& [label, r] : targets.all()) {
    if (!r.touch || !r.visible) continue;
    const float w = r.max.x - r.min.x, h = r.max.y - r.min.y;
    if (std::min(w, h) + slack_px >= least) continue;
    out.push_back("touch target \"" + label + "\" is " + format_fixed(w, 0) + " x " +
                  format_fixed(h, 0, " px") + ", under 9 mm (" + format_fixed(least, 0, " px") +
                  " at " + format_fixed(targets.dpi(), 0, " dpi") + ")");
  }
  return out;
}

float TouchTargets::target_px() const {
  return std::max(kTouchTargetPx * scale_, touch_target_px_at(dpi_));
}

float button_width(const std::string& label, float target_px) {
  const std::string shown = label.substr(0, label.find("##"));
  const float text = ImGui::CalcTextSize(shown.c_str()).x;
  return std::max(target_px, text + 2 * ImGui::GetStyle().FramePadding.x);
}

void same_line_if_fits(float width) {
  const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
  const float edge = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (right <= edge) ImGui::SameLine();
}

SplitLayout split_for_side_panel(float side_px, float below) {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  SplitLayout out;
  out.stacked = avail.y > avail.x;
  if (out.stacked)
    out.main = ImVec2(avail.x, avail.y * (1 - below));
  else
    out.main = ImVec2(std::max(avail.x - side_px, avail.x * 0.4f), avail.y);
  return out;
}

void begin_side_panel(const char* id, const SplitLayout& layout, bool border) {
  if (!layout.stacked) ImGui::SameLine();
  ImGui::BeginChild(id, ImVec2(0, 0), border);
}

bool TouchTargets::button(const std::string& label, float width, bool enabled) {
  const float side = target_px();
  const float room = ImGui::GetContentRegionAvail().x;
  // A fitted button is never narrower than it is high: a square thumb target.
  if (width == 0) width = button_width(label, side);
  if (!enabled) ImGui::BeginDisabled();
  const bool pressed = ImGui::Button(label.c_str(), ImVec2(width, side));
  if (!enabled) ImGui::EndDisabled();
  // The visible label is what a script names (ImGui's "##id" suffix is not).
  const std::string name = label.substr(0, label.find("##"));
  const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
  rects_[name] = in_view(min, max, enabled, true);
  // The label must fit the button and the button the panel.
  const float needed = ImGui::CalcTextSize(name.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
  const float drawn = max.x - min.x;
  record_drawn_text(name, std::max(needed, drawn), std::min(room, drawn));
  return pressed && enabled;
}

bool TouchTargets::button_in_row(const std::string& label, bool enabled) {
  same_line_if_fits(button_width(label, target_px()));
  return button(label, 0, enabled);
}

bool TouchTargets::confirmed_button(const std::string& label, const std::string& question,
                                    bool enabled) {
  const std::string popup = "confirm " + label;
  if (button(label, 0, enabled)) ImGui::OpenPopup(popup.c_str());
  bool confirmed = false;
  if (ImGui::BeginPopup(popup.c_str())) {
    const float most = ImGui::GetMainViewport()->Size.x * 0.6f;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + most);
    ImGui::TextUnformatted(question.c_str());
    record_drawn_text(question, std::min(most, ImGui::CalcTextSize(question.c_str()).x), most + 1);
    ImGui::PopTextWrapPos();
    std::string verb = label.substr(0, label.find("##"));
    if (!verb.empty() && verb[0] >= 'A' && verb[0] <= 'Z')
      verb[0] = static_cast<char>(verb[0] - 'A' + 'a');
    const std::string yes = "Yes, " + verb;
    if (button(yes)) {
      confirmed = true;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (button("Keep")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return confirmed;
}

std::optional<TargetRect> TouchTargets::find(const std::string& label) const {
  const auto it = rects_.find(label);
  if (it == rects_.end()) return std::nullopt;
  return it->second;
}

}  // namespace rockface::ui
