#pragma once
// What the screens of the tablet UI share: the open project, the worker,
// the model view, the touch targets, the status lines and the look; each
// screen's own state lives in its room (ui/capture/capture_state.h, ...).
// The screens are free functions over this state (ui/app/screens.h);
// TabletApp owns it and runs frames.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "ui/app/background_task.h"
#include "ui/app/field_services.h"
#include "ui/app/project_session.h"
#include "ui/app/status_lines.h"
#include "ui/app/ui_settings.h"
#include "ui/app/work_queue.h"
#include "ui/blocks/blocks_state.h"
#include "ui/capture/capture_state.h"
#include "ui/mapping/mapping_state.h"
#include "ui/model/model_state.h"
#include "ui/project/project_state.h"
#include "ui/view3d/model_view.h"
#include "ui/widgets/touch_input.h"
#include "ui/widgets/widgets.h"

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

struct AppState {
  UiOptions options;
  FieldServices services;
  Screen screen = Screen::project;
  std::unique_ptr<ProjectSession> session;
  BackgroundTask task;
  // The pairs' 3D images, one after the other on a worker of their own, so
  // the camera (on `task`) shoots the next pair meanwhile (issue 45).
  WorkQueue reconstructions;
  TouchTargets targets;
  ModelView model_view;  // the 3D image, shared by the Model, Mapping and Blocks screens
  // A 3D image whose loading failed (a damaged page, a model the program
  // cannot read): said once, not tried again at every frame.
  std::optional<storage::RecordId> model_load_failed;
  // Each screen's own state, in its room (ui/<screen>/<screen>_state.h).
  ProjectScreenState project;
  CaptureState capture;
  ModelScreenState model;
  MappingState mapping;
  BlocksState blocks;
  TouchGesture gesture;  // this frame's two-finger gesture

  // Issue 27: each screen's status line; the look, remembered per tablet.
  StatusLines statuses;                           // ui/app/status_lines.h, by Screen
  Screen task_screen = Screen::project;           // the screen that started the running task
  std::size_t tasks_noted = 0;                    // BackgroundTask::started() when last noted
  UiSettings settings;                            // theme (ui/app/ui_settings.h)
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
