#include "camera/gphoto2_camera.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <thread>
#include <utility>

#include <gphoto2/gphoto2.h>
#include <opencv2/imgcodecs.hpp>

#include "camera/command_thread.h"
#include "camera/gphoto2_errors.h"
#include "camera/gphoto2_handles.h"
#include "camera/gphoto2_settings.h"
#include "camera/gphoto2_shot_wait.h"
#include "camera/gphoto2_widgets.h"
#include "core/common/atomic_file.h"

namespace rockface::camera {

namespace fs = std::filesystem;
using Kind = CameraError::Kind;
using namespace gphoto2;  // gphoto2_handles.h, gphoto2_widgets.h, gphoto2_settings.h

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_disk_port(const std::string& port) {
  return port.rfind("disk:", 0) == 0;
}

std::string join_path(const std::string& folder, const std::string& name) {
  return folder == "/" ? "/" + name : folder + "/" + name;
}

std::pair<std::string, std::string> split_path(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {"/", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

// The files of one shot as a Capture: the JPEG is the image, everything
// else (a RAW) a companion.
Capture as_capture(std::vector<CapturedFile> got, const std::string& body_serial) {
  auto is_jpeg = [](const CapturedFile& f) {
    const std::string ext = lower(fs::path(f.camera_path).extension().string());
    return ext == ".jpg" || ext == ".jpeg";
  };
  auto jpeg = std::find_if(got.begin(), got.end(), is_jpeg);
  if (jpeg != got.end()) std::iter_swap(got.begin(), jpeg);
  Capture c;
  c.image = std::move(got.front());
  c.companions.assign(std::make_move_iterator(got.begin() + 1), std::make_move_iterator(got.end()));
  c.exif = read_exif(c.image.data);
  c.body_serial = body_serial;
  return c;
}

}  // namespace

struct Gphoto2Camera::State {
  Options options;
  GPContext* context = nullptr;
  ::Camera* camera = nullptr;  // null while disconnected
  std::string model, port;
  std::string serial;                // read once on connecting; empty when the body gives none
  std::vector<std::string> pending;  // captured on the camera, not yet downloaded
  std::string driver_error;          // the camera driver's last error text (its context error)
  bool reconnecting = false;         // the camera was lost: look it up again by model
  std::optional<int> last_battery;   // percent, as read at the last shot

  ~State() {
    disconnect();
    if (context) gp_context_unref(context);
  }

  void disconnect() {
    if (!camera) return;
    gp_camera_exit(camera, context);
    gp_camera_unref(camera);
    camera = nullptr;
  }

  // Turns a libgphoto2 result into an exception; the camera is dropped when
  // it is gone so the next command reconnects.
  void check(int rc, const std::string& action) {
    std::string driver_says = std::exchange(driver_error, {});
    if (rc >= GP_OK) return;
    CameraError e = gphoto2_error(rc, action, driver_says);
    // The directory camlib reports a file that cannot be read as an I/O
    // error; while the folder is still there, the camera is not gone.
    if (e.kind() == Kind::disconnected && is_disk_port(port) && fs::is_directory(port.substr(5))) {
      throw CameraError(Kind::file_unreadable,
                        action +
                            ": the file cannot be read (damaged, or removed while reading) "
                            "(libgphoto2: " +
                            std::string(gp_result_as_string(rc)) + ", code " + std::to_string(rc) +
                            ")");
    }
    if (e.kind() == Kind::disconnected) {
      disconnect();
      reconnecting = true;
      // A body whose battery runs flat switches itself off and drops off
      // the bus, which looks like an unplug: the last level read says why.
      if (last_battery && *last_battery <= Gphoto2Camera::kLowBatteryPercent)
        throw CameraError(Kind::disconnected,
                          std::string(e.what()) + ". Its battery read " +
                              std::to_string(*last_battery) +
                              " % at the last shot: it has probably switched itself off; "
                              "change the battery");
    }
    throw e;
  }

  // The driver's error text says what its result code cannot (a card that
  // ran full comes as "out of memory"): kept for the next check().
  static void keep_driver_error(GPContext*, const char* text, void* data) {
    if (text) static_cast<State*>(data)->driver_error = text;
  }

  void connect() {
    if (!context) {
      context = gp_context_new();
      gp_context_set_error_func(context, keep_driver_error, this);
    }
    std::string want_model = options.model;
    std::string want_port = options.port;
    const bool search =
        want_model.empty() || want_port.empty() || (reconnecting && !is_disk_port(want_port));
    if (search) {
      // Find the camera on USB (again after a replug: the port number changes).
      const auto found = detect_with(context);
      auto it = std::find_if(found.begin(), found.end(), [&](const DetectedCamera& c) {
        return want_model.empty() || c.model == want_model;
      });
      if (it == found.end())
        throw CameraError(
            Kind::no_camera,
            want_model.empty()
                ? "No camera found: plug the camera in, switch it on and set its "
                  "USB mode to PTP (not mass storage)"
                : "The camera " + want_model + " is not connected: plug it in and switch it on");
      want_model = it->model;
      want_port = it->port;
    }
    if (is_disk_port(want_port) && !fs::is_directory(want_port.substr(5)))
      throw CameraError(Kind::disconnected, "The card folder " + want_port.substr(5) + " (port " +
                                                want_port + ") does not exist or is not mounted");

    CameraAbilitiesList* abilities_list = nullptr;
    gp_abilities_list_new(&abilities_list);
    std::unique_ptr<CameraAbilitiesList, int (*)(CameraAbilitiesList*)> al(abilities_list,
                                                                           gp_abilities_list_free);
    check(gp_abilities_list_load(abilities_list, context), "Loading the camera drivers");
    const int m = gp_abilities_list_lookup_model(abilities_list, want_model.c_str());
    if (m < GP_OK)
      throw CameraError(Kind::no_camera,
                        "The camera model \"" + want_model + "\" is not known to libgphoto2");
    CameraAbilities abilities;
    check(gp_abilities_list_get_abilities(abilities_list, m, &abilities),
          "Reading the camera driver");

    GPPortInfoList* port_list = nullptr;
    gp_port_info_list_new(&port_list);
    std::unique_ptr<GPPortInfoList, int (*)(GPPortInfoList*)> pl(port_list, gp_port_info_list_free);
    check(gp_port_info_list_load(port_list), "Listing the camera ports");
    const int p = gp_port_info_list_lookup_path(port_list, want_port.c_str());
    if (p < GP_OK)
      throw CameraError(Kind::no_camera,
                        "There is no camera port \"" + want_port +
                            "\" (ports look like usb:001,007 or disk:/media/card)");
    GPPortInfo info;
    check(gp_port_info_list_get_info(port_list, p, &info), "Reading the camera port");

    ::Camera* cam = nullptr;
    gp_camera_new(&cam);
    int rc = gp_camera_set_abilities(cam, abilities);
    if (rc >= GP_OK) rc = gp_camera_set_port_info(cam, info);
    if (rc >= GP_OK) rc = gp_camera_init(cam, context);
    if (rc < GP_OK) {
      gp_camera_unref(cam);
      CameraError e = gphoto2_error(rc, "Connecting to the " + want_model + " on " + want_port,
                                    std::exchange(driver_error, {}));
      throw e;
    }
    camera = cam;
    reconnecting = false;
    model = want_model;
    port = want_port;
    serial = read_serial_number(camera, context);
  }

  // The open camera's settings (gphoto2_settings.h), errors checked as
  // every other call's.
  CameraSettings settings() {
    return CameraSettings(camera, context, model,
                          [this](int rc, const std::string& action) { check(rc, action); });
  }

  // The first of the tablet setting's names this camera has; throws naming
  // the setting when it has none.
  std::string tablet_setting_widget(TabletSetting which, const char* doing) {
    return settings().require(widget_names(which), doing, tablet_setting_name(which));
  }

  static std::vector<DetectedCamera> detect_with(GPContext* context) {
    ListPtr list = new_list();
    const int n = gp_camera_autodetect(list.get(), context);
    std::vector<DetectedCamera> found;
    for (int i = 0; i < n; ++i) {
      const char* name = nullptr;
      const char* value = nullptr;
      gp_list_get_name(list.get(), i, &name);
      gp_list_get_value(list.get(), i, &value);
      found.push_back({name ? name : "", value ? value : ""});
    }
    return found;
  }

  void ensure_connected() {
    if (!camera) connect();
  }

  // Writes the bytes under the spool folder through the one atomic writer
  // (temporary name, fsync, rename), so a half-written file never looks like
  // a picture.
  std::string spool(const std::string& name, const char* data, unsigned long size) {
    fs::create_directories(options.spool_dir);
    fs::path target = fs::path(options.spool_dir) / name;
    for (int k = 1; fs::exists(target); ++k)
      target =
          fs::path(options.spool_dir) / (fs::path(name).stem().string() + "-" + std::to_string(k) +
                                         fs::path(name).extension().string());
    try {
      write_bytes_atomically(target, data, size);
    } catch (const Error& e) {
      throw CameraError(Kind::other, "Saving " + name + " to " + options.spool_dir +
                                         " failed: is the tablet's storage full? (" + e.what() +
                                         ")");
    }
    return target.string();
  }

  CapturedFile download(const std::string& camera_path) {
    ensure_connected();
    const auto [folder, name] = split_path(camera_path);
    FilePtr file = new_file();
    with_busy_retries(
        [&] {
          return gp_camera_file_get(camera, folder.c_str(), name.c_str(), GP_FILE_TYPE_NORMAL,
                                    file.get(), context);
        },
        "Downloading " + camera_path);
    const char* data = nullptr;
    unsigned long size = 0;
    check(gp_file_get_data_and_size(file.get(), &data, &size), "Reading " + camera_path);
    CapturedFile out;
    out.camera_path = camera_path;
    out.data.assign(reinterpret_cast<const uint8_t*>(data),
                    reinterpret_cast<const uint8_t*>(data) + size);
    if (!options.spool_dir.empty()) out.saved_path = spool(name, data, size);
    pending.erase(std::remove(pending.begin(), pending.end(), camera_path), pending.end());
    return out;
  }

  void list_recursive(const std::string& folder, std::vector<std::string>& out) {
    ListPtr files = new_list();
    check(gp_camera_folder_list_files(camera, folder.c_str(), files.get(), context),
          "Listing the pictures in " + folder);
    for (int i = 0; i < gp_list_count(files.get()); ++i) {
      const char* name = nullptr;
      gp_list_get_name(files.get(), i, &name);
      if (name) out.push_back(join_path(folder, name));
    }
    ListPtr folders = new_list();
    check(gp_camera_folder_list_folders(camera, folder.c_str(), folders.get(), context),
          "Listing the folders in " + folder);
    for (int i = 0; i < gp_list_count(folders.get()); ++i) {
      const char* name = nullptr;
      gp_list_get_name(folders.get(), i, &name);
      if (name) list_recursive(join_path(folder, name), out);
    }
  }

  static long long ms_until(std::chrono::steady_clock::time_point end) {
    return std::max<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                   end - std::chrono::steady_clock::now())
                                   .count(),
                               0);
  }

