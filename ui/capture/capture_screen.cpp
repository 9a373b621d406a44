// Capture: the camera's connection and the settings that matter, live view
// where the camera gives one, the stereo guidance, and the left and right
// shots with a clear "captured / stored" state. Camera calls run on the
// worker (a DSLR answers over USB in tens to hundreds of milliseconds); the
// mock camera goes through the same path.
#include <GLES3/gl3.h>

#include <atomic>
#include <filesystem>
#include <memory>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "camera/camera_error.h"
#include "camera/capture_guidance.h"
#include "camera/exif.h"
#include "core/common/number_format.h"
#include "storage/project/calibration_library.h"
#include "storage/project/project_store.h"
#include "ui/app/screens.h"
#include "ui/platform/texture_generation.h"
#include "ui/widgets/format.h"
#include "ui/widgets/keypad.h"
#include "ui/widgets/widgets_controls.h"
#include "ui/widgets/widgets_text.h"

namespace rockface::ui {

namespace {

// The range pole's targets: from a short pole's 0.3 m to a long one's 10 m
// (the store's last length is taken back up to 50 m: tablet_app.cpp).
constexpr double kMinPoleM = 0.3, kMaxPoleM = 10.0;

// The settings a stereo pair depends on, by libgphoto2 widget name.
constexpr const char* kKeySettings[] = {"focallength", "focusmode", "f-number",
                                        "aperture",    "iso",       "shutterspeed"};

struct CameraSnapshot {
  std::string model;
  std::vector<camera::CameraSetting> settings;
};

void connect(AppState& app) {
  CameraConnector* connector = app.services.camera;
  auto snapshot = std::make_shared<CameraSnapshot>();
  auto slot = std::make_shared<std::shared_ptr<camera::Camera>>();
  app.task.start(
      "Connect camera",
      [connector, snapshot, slot](Progress& progress) {
        progress.step("connecting", 0.1);
        std::shared_ptr<camera::Camera> cam = connector->connect();
        snapshot->model = cam->model();
        for (const auto& s : cam->settings())
          for (const char* key : kKeySettings)
            if (s.name == key) snapshot->settings.push_back(s);
        *slot = std::move(cam);
        return "connected to " + snapshot->model;
      },
      [&app, snapshot, slot](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) {
          app.capture.connection = "not connected: " + outcome.message;
          return;
        }
        app.capture.camera = *slot;
        app.capture.connection = snapshot->model;
        app.capture.guidance.clear();
        for (const auto& s : snapshot->settings)
          app.capture.guidance.push_back(s.label + ": " + s.value);
      });
}

// Locks the focus; where the camera cannot do it over USB, returns why
// (empty when locked). Any other failure stops the shot.
std::string lock_focus_or_say_why(camera::Camera& cam) {
  try {
    cam.lock_focus();
    return {};
  } catch (const camera::CameraError& e) {
    if (e.kind() != camera::CameraError::Kind::not_supported) throw;
    return e.what();
  }
}

void shoot(AppState& app, bool left) {
  auto cam = app.capture.camera;
  auto shot = std::make_shared<camera::Capture>();
  app.task.start(
      left ? "Left shot" : "Right shot",
      [cam, shot, left](Progress& progress) {
        const std::string side = left ? "left" : "right";
        // Issue 42: a shot of this station that the camera took and did not
        // send (it stopped answering mid-download) is fetched from its card,
        // not taken again: the station's picture is the one already shot.
        progress.step("fetching a shot left on the camera", 0.1);
        if (auto waiting = cam->fetch_pending_capture()) {
          *shot = std::move(*waiting);
          return side + " shot fetched from the camera's card (" +
                 std::filesystem::path(shot->image.camera_path).filename().string() +
                 ", taken before the camera stopped answering)";
        }
        progress.step("focus and shoot", 0.2);
        // The right shot keeps the left's focus. A body that gives no focus
        // control over USB still shoots: the geologist focuses it by hand
        // (refusing the shot left no way to take it at all), and is told.
        std::string by_hand;
        if (left) by_hand = lock_focus_or_say_why(*cam);
        try {
          *shot = cam->capture();
        } catch (const camera::CameraError& e) {
          const std::vector<std::string> waiting = cam->pending_downloads();
          if (waiting.empty()) throw;
          throw camera::CameraError(
              e.kind(), std::string(e.what()) + ". The picture is on the camera's card (" +
                            std::filesystem::path(waiting.front()).filename().string() +
                            "): once the camera answers, tap Shoot " + side +
                            " again and it is fetched, not taken again");
        }
        std::string said = side + " shot captured";
        if (!by_hand.empty()) said += " with the focus as set by hand (" + by_hand + ")";
        // Issue 42: a low battery is said with the shot, before the next pair.
        if (!shot->battery_warning.empty()) said += ". " + shot->battery_warning;
        return said;
      },
      [&app, shot, left](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done) return;
        // A left shot after a stored pair begins the next pair: the right
        // shot shown belongs to the stored one (asking "not stored yet?"
        // before shooting the new right would be wrong).
        if (left && app.capture.stored) app.capture.right.reset();
        (left ? app.capture.left : app.capture.right) = std::move(*shot);
        app.capture.stored = false;
      });
}

