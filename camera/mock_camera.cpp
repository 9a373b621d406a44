#include "camera/mock_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "camera/camera_error.h"
#include "camera/synthetic_renderer.h"
#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::camera {

namespace fs = std::filesystem;
using Kind = CameraError::Kind;

namespace {

std::string lowercase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_jpeg(const fs::path& p) {
  const std::string ext = lowercase(p.extension().string());
  return ext == ".jpg" || ext == ".jpeg";
}

std::vector<uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CameraError(Kind::file_unreadable, "Replay: " + path + " cannot be opened");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The settings of a Nikon-like body, with libgphoto2's widget names.
std::vector<CameraSetting> default_settings() {
  return {
      {"expprogram", "Exposure Program", "A", {"M", "P", "A", "S"}, false},
      {"f-number", "F-Number", "8", {"2.8", "4", "5.6", "8", "11", "16"}, false},
      {"shutterspeed",
       "Shutter Speed",
       "1/125",
       {"1/30", "1/60", "1/125", "1/250", "1/500", "1/1000"},
       false},
      {"iso", "ISO Speed", "200", {"100", "200", "400", "800", "1600"}, false},
      {"imagequality", "Image Quality", "JPEG Fine", {"JPEG Fine", "NEF+Fine"}, false},
      {"capturetarget", "Capture Target", "Memory card", {"Internal RAM", "Memory card"}, false},
      {"flashmode", "Flash Mode", "Off", {"Off", "On"}, false},
      {"focusmode", "Focus Mode", "AF-S", {"AF-S", "Manual"}, false},
  };
}

// "1/125" or "2" seconds.
std::optional<double> shutter_seconds(const std::string& text) {
  double a = 0, b = 0;
  if (std::sscanf(text.c_str(), "%lf/%lf", &a, &b) == 2 && b > 0) return a / b;
  if (std::sscanf(text.c_str(), "%lf", &a) == 1 && a > 0) return a;
  return std::nullopt;
}

}  // namespace

std::unique_ptr<MockCamera> MockCamera::replay(const std::string& folder,
                                               const std::string& spool_dir) {
  if (!fs::is_directory(folder)) throw InputError(folder, "no such capture folder");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::unique_ptr<MockCamera> cam(new MockCamera());
  cam->mode_ = Mode::replay;
  cam->folder_ = folder;
  cam->spool_dir_ = spool_dir;
  for (const auto& f : files) {
    if (!is_jpeg(f)) continue;
    ReplayShot shot{f.string(), {}};
    for (const auto& g : files)
      if (g != f && g.stem() == f.stem() && !is_jpeg(g)) shot.companions.push_back(g.string());
    cam->shots_.push_back(std::move(shot));
  }
  if (cam->shots_.empty()) throw InputError(folder, "holds no JPEG captures to replay");
  cam->settings_ = default_settings();
  // Show the settings the first shot was taken with.
  const ExifInfo first = read_exif_file(cam->shots_.front().image);
  if (first.f_number) cam->find("f-number").value = format_significant(*first.f_number, 6);
  if (first.iso) cam->find("iso").value = std::to_string(*first.iso);
  if (first.flash_fired) cam->find("flashmode").value = *first.flash_fired ? "On" : "Off";
  return cam;
}

std::unique_ptr<MockCamera> MockCamera::synthetic(SyntheticScene scene,
                                                  const std::string& spool_dir,
                                                  SyntheticCameraBody body) {
  // Poses are checked now, so a bad scene fails when the camera opens.
  station_pose(scene.stations[0], "imaging.stations[0]");
  station_pose(scene.stations[1], "imaging.stations[1]");
  std::unique_ptr<MockCamera> cam(new MockCamera());
  cam->mode_ = Mode::synthetic;
  cam->scene_ = std::move(scene);
  cam->body_ = std::move(body);
  cam->spool_dir_ = spool_dir;
  cam->settings_ = default_settings();
  return cam;
}

