#pragma once
// The import readers chosen by the file's name (`rockface import`): .ply,
// .obj, .pcd, .xyz / .txt / .csv / .asc, .pts, .ptx, .las. LAZ and E57 are
// refused naming the format and the tools that convert them (no Debian
// library reads them); any other name is refused listing the formats read.
// A cloud without colours whose file holds a scanner's intensity gets its
// colours from it (intensity_grey.h).
#include <filesystem>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "storage/exchange/imported_surface.h"
#include "storage/exchange/xyz_reader.h"

namespace rockface::storage {

struct ImportFileOptions {
  PointColumns columns;  // text clouds: the columns, when the file does not say
  // Added to every coordinate the file holds: the shift a program wrote the
  // file with (CloudCompare's "global shift"), so that absolute = file + offset.
  std::optional<Eigen::Vector3d> offset;
};

ImportedSurface read_imported_surface(const std::filesystem::path& file,
                                      const ImportFileOptions& options = {});

// The names read, for messages and help: ".ply, .obj, ...".
std::string imported_surface_extensions();

// The format a file's name says, as the import names it ("PLY", "LAS",
// "text cloud"; "LAZ" and "E57", which the import refuses saying how to
// convert them), empty when its name says none: what the tablet's file
// picker lists.
std::string imported_surface_format_by_name(const std::filesystem::path& file);

}  // namespace rockface::storage
