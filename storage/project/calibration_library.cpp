#include "storage/project/calibration_library.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "core/common/number_format.h"

namespace rockface::storage {

namespace {

// EXIF text comes padded and in the maker's case ("NIKON CORPORATION ",
// "Nikon"); a body is the same body whatever the case and padding.
std::string plain(const std::string& s) {
  std::string out;
  for (const char c : s)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!out.empty() && out.back() != ' '))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c == '\t' ? ' ' : c)));
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

bool same_known(const std::string& a, const std::string& b) {
  return a.empty() || b.empty() || plain(a) == plain(b);
}

// Makers write "NIKON CORPORATION" in Make and "NIKON D750" in Model: the
// model alone names the body when one contains the other.
bool same_model(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return true;
  const std::string x = plain(a), y = plain(b);
  return x == y || x.find(y) != std::string::npos || y.find(x) != std::string::npos;
}

// Half a millimetre: zoom settings are read from EXIF to 0.1 mm or better,
// and the nearest marked settings of a zoom lens lie 2 mm or more apart.
constexpr double kFocalSettingToleranceMm = 0.5;

}  // namespace

bool calibration_fits(const Calibration& c, const std::optional<CameraBody>& body,
                      const PhotoCamera& photo, std::string* why) {
  const auto no = [why](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  const auto& k = c.intrinsics;
  if (photo.width > 0 && photo.height > 0 && (k.width != photo.width || k.height != photo.height))
    return no("calibrated at " + std::to_string(k.width) + " x " + std::to_string(k.height) +
              " px");
  if (body) {
    if (!same_model(body->model, photo.model)) return no("of another body (" + body->model + ")");
    if (!same_known(body->serial, photo.serial))
      return no("of another body (serial " + body->serial + ")");
  }
  if (!same_known(k.lens, photo.lens)) return no("with another lens (" + k.lens + ")");
  if (c.focal_setting_mm > 0 && photo.focal_mm &&
      std::abs(c.focal_setting_mm - *photo.focal_mm) > kFocalSettingToleranceMm)
    return no("at " + format_significant(c.focal_setting_mm, 4) + " mm");
  return true;
}

CalibrationChoice choose_calibration(ProjectStore& store, const PhotoCamera& photo) {
  const std::vector<CameraBody> bodies = store.list_camera_bodies();
  std::vector<Calibration> all = store.list_calibrations();
  // Newest first.
  std::sort(all.begin(), all.end(),
            [](const Calibration& a, const Calibration& b) { return a.id > b.id; });
  CalibrationChoice out;
  std::string nearest;
  for (const auto& c : all) {
    std::optional<CameraBody> body;
    for (const auto& b : bodies)
      if (c.body_id && b.id == *c.body_id) body = b;
    std::string why;
    if (calibration_fits(c, body, photo, &why)) {
      out.calibration = c;
      return out;
    }
    if (nearest.empty()) nearest = "the newest, " + std::to_string(c.id) + ", is " + why;
  }
  out.refusal = "no calibration of " + photo.described() + " in the project" +
                (all.empty() ? std::string()
                             : " (" + std::to_string(all.size()) + " stored; " + nearest + ")") +
                ": calibrate this camera and lens at this focal length (rockface calibrate "
                "--project), or choose a calibration";
  return out;
}

void record_camera(Capture& capture, const PhotoCamera& photo) {
  const std::pair<const char*, std::string> fields[] = {
      {"camera_make", photo.make},
      {"camera_model", photo.model},
      {"camera_serial", photo.serial},
      {"camera_lens", photo.lens},
      {"camera_focal_mm", photo.focal_mm ? format_round_trip(*photo.focal_mm) : std::string()}};
  for (const auto& [key, value] : fields)
    if (!value.empty()) capture.settings[key] = value;
}

std::optional<PhotoCamera> recorded_camera(const Capture& capture) {
  auto field = [&](const char* key) {
    const auto it = capture.settings.find(key);
    return it == capture.settings.end() ? std::string() : it->second;
  };
  PhotoCamera photo;
  photo.make = field("camera_make");
  photo.model = field("camera_model");
  photo.serial = field("camera_serial");
  photo.lens = field("camera_lens");
  if (photo.make.empty() && photo.model.empty() && photo.serial.empty()) return std::nullopt;
  const std::string focal = field("camera_focal_mm");
  if (!focal.empty()) {
    char* end = nullptr;
    const double mm = std::strtod(focal.c_str(), &end);
    if (end != focal.c_str() && std::isfinite(mm) && mm > 0) photo.focal_mm = mm;
  }
  return photo;
}

}  // namespace rockface::storage
