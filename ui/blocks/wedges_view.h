#pragma once
// The Blocks screen's Wedges view: the wedges that the visit's sets form
// around the tunnel's design section (roof, walls, floor, face), found on
// the worker by the WedgeRunner, shown as a table in words and units with
// the section picture.
#include <filesystem>
#include <optional>

#include "storage/project/project_records.h"
#include "ui/app/field_services.h"
#include "ui/widgets/keypad.h"
#include "ui/widgets/picture_texture.h"

namespace rockface::ui {

struct AppState;

// Issue 39: friction and support for the wedges, typed on the keypad in the
// units a geologist reads them (degrees, m, kN, mm, MPa). The project has
// no place for these with the visit (only the round's support decision):
// the form keeps them for the session, and each Find wedges uses them.
enum class WedgeField {
  friction,
  bolt_length,
  bolt_spacing,
  bolt_capacity,
  shotcrete_thickness,
  shotcrete_shear
};

struct WedgeFormState {
  bool open = false;  // the form shown above the table
  WedgeField typing = WedgeField::friction;
  TypedNumber friction{4}, bolt_length{4}, bolt_spacing{4}, bolt_capacity{5},
      shotcrete_thickness{4}, shotcrete_shear{4};
  TypedNumber& field(WedgeField f);
  // What the runner is asked with; problem() must be empty first.
  WedgeForm form() const;
  // Why the form cannot be used ("Bolts: type the spacing as well"); empty when it can.
  std::string problem() const;
  void clear();
};

struct WedgesState {
  bool open = false;  // the Blocks screen shows the Wedges view instead of the blocks
  // What the table was made for; a new project or visit clears it.
  std::filesystem::path file;
  std::optional<storage::RecordId> visit;
  std::optional<WedgeTable> table;
  std::string message;  // why there is no table (no tunnel, fewer than three sets)
  PictureTexture picture;
  WedgeFormState form;  // kept across projects and visits: the geologist's typing
};

void draw_wedges_view(AppState& app);

}  // namespace rockface::ui
