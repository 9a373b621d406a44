#pragma once
// A visit's excavated surface as the tunnel measurements read it: every 3D
// image of the visit (one per stereo pair, all in the face frame: the
// project's datum-relative frame) in one mesh, and which vertices are not
// rock. The range pole stands in the photographs: the vertices around the
// line through its two targets (as the registration found them) are marked,
// so the pole is never counted as underbreak.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/tunnel/lining_precision.h"
#include "core/tunnel/profile_deviation.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct VisitSurface {
  std::vector<Eigen::Vector3d> vertices;  // datum-relative
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::uint8_t> not_rock;  // per vertex
  int models = 0;
  std::size_t pole_vertices = 0;  // marked as the range pole
  // The models' registration: the first pair's (how the face frame was set).
  storage::Model first;  // without its mesh
  // The largest predicted depth sigma the models' reconstructions state
  // (m; every model scaled): the surface's precision. Absent when a model
  // states none or is unscaled (its sigma is then in units of the base).
  std::optional<double> depth_sigma_m;
  // The stereo pairs that made it (their cameras in the same frame, focal
  // length and disparity precision), for each cell's own predicted
  // precision (lining_precision.h). Empty when a model does not record its
  // pair's geometry (a further pair of a face registration, an imported
  // cloud, an unscaled model): then the stated depth_sigma_m holds for all.
  tunnel::LiningPrecision precision;
};

// Around the pole: the pole is 4 cm across and its targets 25 cm; a radius of
// 0.2 m takes the targets' plates and the reconstruction's smear around the
// pole's silhouette, and the line runs from 1 m below the lower target (the
// pole's foot on the invert) to 0.3 m above the upper one.
struct PoleMask {
  double radius_m = 0.2;
  double below_m = 1.0;
  double above_m = 0.3;
};

// Throws InputError naming the visit when it has no 3D image.
VisitSurface visit_surface(storage::ProjectStore& store, storage::RecordId visit_id,
                           const PoleMask& mask = {});

// The surface as the tunnel's measurements read it (views of its vectors:
// the surface must outlive the result).
tunnel::SurfaceInput surface_input(const VisitSurface& surface);

}  // namespace rockface::app