std::string MockCamera::model() {
  return mode_ == Mode::replay ? "rockface replay of " + folder_ : body_.make + " " + body_.model;
}

CameraSetting& MockCamera::find(const std::string& name) {
  for (auto& s : settings_)
    if (s.name == name) return s;
  throw CameraError(Kind::not_supported, "The " + model() + " has no setting \"" + name + "\"");
}

std::vector<CameraSetting> MockCamera::settings() {
  return settings_;
}

CameraSetting MockCamera::setting(const std::string& name) {
  return find(name);
}

void MockCamera::set_setting(const std::string& name, const std::string& value) {
  if (closed_) throw CameraError(Kind::disconnected, "The mock camera is closed");
  CameraSetting& s = find(name);
  if (std::find(s.choices.begin(), s.choices.end(), value) == s.choices.end()) {
    std::string offered;
    for (const auto& c : s.choices) offered += (offered.empty() ? "" : ", ") + c;
    throw CameraError(Kind::bad_value, "The " + model() + " offers " + s.label + " " + offered +
                                           "; \"" + value + "\" is not one of them");
  }
  s.value = value;
  if (name == "focusmode" && value != "Manual") {
    focus_locked_ = false;
    locked_focus_m_.reset();
  }
}

void MockCamera::apply(const ExposureSettings& e) {
  if (e.program) set_setting("expprogram", *e.program);
  if (e.aperture) set_setting("f-number", *e.aperture);
  if (e.shutter) set_setting("shutterspeed", *e.shutter);
  if (e.iso) set_setting("iso", *e.iso);
  if (e.image_format) set_setting("imagequality", *e.image_format);
  if (e.capture_target) set_setting("capturetarget", *e.capture_target);
}

FlashState MockCamera::flash() {
  return find("flashmode").value == "Off" ? FlashState::off : FlashState::on;
}

void MockCamera::lock_focus() {
  if (closed_) throw CameraError(Kind::disconnected, "The mock camera is closed");
  find("focusmode").value = "Manual";
  focus_locked_ = true;
  // The synthetic lens focuses on what the next station looks at, then holds.
  if (mode_ == Mode::synthetic) {
    const auto& st = scene_->stations[std::min<size_t>(next_, 1)];
    locked_focus_m_ = (st.look_at - st.position).norm();
  }
}

size_t MockCamera::shots_left() const {
  if (mode_ == Mode::replay) return shots_.size() - next_;
  return next_ < 2 ? 2 - next_ : 0;
}

CapturedFile MockCamera::store(const std::string& name, std::vector<uint8_t> data) {
  CapturedFile f;
  f.camera_path = "/DCIM/100MOCK/" + name;
  if (!spool_dir_.empty()) {
    fs::create_directories(spool_dir_);
    const fs::path target = fs::path(spool_dir_) / name;
    try {
      write_bytes_atomically(target, data.data(), data.size());
    } catch (const Error& e) {
      throw CameraError(Kind::other,
                        "Saving " + name + " to " + spool_dir_ + " failed (" + e.what() + ")");
    }
    f.saved_path = target.string();
  }
  f.data = std::move(data);
  events_.push_back({CameraEvent::Kind::file_added, f.camera_path});
  return f;
}

Capture MockCamera::capture() {
  if (closed_) throw CameraError(Kind::disconnected, "The mock camera is closed");
  if (shots_left() == 0)
    throw CameraError(Kind::other,
                      mode_ == Mode::replay
                          ? "The replay is finished: all " + std::to_string(shots_.size()) +
                                " captures of " + folder_ + " were served"
                          : std::string("The synthetic scene has two stations and both were "
                                        "taken"));
  Capture c = mode_ == Mode::replay ? capture_replay() : capture_synthetic();
  events_.push_back({CameraEvent::Kind::capture_complete, {}});
  ++next_;
  return c;
}

Capture MockCamera::capture_replay() {
  const ReplayShot& shot = shots_[next_];
  Capture c;
  c.image = store(fs::path(shot.image).filename().string(), read_bytes(shot.image));
  for (const auto& companion : shot.companions)
    c.companions.push_back(store(fs::path(companion).filename().string(), read_bytes(companion)));
  c.exif = read_exif(c.image.data);
  return c;
}

