#include "core/photogrammetry/camera/photo_camera.h"

#include <cctype>

#include "core/common/number_format.h"

namespace rockface::photogrammetry {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string PhotoCamera::described() const {
  std::string out = model.empty() ? "an unknown camera" : model;
  // Makers repeat their name in the model ("NIKON D750"); when they do not
  // ("Canon" / "EOS 5D"), the make is said too.
  const std::string maker = lower(make.substr(0, make.find(' ')));
  if (!make.empty() && !model.empty() && lower(model).rfind(maker, 0) != 0)
    out = make + " " + model;
  if (!serial.empty()) out += " (serial " + serial + ")";
  if (!lens.empty()) out += ", lens " + lens;
  if (focal_mm) out += " at " + format_significant(*focal_mm, 4) + " mm";
  if (width > 0 && height > 0)
    out += ", " + std::to_string(width) + " x " + std::to_string(height) + " px";
  return out;
}

}  // namespace rockface::photogrammetry