  std::vector<CameraEvent> wait_events(int timeout_ms) {
    std::vector<CameraEvent> out;
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
    for (;;) {
      const long long left = ms_until(end);
      out.push_back(next_event(static_cast<int>(left)));
      if (out.back().kind == CameraEvent::Kind::timeout || left <= 0) break;
    }
    return out;
  }

  // The camera's next event within timeout_ms (a timeout event if none).
  CameraEvent next_event(int timeout_ms) {
    CameraEventType type = GP_EVENT_UNKNOWN;
    void* data = nullptr;
    check(gp_camera_wait_for_event(camera, timeout_ms, &type, &data, context),
          "Waiting for the camera");
    CameraEvent e;
    switch (type) {
      case GP_EVENT_FILE_ADDED: {
        const auto* path = static_cast<CameraFilePath*>(data);
        e.kind = CameraEvent::Kind::file_added;
        e.detail = join_path(path->folder, path->name);
        break;
      }
      case GP_EVENT_CAPTURE_COMPLETE:
        e.kind = CameraEvent::Kind::capture_complete;
        break;
      case GP_EVENT_TIMEOUT:
        e.kind = CameraEvent::Kind::timeout;
        break;
      case GP_EVENT_UNKNOWN:
        if (data) e.detail = static_cast<const char*>(data);
        break;
      default:
        break;
    }
    free(data);
    return e;
  }

