#pragma once
// Every string the tablet draws goes through these (never ImGui::Text and
// friends directly): each fits the panel it is drawn in — a paragraph
// wraps at the panel's edge, a one-line label too long for its place is
// shortened with "…" and the whole text is one tap away (a popup) — and
// each is recorded with its width and the width it had, so that the screen
// walk of tests/ui sees every string drawn in a frame (ui/app/text_check.h).
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "ui/app/text_check.h"

namespace rockface::ui {

// One line; shortened with "…" when wider than the space left on the line,
// and then tapping it shows the whole text.
void label(std::string_view text);
// A label on a row of buttons: centred on the buttons' height (shortened, its
// tap target is that height).
void label_in_row(std::string_view text);
void label_in_row(std::string_view text, ImU32 colour);
// Same, in a colour (verdicts, warnings).
void label(std::string_view text, ImU32 colour);
// Wrapped at the panel's edge.
void paragraph(std::string_view text);
void paragraph(std::string_view text, ImU32 colour);
// A secondary line (greyed), wrapped.
void note(std::string_view text);
// A bullet point, wrapped.
void bullet(std::string_view text);
// "Title: value" on one line, the value shortened first when it does not fit.
void field(std::string_view title, std::string_view value);
// A section heading (the theme's heading colour).
void heading(std::string_view text);

// A progress bar filling the rest of the line, `height` high, with `text`
// in it shortened to fit the bar.
void progress_bar(float fraction, std::string_view text, float height);

// Records a string drawn by other means (a button's label, a progress
// bar's text) with its width and the width it had.
void record_drawn_text(std::string_view text, float width, float available);

// The strings drawn since the frame began (TabletApp clears it per frame).
void clear_drawn_text();
const std::vector<DrawnText>& drawn_text();

// Text shortened from the end to fit `width` px, with "…"; the whole text
// when it fits.
std::string shortened(std::string_view text, float width);

// The colour of warnings and errors in the current theme.
ImU32 warning_colour();

}  // namespace rockface::ui