void live_view(AppState& app) {
  auto cam = app.capture.camera;
  auto frame = std::make_shared<cv::Mat>();
  app.task.start(
      "Live view",
      [cam, frame](Progress&) {
        *frame = cam->live_view();
        return std::string("live view frame");
      },
      [&app, frame](const TaskOutcome& outcome) {
        if (outcome.kind != TaskOutcome::Kind::done || frame->empty()) return;
        cv::Mat rgba;
        const double shrink = std::min(1.0, 640.0 / frame->cols);
        cv::resize(*frame, rgba, cv::Size(), shrink, shrink, cv::INTER_AREA);
        cv::cvtColor(rgba, rgba, cv::COLOR_BGR2RGBA);
        if (!app.capture.live_view_texture) glGenTextures(1, &app.capture.live_view_texture);
        glBindTexture(GL_TEXTURE_2D, app.capture.live_view_texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, rgba.cols, rgba.rows, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     rgba.data);
        note_texture_changed();
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        app.capture.live_view = rgba;
      });
}

// Saves the pair with the calibration of the camera that took it, then
// (when a reconstruction runner exists) reconstructs it, on the queue of 3D
// images (issue 45): the camera is free for the next pair at once, and the
// pairs are reconstructed in the order they were stored. The pair is saved
// before any cancel is heard (report, not step), so stopping its 3D image
// keeps the pair.
void store_and_reconstruct(AppState& app) {
  const auto file = app.session->file();
  const auto visit = *app.session->visit();
  storage::Capture capture;
  capture.visit_id = visit;
  capture.label = "tablet pair";
  capture.left.bytes = app.capture.left->image.data;
  capture.right.bytes = app.capture.right->image.data;
  capture.left_exif = camera::exif_fields(app.capture.left->exif);
  capture.right_exif = camera::exif_fields(app.capture.right->exif);
  capture.settings["range_pole_m"] = std::to_string(app.capture.range_pole_m);
  const Preset preset = app.capture.preset;
  capture.settings["preset"] = std::string(preset_name(preset));
  photogrammetry::PhotoCamera photo = camera::photo_camera(app.capture.left->exif);
  // Bodies that keep their serial number in the maker note only: the one
  // the camera told over USB.
  if (photo.serial.empty()) photo.serial = app.capture.left->body_serial;
  storage::record_camera(capture, photo);
  ReconstructionRunner* runner = app.services.reconstruction;
  // Its place in the visit: the pairs stored, and those on the queue before it.
  const WorkQueueStatus queued = app.reconstructions.status();
  const std::size_t pair =
      app.session->captures().size() + queued.waiting + (queued.current.running ? 1 : 0) + 1;
  app.capture.stored = true;  // on its way: a new shot needs no confirmation
  // Whether the pair reached the project: a pair whose saving failed (a full
  // disk) is shown "not stored" again while its shots are still on screen.
  auto saved = std::make_shared<std::atomic<bool>>(false);
  // The shots' files in the camera's spool: once the pair is in the
  // project they are copies, and the spool would only grow (a RAW that came
  // with a shot is not in the project and stays).
  const std::vector<std::string> spooled{app.capture.left->image.saved_path,
                                         app.capture.right->image.saved_path};
  app.reconstructions.add(
      "Pair " + std::to_string(pair),
      [file, capture, photo, preset, runner, saved, spooled](Progress& progress) mutable {
        progress.report("storing the pair", 0.02);
        storage::ProjectStore store = storage::ProjectStore::open(file);
        // The calibration of the camera that took the pair (issue 42: the
        // project's newest was taken, whatever body and lens).
        if (photo.width == 0 || photo.height == 0) {
          const cv::Mat image = cv::imdecode(capture.left.bytes, cv::IMREAD_GRAYSCALE);
          photo.width = image.cols;
          photo.height = image.rows;
        }
        const storage::CalibrationChoice choice = storage::choose_calibration(store, photo);
        if (choice.calibration) capture.calibration_id = choice.calibration->id;
        const storage::RecordId id = store.save_capture(capture);
        *saved = true;
        for (const std::string& path : spooled) {
          std::error_code ignored;  // a spool file already gone is no fault
          if (!path.empty()) std::filesystem::remove(path, ignored);
        }
        if (!choice.calibration)
          return "stored as capture " + std::to_string(id) +
                 "; not reconstructed: " + choice.refusal;
        if (!runner) return "stored as capture " + std::to_string(id);
        const storage::RecordId model = runner->reconstruct(file, id, preset, progress);
        return "stored, 3D image " + std::to_string(model) + " saved (Model)";
      },
      [&app, file, saved, shot = app.capture.left->image.data.data()](const TaskOutcome&) {
        // The shots on screen are still this pair's (the same bytes in memory).
        if (!*saved && app.capture.left && app.capture.left->image.data.data() == shot)
          app.capture.stored = false;
        if (app.session && app.session->file() == file) app.session->refresh();
      });
}

