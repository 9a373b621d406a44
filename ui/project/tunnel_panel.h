#pragma once
// The tunnel on the Project screen: the project's tunnel (alignment,
// design profile, drive, tolerance) or, when it has none, its files chosen
// on the tablet (tunnel_files_picker.h), where the current visit lies in it and
// how it was placed, and on request two views made on the worker: the
// excavation of the visit's round against the design (developed view) and
// the joint sets along the drive.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "storage/tunnel/tunnel_records.h"
#include "ui/app/field_services.h"
#include "ui/project/drive_chart.h"
#include "ui/project/excavation_view.h"
#include "ui/project/tunnel_files_picker.h"
#include "ui/widgets/picture_texture.h"

namespace rockface::ui {

struct AppState;

struct TunnelState {
  // What was read for (project, visit); re-read when either changes.
  std::filesystem::path file;
  std::optional<storage::RecordId> visit;
  bool loaded = false;
  std::optional<storage::TunnelRecord> record;
  std::optional<storage::VisitPlacement> placement;
  std::string view;  // "excavation" | "drive" | empty
  // The typed placement of the range pole's lower target (m).
  double typed_chainage = 0, typed_offset = 0, typed_height = 0;
  // Issue 46: the heading the visit was taken at, as stored ("" none) and
  // as being typed (storage/tunnel/visit_heading.h).
  std::string visit_heading, typed_heading;
  std::vector<std::string> lines;
  PictureTexture picture;
  // Issue 39: the joints along the drive ("drive"), drawn at the screen's
  // size, and what the last frame drew of them.
  std::optional<DriveJoints> drive;
  DriveChartDrawn drive_drawn;
  // The excavation of this round ("excavation"): its figures and developed
  // view (the cells in `picture`), and what the last frame drew.
  std::optional<ExcavationView> excavation;
  ExcavationDrawn excavation_drawn;
  // Issue 42: a project with no tunnel gets one from its files.
  TunnelFilesPicker picker;
};

void draw_tunnel_panel(AppState& app);

}  // namespace rockface::ui
