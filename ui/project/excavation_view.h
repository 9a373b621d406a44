#pragma once
// Issue 39: the excavation of this round on the Project screen: the
// developed view the field report draws (the round's surface against the
// design line unrolled, the face at the top), its cells shown as a texture
// and labelled with the tablet's own font (chainage, the places along the
// outline), with its legend, and the figures in the UI's units (m³).
#include "ui/app/field_services.h"
#include "ui/widgets/picture_texture.h"

namespace rockface::ui {

struct ExcavationDrawn {
  bool view = false;                 // the developed view drawn
  int legend_entries = 0;            // the legend's entries drawn (colour scale included)
  std::vector<std::string> figures;  // the lines of figures written
};

// Draws at the cursor, `width` px wide; `cells` holds view.cells uploaded.
ExcavationDrawn draw_excavation_view(const ExcavationView& view, const PictureTexture& cells,
                                     float width);

// The figures in words and units ("Overbreak 0.412 m³ ± 0.020 m³, ...").
std::vector<std::string> excavation_figures(const ExcavationView& view);

}  // namespace rockface::ui