  // Runs `step` (a libgphoto2 call), asking a body that answers busy again
  // a bounded number of times before the busy result is said.
  template <class Step>
  void with_busy_retries(Step step, const std::string& action) {
    int rc = step();
    for (int i = 0; rc == GP_ERROR_CAMERA_BUSY && i < options.busy_retries; ++i) {
      std::exchange(driver_error, {});
      std::this_thread::sleep_for(std::chrono::milliseconds(options.busy_wait_ms));
      rc = step();
    }
    if (rc == GP_ERROR_CAMERA_BUSY && options.busy_retries > 0)
      driver_error = "still busy after " + std::to_string(options.busy_retries + 1) + " tries " +
                     std::to_string(options.busy_wait_ms) + " ms apart" +
                     (driver_error.empty() ? "" : "; " + driver_error);
    check(rc, action);
  }

  // The body's battery level in percent; none when it gives no number.
  std::optional<int> read_battery() {
    const std::optional<std::string> value = read_battery_value(camera, context);
    // The failed reads' driver text belongs to no later call.
    if (!value) std::exchange(driver_error, {});
    return value ? battery_percent_of(*value) : std::nullopt;
  }

  // Triggers one shot and waits for its files (gphoto2_shot_wait.h); each
  // file goes on the pending list as soon as the camera names it.
  std::vector<std::string> shoot() {
    with_busy_retries([&] { return gp_camera_trigger_capture(camera, context); },
                      "Taking a picture");
    return wait_for_shot_files(
        [&](int timeout_ms) {
          CameraEvent e = next_event(timeout_ms);
          if (e.kind == CameraEvent::Kind::file_added) pending.push_back(e.detail);
          return e;
        },
        {options.capture_timeout_ms, options.file_after_complete_ms, options.event_drain_ms});
  }
};

