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

#include "core/tunnel/alignment.h"
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

// The surface's rock placed along the tunnel: every k-th vertex that is rock
// (20,000 places give the percentiles below to well under a millimetre).
std::vector<tunnel::AlignmentPlace> rock_places(const tunnel::Alignment& alignment,
                                                const VisitSurface& surface);

// How far the rock reaches along the drive: the 2nd percentile of chainage
// in the drive direction (the rear of the walls the cameras saw) and the
// 99th (the face), so that a few stray points count for nothing. Nothing
// when there is no rock.
struct SurfaceReach {
  double rear = 0, front = 0;  // chainages
};
std::optional<SurfaceReach> surface_reach(const tunnel::Alignment& alignment,
                                          const std::vector<tunnel::AlignmentPlace>& places);

}  // namespace rockface::app