Capture MockCamera::capture_synthetic() {
  const SyntheticScene& scene = *scene_;
  NoProgress quiet;
  const int station = static_cast<int>(next_);
  SyntheticView view = render_view(scene, station, rendered_intrinsics(scene), false, quiet);

  ExifInfo exif;
  exif.make = body_.make;
  exif.model = body_.model;
  exif.lens = body_.lens;
  char when[32];
  std::snprintf(when, sizeof when, "2026:01:01 12:00:%02d", station);
  exif.datetime = when;
  exif.focal_length_mm = scene.camera.fx * body_.sensor_width_mm / scene.camera.width;
  exif.f_number = std::stod(find("f-number").value);
  exif.exposure_time_s = shutter_seconds(find("shutterspeed").value);
  exif.iso = std::stoi(find("iso").value);
  exif.flash_fired = find("flashmode").value == "On";
  // A scene that asks for a sensor at an ISO or a flash was shot so.
  if (scene.effects.sensor) exif.iso = static_cast<int>(std::lround(scene.effects.sensor->iso));
  if (scene.effects.flash) exif.flash_fired = true;
  const auto& st = scene.stations[station];
  exif.focus_distance_m =
      focus_locked_ && locked_focus_m_ ? *locked_focus_m_ : (st.look_at - st.position).norm();
  exif.width = scene.camera.width;
  exif.height = scene.camera.height;

  std::vector<uint8_t> jpeg;
  cv::imencode(".jpg", view.image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95});
  char name[32];
  std::snprintf(name, sizeof name, "SYN_%04d", station + 1);
  Capture c;
  c.image = store(std::string(name) + ".JPG", with_exif(jpeg, exif));
  c.exif = exif;
  if (find("imagequality").value != "JPEG Fine") {
    std::vector<uint8_t> png;
    cv::imencode(".png", view.image, png);
    c.companions.push_back(store(std::string(name) + ".PNG", std::move(png)));
  }
  return c;
}

cv::Mat MockCamera::live_view() {
  if (closed_) throw CameraError(Kind::disconnected, "The mock camera is closed");
  if (mode_ == Mode::replay) {
    const auto& shot = shots_[std::min(next_, shots_.size() - 1)];
    cv::Mat full = cv::imread(shot.image, cv::IMREAD_COLOR);
    if (full.empty())
      throw CameraError(Kind::file_unreadable,
                        "Replay: " + shot.image + " is not a readable image");
    const double scale = std::min(1.0, 1024.0 / full.cols);
    cv::Mat frame;
    cv::resize(full, frame, cv::Size(), scale, scale, cv::INTER_AREA);
    return frame;
  }
  // Live view is a small frame of what the next station sees (1/8 scale,
  // pixel centres kept: x' = (x + 0.5) s - 0.5).
  const SyntheticScene& scene = *scene_;
  photogrammetry::CameraIntrinsics small = rendered_intrinsics(scene);
  const double s = std::min(1.0, 1024.0 / small.width);
  small.width = std::max(1, static_cast<int>(small.width * s));
  small.height = std::max(1, static_cast<int>(small.height * s));
  small.fx *= s;
  small.fy *= s;
  small.cx = (small.cx + 0.5) * s - 0.5;
  small.cy = (small.cy + 0.5) * s - 0.5;
  NoProgress quiet;
  return render_view(scene, static_cast<int>(std::min<size_t>(next_, 1)), small, false, quiet)
      .image;
}

std::vector<CameraEvent> MockCamera::events(int /*timeout_ms*/) {
  std::vector<CameraEvent> out(events_.begin(), events_.end());
  events_.clear();
  out.push_back({CameraEvent::Kind::timeout, {}});
  return out;
}

void MockCamera::close() {
  closed_ = true;
}

}  // namespace rockface::camera