std::vector<DetectedCamera> Gphoto2Camera::detect() {
  GPContext* context = gp_context_new();
  auto found = State::detect_with(context);
  gp_context_unref(context);
  return found;
}

Gphoto2Camera::Gphoto2Camera(Options options)
    : state_(std::make_unique<State>()), thread_(std::make_unique<CommandThread>()) {
  state_->options = std::move(options);
  thread_->call([this] { state_->connect(); });
}

Gphoto2Camera::~Gphoto2Camera() {
  // The state is torn down on the thread that owns the camera.
  thread_->call([this] { state_.reset(); });
}

std::string Gphoto2Camera::model() {
  return thread_->call([this] { return state_->model; });
}

std::string Gphoto2Camera::port() {
  return thread_->call([this] { return state_->port; });
}

std::string Gphoto2Camera::serial_number() {
  return thread_->call([this] {
    state_->ensure_connected();
    return state_->serial;
  });
}

std::vector<CameraSetting> Gphoto2Camera::settings() {
  return thread_->call([this] {
    state_->ensure_connected();
    WidgetPtr root = state_->settings().root();
    std::vector<CameraSetting> out;
    collect_leaf_settings(root.get(), out);
    return out;
  });
}

CameraSetting Gphoto2Camera::setting(const std::string& name) {
  return thread_->call([&] {
    state_->ensure_connected();
    return state_->settings().read(name);
  });
}

void Gphoto2Camera::set_setting(const std::string& name, const std::string& value) {
  thread_->call([&] {
    state_->ensure_connected();
    state_->settings().write(name, value);
  });
}

void Gphoto2Camera::apply(const ExposureSettings& exposure) {
  thread_->call([&] {
    state_->ensure_connected();
    const CameraSettings settings = state_->settings();
    auto set = [&](const std::optional<std::string>& value, const std::vector<std::string>& names,
                   const char* what) {
      if (value) settings.write(settings.require(names, "set", what), *value);
    };
    set(exposure.program, kProgramNames, "exposure program");
    set(exposure.aperture, kApertureNames, "aperture");
    set(exposure.shutter, kShutterNames, "shutter speed");
    set(exposure.iso, kIsoNames, "ISO");
    set(exposure.image_format, kFormatNames, "image format");
    set(exposure.capture_target, kTargetNames, "capture target");
  });
}

CameraSetting Gphoto2Camera::tablet_setting(TabletSetting which) {
  return thread_->call([&] {
    state_->ensure_connected();
    return state_->settings().read(state_->tablet_setting_widget(which, "read"));
  });
}

void Gphoto2Camera::set_tablet_setting(TabletSetting which, const std::string& value) {
  thread_->call([&] {
    state_->ensure_connected();
    state_->settings().write(state_->tablet_setting_widget(which, "set"), value);
  });
}

FlashState Gphoto2Camera::flash() {
  return thread_->call([this] {
    state_->ensure_connected();
    const CameraSettings settings = state_->settings();
    const std::string name = settings.find(kFlashNames);
    if (name.empty()) return FlashState::unknown;
    return flash_state_of(settings.read(name).value);
  });
}

