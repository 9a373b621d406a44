#pragma once
// A 3D image made elsewhere becomes a visit's 3D image (`rockface import`,
// and the tablet's Project screen): the file is read (storage/exchange's
// import readers), a point cloud is meshed (a 2.5D Delaunay over its best
// plane, holes left as holes), a virtual photograph of it is drawn (the
// "left photograph" the geologist maps on: every vertex has its pixel), and
// the visit, the view's calibration, the view as a capture and the model are
// stored in one transaction, after everything was read and checked: a
// refused import leaves the project as it was.
//
// Frames: a file in survey coordinates (coordinates beyond 10 km, an
// --offset, or a PLY that names its datum) is already scaled, levelled and
// oriented: its registration is "scanner" (the scanner's registration), and
// its points are moved to the project's datum (a project with no datum and no
// 3D image yet takes the file's). A file in a local frame is stored as it is,
// registration "none", until control points picked on it place it.
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/common/progress.h"
#include "firmware-app/import/import_range_pole.h"
#include "storage/exchange/import_reader.h"
#include "storage/project/project_records.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct ImportRequest {
  std::filesystem::path file;
  storage::ImportFileOptions file_options;
  std::optional<storage::RecordId> visit;  // add to this visit; none: a new visit
  std::string geologist;                   // who mapped the new visit; "" none
  // "survey" | "local" | "" (from the coordinates: survey beyond 10 km).
  std::string frame;
  // A point the surface is seen from (absolute, as the file's coordinates
  // plus the offset): where the scanner stood or the geologist looks from.
  // None: the file's normals or faces say, else the upper side of a surface
  // lying flat, else a side the note names.
  std::optional<Eigen::Vector3d> view_from;
  // A local-frame cloud's ground control: CSV id,u,v,X,Y,Z, u and v pixels
  // of its virtual view (import_control_points.h); empty: none.
  std::string gcp_file;
  // A local-frame cloud's range pole (import_range_pole.h): its two targets
  // in the file's coordinates, the pole's length (none: the length the
  // geologist last typed in this project, `range_pole_m`), and a compass
  // line for north.
  std::optional<ImportPole> pole;
  // `--pole auto`: the two targets found in the cloud's colours
  // (photogrammetry/targets/cloud_range_pole.h) instead of given.
  bool find_pole = false;
  std::optional<double> pole_length_m;
  std::optional<ImportCompassLine> north;
};

struct ImportResult {
  storage::RecordId visit = 0, model = 0, capture = 0;
  std::string format;
  std::size_t points = 0, triangles = 0, skipped_points = 0, unused_points = 0;
  // A cloud without colours whose file held a scanner's intensity: the
  // intensity range drawn black to white (storage/exchange/intensity_grey.h).
  std::optional<std::array<double, 2>> intensity_as_grey;
  bool meshed = false;             // a cloud meshed here (else the file's faces)
  std::string round_meshing;       // a round meshed on the tunnel's developed view: how
  std::string frame;               // "survey" | "local"
  std::string registration_kind;   // "scanner" | "ground_control" | "range_pole[_compass]" | "none"
  std::size_t control_points = 0;  // ground control: how many, their rms, the scale found
  double control_rms_m = 0, control_scale = 1;
  std::optional<double> pole_length_m;   // the range pole's, when it registered the cloud
  std::optional<ImportPole> pole_found;  // `--pole auto`: the targets' centres, the file's frame
  std::optional<double> north_rotation_deg;  // the compass line's turn about the vertical
  Eigen::Vector3d file_datum = Eigen::Vector3d::Zero();  // absolute = stored vertex + datum
  Eigen::Vector3d project_datum = Eigen::Vector3d::Zero();
  bool project_datum_set = false;  // the project took the file's datum
  double point_spacing_m = 0;
  // A meshed cloud's scatter normal to its surface (cloud_noise.h), stored as
  // the model's predicted depth precision.
  std::optional<double> noise_sigma_m;
  int view_width = 0, view_height = 0;
  std::string view_side;  // how the side the view looks from was chosen, in words
};

// "0 black to 4095 white": the intensity range the colours were drawn from;
// empty when they were not.
std::string intensity_range_words(const ImportResult& r);

// `progress` hears each stage (reading, meshing, the view, storing); a
// cancel before the storing stores nothing.
ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request,
                            Progress& progress);
ImportResult import_surface(storage::ProjectStore& store, const ImportRequest& request);

}  // namespace rockface::app
