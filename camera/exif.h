#pragma once
// The EXIF fields the field workflow needs from a JPEG: what the lens and
// focus were set to (a stereo pair must share them), exposure, flash, the
// camera and the time. Read and written with libexif (Debian libexif-dev,
// which libgphoto2-dev already depends on).
//
// Focus distance comes from the standard SubjectDistance tag; bodies that
// keep it only in their maker note report none.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/photogrammetry/camera/photo_camera.h"

namespace rockface::camera {

struct ExifInfo {
  std::string make, model, lens;
  std::string serial;    // BodySerialNumber: which body of that model (issue 42)
  std::string datetime;  // DateTimeOriginal, "YYYY:MM:DD HH:MM:SS"
  std::optional<double> focal_length_mm;
  std::optional<double> f_number;
  std::optional<double> exposure_time_s;
  std::optional<int> iso;
  std::optional<bool> flash_fired;
  std::optional<double> focus_distance_m;  // SubjectDistance
  std::optional<int> width, height;        // PixelXDimension / PixelYDimension

  bool empty() const;
};

// Parses the EXIF block of a JPEG (or a raw "Exif\0\0" TIFF block). A file
// without EXIF gives an empty ExifInfo; damaged tags are skipped, never
// trusted.
ExifInfo read_exif(const std::vector<uint8_t>& jpeg);

// What the photograph says of its camera, for choosing its calibration.
photogrammetry::PhotoCamera photo_camera(const ExifInfo& info);

// Reads a file's EXIF. Throws InputError(path, ...) when the file cannot be read.
ExifInfo read_exif_file(const std::string& path);

// The fields that are set, as name -> text ("focal_length_mm" -> "24"), the
// form a project stores with a capture.
std::map<std::string, std::string> exif_fields(const ExifInfo& info);

// Returns the JPEG with an APP1 EXIF block holding `info` inserted after the
// start-of-image marker (any EXIF block already there is replaced). Throws
// Error when `jpeg` is not a JPEG.
std::vector<uint8_t> with_exif(const std::vector<uint8_t>& jpeg, const ExifInfo& info);

}  // namespace rockface::camera