// The queue of 3D images: the one being made, how far, and how many wait;
// the geologist may stop them (each pair stays stored).
void draw_reconstructions(AppState& app) {
  if (!app.reconstructions.busy()) return;
  const WorkQueueStatus q = app.reconstructions.status();
  if (app.targets.button("Stop 3D images", 0, q.current.running && !q.current.cancelling))
    app.reconstructions.cancel();
  ImGui::SameLine();
  std::string text = q.current.running
                         ? q.current.title + ": " + q.current.stage + " (" +
                               format::text(format::Fraction{q.current.fraction}) + ", " +
                               format::text(format::Duration{q.current.seconds}) + ")"
                         : std::string("3D images");
  if (q.waiting > 0)
    text += "; " + format::count(static_cast<std::int64_t>(q.waiting), "pair waits", "pairs wait");
  if (q.current.cancelling) text += ", stopping";
  progress_bar(static_cast<float>(q.current.fraction), text, app.targets.target_px());
}

const char* shot_state(const std::optional<camera::Capture>& shot, bool stored) {
  if (!shot) return "not taken";
  return stored ? "taken and stored" : "taken, not stored yet";
}

// A shot taken but not stored is lost by shooting it again: asked first.
bool shoot_button(AppState& app, const char* label, bool taken, bool enabled) {
  if (taken && !app.capture.stored)
    return app.targets.confirmed_button(label, "The shot taken is not stored yet. Take it again?",
                                        enabled);
  return app.targets.button(label, 0, enabled);
}

// The range pole's length, typed in millimetres as its makers mark it
// (a slider could not say 2.000 m exactly; issue 42), kept for the
// project's next pairs.
void draw_pole_length(AppState& app) {
  CaptureState& c = app.capture;
  field("Range pole", format_fixed(c.range_pole_m, 3, " m") + " between its target centres");
  if (!c.typing_pole) {
    if (app.targets.button("Type pole length")) {
      c.typing_pole = true;
      c.pole_mm.clear();
    }
    return;
  }
  label(c.pole_mm.text().empty() ? std::string("Type the length in millimetres")
                                 : c.pole_mm.text() + " mm");
  if (const auto k = draw_keypad(app.targets)) c.pole_mm.key(*k);
  const double m = c.pole_mm.value() / 1000;
  const bool typed = !c.pole_mm.text().empty();
  const bool fits = m >= kMinPoleM && m <= kMaxPoleM;
  if (typed && !fits)
    paragraph("A range pole of " + format_fixed(m, 3, " m") + "? Its targets are " +
              format_fixed(kMinPoleM, 1, " m") + " to " + format_fixed(kMaxPoleM, 0, " m") +
              " apart: type the length in millimetres (2 m is 2000).");
  if (app.targets.button("Set pole length", 0, typed && fits)) {
    c.range_pole_m = static_cast<float>(m);
    c.typing_pole = false;
  }
  ImGui::SameLine();
  if (app.targets.button_in_row("Cancel pole length")) c.typing_pole = false;
}