void Gphoto2Camera::lock_focus() {
  thread_->call([this] {
    state_->ensure_connected();
    // Focus once on what the camera sees, then hold it: manual focus mode.
    const CameraSettings settings = state_->settings();
    const std::string drive = settings.find(kAutofocusNames);
    if (!drive.empty()) settings.write(drive, "1");
    const std::string mode = settings.find(kFocusModeNames);
    if (mode.empty())
      throw CameraError(Kind::not_supported, "The " + state_->model +
                                                 " does not let rockface lock focus over USB: "
                                                 "focus once on the face, then switch the lens "
                                                 "to MF");
    if (const auto manual = manual_focus_choice(settings.read(mode).choices)) {
      settings.write(mode, *manual);
      return;
    }
    throw CameraError(Kind::not_supported, "The " + state_->model +
                                               " offers no manual focus mode over USB: focus "
                                               "once on the face, then switch the lens to MF");
  });
}

Capture Gphoto2Camera::capture() {
  return thread_->call([this] {
    State& s = *state_;
    s.ensure_connected();
    // Kept from the last reading when the body gives none now (gone off).
    if (const std::optional<int> level = s.read_battery()) s.last_battery = level;
    const std::vector<std::string> files = s.shoot();
    std::vector<CapturedFile> got;
    for (const auto& f : files) got.push_back(s.download(f));
    Capture c = as_capture(std::move(got), s.serial);
    if (s.last_battery && *s.last_battery <= kLowBatteryPercent)
      c.battery_warning = "The camera's battery is at " + std::to_string(*s.last_battery) +
                          " %: change it before the next pair (a body whose battery runs flat "
                          "switches itself off, mid-pair)";
    return c;
  });
}

std::optional<int> Gphoto2Camera::battery_percent() {
  return thread_->call([this] {
    state_->ensure_connected();
    return state_->read_battery();
  });
}

std::optional<Capture> Gphoto2Camera::fetch_pending_capture() {
  return thread_->call([this]() -> std::optional<Capture> {
    State& s = *state_;
    if (s.pending.empty()) return std::nullopt;
    // A file fetched leaves the list (safe in the spool); one that fails
    // stays on it for the next try, and the failure is said.
    std::vector<CapturedFile> got;
    for (const auto& f : std::vector<std::string>(s.pending)) got.push_back(s.download(f));
    return as_capture(std::move(got), s.serial);
  });
}

cv::Mat Gphoto2Camera::live_view() {
  return thread_->call([this] {
    State& s = *state_;
    s.ensure_connected();
    FilePtr file = new_file();
    s.check(gp_camera_capture_preview(s.camera, file.get(), s.context), "Reading live view");
    const char* data = nullptr;
    unsigned long size = 0;
    s.check(gp_file_get_data_and_size(file.get(), &data, &size), "Reading live view");
    const cv::Mat bytes(1, static_cast<int>(size), CV_8U, const_cast<char*>(data));
    cv::Mat frame = cv::imdecode(bytes, cv::IMREAD_COLOR);
    if (frame.empty())
      throw CameraError(Kind::other, "The camera sent a live-view frame that is not an image");
    return frame;
  });
}

std::vector<CameraEvent> Gphoto2Camera::events(int timeout_ms) {
  return thread_->call([&] {
    state_->ensure_connected();
    return state_->wait_events(timeout_ms);
  });
}

void Gphoto2Camera::close() {
  thread_->call([this] { state_->disconnect(); });
}

std::vector<std::string> Gphoto2Camera::list_files(const std::string& folder) {
  return thread_->call([&] {
    state_->ensure_connected();
    std::vector<std::string> out;
    state_->list_recursive(folder, out);
    return out;
  });
}

CapturedFile Gphoto2Camera::download(const std::string& camera_path) {
  return thread_->call([&] { return state_->download(camera_path); });
}

std::vector<std::string> Gphoto2Camera::pending_downloads() {
  return thread_->call([this] { return state_->pending; });
}

std::vector<CapturedFile> Gphoto2Camera::retry_pending() {
  return thread_->call([this] {
    std::vector<CapturedFile> got;
    const auto pending = state_->pending;
    for (const auto& path : pending) {
      try {
        got.push_back(state_->download(path));
      } catch (const CameraError&) {
        // Stays pending; the caller sees it in pending_downloads().
      }
    }
    return got;
  });
}

}  // namespace rockface::camera
