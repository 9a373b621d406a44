#pragma once
// A 3D image made elsewhere (a laser scanner's point cloud, a drone or office
// photogrammetry mesh) as the import readers give it: points relative to a
// datum, so that survey coordinates (UTM easting / northing of 10^5..10^7 m)
// keep their tenth of a millimetre, with what the file holds besides:
// colours, normals, faces, a texture.
//
// The readers (las_reader.h, xyz_reader.h, ptx_reader.h, pcd_reader.h,
// obj_reader.h, ply_reader.h; import_reader.h chooses by the file's name)
// refuse a file by InputError naming it and the place, before allocating for
// a count the file cannot hold.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "storage/project/project_records.h"

namespace rockface::storage {

struct ImportedSurface {
  // Vertices relative to `datum`; faces empty for a point cloud; colours and
  // texcoords empty or one per vertex (as the project stores a Mesh).
  Mesh mesh;
  std::vector<Eigen::Vector3f> normals;             // empty or one per vertex
  Eigen::Vector3d datum = Eigen::Vector3d::Zero();  // absolute = vertex + datum
  std::string texture_file;  // the texture image, a path beside the file; empty if none
  std::string format;        // what was read, in words: "LAS 1.4 point format 7"
  // Points the file holds but that carry no surface: a scanner's "no
  // return" (0, 0, 0 in PTX, NaN in an organised PCD). Counted, not kept.
  std::size_t skipped_points = 0;
  // Where the scanner stood for each scan, relative to `datum` as the
  // vertices (PTX's header): the side the surface was seen from.
  std::vector<Eigen::Vector3d> scanner_positions;
  // A scanner's return intensity, one per vertex, as the file holds it
  // (text clouds' intensity column, PTX, LAS), while the file has no colours;
  // empty otherwise. read_imported_surface() turns it into grey colours
  // (intensity_grey.h) and empties it.
  std::vector<float> intensities;
  // The file's intensity range drawn as grey (its least black, its most
  // white), when the colours came from the intensity.
  std::optional<std::array<double, 2>> intensity_as_grey;
};

// The absolute coordinates beyond which a datum is taken (10 km: survey
// coordinates, not a local frame around the scanner or the camera).
constexpr double kSurveySizedCoordinate = 1e4;

// Moves absolute coordinates to datum-relative ones: for coordinates of
// survey size the first point rounded to metres, else zero.
void take_datum(ImportedSurface& s);

// Refuses a point that is not finite: "FILE: WHERE: x is not a finite number".
void require_finite_point(const Eigen::Vector3d& p, const std::string& source,
                          const std::string& where);

// The whole file, or InputError naming it.
std::string read_whole_file(const std::string& file);

}  // namespace rockface::storage