void draw_guidance(AppState& app) {
  CaptureState& c = app.capture;
  const float s = app.targets.scale();
  heading("Stereo guidance");
  label("Distance to the face");
  slider(app.targets, "distance", &c.distance_m, 2, 100, "%.0f m",
         std::min(400 * s, ImGui::GetContentRegionAvail().x));
  const camera::BaseLengthHint hint = camera::base_length_hint(c.distance_m);
  bullet("Walk " + format::text(format::Length{hint.min_m}) + " to " +
         format::text(format::Length{hint.max_m}) +
         " between the shots (1/8 to 1/5 of the distance).");
  bullet("Same focal length, focus and aperture for both shots; no flash.");
  bullet("The range pole (both targets) in view of both shots.");
  draw_pole_length(app);
  label("3D image");
  const std::vector<std::string> presets{"fast: a first look", "standard", "precise"};
  const std::size_t at = c.preset == Preset::fast ? 0 : c.preset == Preset::standard ? 1 : 2;
  if (const auto chosen = choice(app.targets, "Preset", presets[at], presets, at))
    c.preset = *chosen == 0 ? Preset::fast : *chosen == 1 ? Preset::standard : Preset::precise;
}

// The camera and the shots: what the geologist taps at the face, first.
void draw_shots(AppState& app) {
  CaptureState& c = app.capture;
  const bool idle = !app.task.running();
  field("Camera", format::without_folders(c.connection));
  if (app.services.camera) note(format::without_folders(app.services.camera->describe()));
  if (app.targets.button(c.camera ? "Reconnect" : "Connect camera", 0, idle && app.services.camera))
    connect(app);
  if (app.targets.button_in_row("Live view", idle && c.camera)) live_view(app);
  ImGui::Separator();
  const bool can_shoot = idle && c.camera != nullptr;
  if (shoot_button(app, "Shoot left", c.left.has_value(), can_shoot)) shoot(app, true);
  ImGui::SameLine();
  label_in_row(std::string("Left: ") + shot_state(c.left, c.stored));
  if (shoot_button(app, "Shoot right", c.right.has_value(), can_shoot && c.left.has_value()))
    shoot(app, false);
  ImGui::SameLine();
  label_in_row(std::string("Right: ") + shot_state(c.right, c.stored));
  // Storing waits for no camera call: the pair goes to the queue of 3D images.
  const bool can_store = c.left && c.right && !c.stored && app.session && app.session->visit() &&
                         !app.session->read_only();
  if (app.targets.button("Store pair and reconstruct", 0, can_store)) store_and_reconstruct(app);
  draw_reconstructions(app);
  if (!app.session) note("Open a project to store the pair (Project).");
  if (c.left && c.right) {
    for (const auto& n : camera::check_pair(c.left->exif, c.right->exif)) {
      if (n.severity == camera::GuidanceNote::Severity::refusal)
        paragraph("Refused: " + n.text, warning_colour());
      else
        bullet(n.text);
    }
  }
  if (c.live_view_texture && !c.live_view.empty()) {
    const float w = std::min(480 * app.targets.scale(), ImGui::GetContentRegionAvail().x);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(c.live_view_texture)),
                 ImVec2(w, w * c.live_view.rows / c.live_view.cols));
  }
}

}  // namespace

void draw_capture_screen(AppState& app) {
  // Shots on the left, guidance and the camera's settings beside them (below
  // them in portrait).
  const SplitLayout layout = split_for_side_panel(ImGui::GetContentRegionAvail().x * 0.45f, 0.5f);
  ImGui::BeginChild("capture shots", layout.main);
  draw_shots(app);
  ImGui::EndChild();
  begin_side_panel("capture guidance", layout);
  draw_guidance(app);
  if (!app.capture.guidance.empty()) {
    ImGui::Separator();
    heading("Camera settings");
    for (const auto& g : app.capture.guidance) bullet(g);
  }
  ImGui::EndChild();
}

}  // namespace rockface::ui
