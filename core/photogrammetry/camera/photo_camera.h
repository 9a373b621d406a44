#pragma once
// What a photograph says of the camera that took it (from its EXIF and its
// pixels): which body, lens and focal setting, so that it gets that
// camera's calibration (storage/project/calibration_library.h, issue 42).
#include <optional>
#include <string>

namespace rockface::photogrammetry {

struct PhotoCamera {
  std::string make, model, serial, lens;
  std::optional<double> focal_mm;
  int width = 0, height = 0;  // pixels; 0 when the photograph does not say

  // "NIKON D750 (serial 3012345), lens 24.0 mm f/1.8 at 24 mm, 6016 x 4016 px"
  std::string described() const;
};

}  // namespace rockface::photogrammetry
