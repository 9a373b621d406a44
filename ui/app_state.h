#pragma once
// What the screens of the tablet UI share: the open project, the worker,
// the model view, the camera and the touch targets. The screens are free
// functions over this state (screens.h); TabletApp owns it and runs frames.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "ui/background_task.h"
#include "ui/compass_entry.h"
#include "ui/face_outline.h"
#include "ui/field_services.h"
#include "ui/map_blocks.h"
#include "ui/model_view.h"
#include "ui/motion_playback.h"
#include "ui/office_panel.h"
#include "ui/overlay_photo_targets.h"
#include "ui/project_session.h"
#include "ui/proposals_view.h"
#include "ui/rockmass_view.h"
#include "ui/status_lines.h"
#include "ui/touch_input.h"
#include "ui/trace_marker.h"
#include "ui/tunnel_panel.h"
#include "ui/ui_settings.h"
#include "ui/wedges_view.h"
#include "ui/widgets.h"

namespace rockface::ui {

enum class Screen { project, capture, model, mapping, blocks };
const char* screen_name(Screen screen);  // "Project", "Capture", ...

struct UiOptions {
  std::filesystem::path project;                // opened at start; empty: the Project screen
  std::filesystem::path projects_folder = ".";  // where "New project" creates files
  float scale = 1;                              // 1 = a 1280x800 tablet
  // Triangles the model view draws at most (the stored model is decimated
  // for display; picking and measuring use the stored model).
  std::size_t max_display_triangles = 400000;
  // Issue 27: the tablet's pixel density (0: kScaleOneDpi x scale, the
  // density the scale stands for; a window takes its screen's) and the
  // file the tablet's settings are remembered in (empty: not remembered).
  float dpi = 0;
  std::filesystem::path settings_file;
};

// The camera of the Capture screen and the shots of the pair being taken.
struct CaptureState {
  std::shared_ptr<camera::Camera> camera;  // used on the worker only while a task runs
  std::string connection = "not connected";
  std::optional<camera::Capture> left, right;
  bool stored = false;  // the pair is saved in the project
  std::vector<std::string> guidance;
  float distance_m = 10;      // to the face, for the base length hint
  float range_pole_m = 2.0f;  // distance between the pole's target centres
  cv::Mat live_view;
  unsigned live_view_texture = 0;
};

struct MappingState {
  TraceMarker marker;        // the trace being marked
  std::string joint_label;   // joint (set) the next trace is assigned to; empty: none
  MapBlocksState blocks;     // the blocks the saved traces cut out, updated after each edit
  ProposalsState proposals;  // trace proposals to accept, correct or reject (issue 25)
  // Issue 27: "Outline the face": taps mark the mapped face's corners
  // instead of a trace while `outlining`.
  FaceOutline outline;
  bool outlining = false;
  // Issue 27: a compass reading for the trace being marked or a saved one.
  CompassEntry compass;
};

struct AppState {
  UiOptions options;
  FieldServices services;
  Screen screen = Screen::project;
  std::unique_ptr<ProjectSession> session;
  BackgroundTask task;
  TouchTargets targets;
  ModelView model_view;
  CaptureState capture;
  MappingState mapping;
  TunnelState tunnel;                         // the Project screen's tunnel panel
  WedgesState wedges;                         // the Blocks screen's Wedges view
  OfficeState office;                         // the Project screen's sync to the office
  RockMassState rockmass;                     // the Blocks screen's Rock mass view
  std::optional<std::size_t> selected_block;  // index into session->blocks()
  MotionPlayback motion;                      // the selected block's motion after failure
  std::string new_project_name = "site";
  TouchGesture gesture;  // this frame's two-finger gesture
  // The Model screen's left photograph with the detected pole targets
  // (issue 27), shown in place of the 3D image when chosen.
  PhotoTargetsView photo_targets;
  bool show_photograph = false;

  // Issue 27: each screen's status line; the look, remembered per tablet.
  StatusLines statuses;                           // ui/status_lines.h, by Screen
  Screen task_screen = Screen::project;           // the screen that started the running task
  std::size_t tasks_noted = 0;                    // BackgroundTask::started() when last noted
  UiSettings settings;                            // theme (ui/ui_settings.h)
  std::optional<Theme> theme_wanted;              // applied between two frames
  std::optional<storage::RecordId> status_visit;  // the visit the messages are about
  // On the current screen's status line: a message, or an error that stays
  // until tapped.
  void say(std::string text);
  void fail(std::string text);

  // Opens a project and loads its model on the worker; errors go to status.
  void open_project(const std::filesystem::path& file);
};

}  // namespace rockface::ui
