#pragma once
// The Blocks screen's Wedges view: the wedges that the visit's sets form
// around the tunnel's design section (roof, walls, floor, face), found on
// the worker by the WedgeRunner, shown as a table in words and units with
// the section picture.
#include <filesystem>
#include <optional>

#include "storage/project/project_records.h"
#include "ui/app/field_services.h"
#include "ui/widgets/picture_texture.h"

namespace rockface::ui {

struct AppState;

struct WedgesState {
  bool open = false;  // the Blocks screen shows the Wedges view instead of the blocks
  // What the table was made for; a new project or visit clears it.
  std::filesystem::path file;
  std::optional<storage::RecordId> visit;
  std::optional<WedgeTable> table;
  std::string message;  // why there is no table (no tunnel, fewer than three sets)
  PictureTexture picture;
};

void draw_wedges_view(AppState& app);

}  // namespace rockface::ui
