#pragma once
// The two looks of the tablet: daylight (black on white, saturated accents,
// large type: sunlight washes out greys and thin strokes) and tunnel (light
// on near-black, dimmer, normal type: under a tunnel's lamps a white screen
// dazzles and hides the face behind it). The geologist picks one on the
// Project screen; it is remembered per tablet (ui/app/ui_settings.h).
#include <optional>
#include <string_view>

namespace rockface::ui {

enum class Theme { daylight, tunnel };

const char* theme_name(Theme theme);  // "daylight", "tunnel"
std::optional<Theme> theme_from_name(std::string_view name);

// Body text height in pixels at scale 1.
float theme_font_px(Theme theme);

// Sets ImGui's style and rebuilds the font atlas for `scale` (1 = a 10"
// 1280x800 tablet). Outside a frame only (between Render and NewFrame):
// the caller re-creates the GL font texture after it.
// Every frame (button, slider, box) is at least `min_target_px` high: a
// thumb target at the tablet's DPI.
void apply_theme(Theme theme, float scale, float min_target_px);

}  // namespace rockface::ui
