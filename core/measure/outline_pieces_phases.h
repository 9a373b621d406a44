#pragma once
// The phases of split_outline (outline_pieces.h), each a function of its
// own input, declared here so that each can be read and tested on its own:
//   1. piece_settings: the point precision the pieces are judged with;
//   2. outline_submesh: the 3D image inside the outline, a mesh of its own;
//   3. facet_planes: the facets found there grouped by the plane they lie in;
//   4. settle_planes: every point to its nearest plane, the planes refitted,
//      parts too small or too rough dropped (label_points labels);
//   5. touching_pieces and fold_outlines: the outline cut along the lines
//      where neighbouring pieces' planes meet;
//   6. measure_pieces: each piece measured as an area (measure_piece),
//      largest first, named id + a, b, ...
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/plane.h"
#include "core/measure/facets/facet_options.h"
#include "core/measure/facets/facets.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/outline_pieces.h"
#include "core/measure/photo_view.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure::outline_phases {

// The stated settings with the point precision made finer where the
// analysis needs it: the planarity gate (planarity_in_sigmas sigmas) then
// is half the snap tolerance.
MeasureSettings piece_settings(const MeasureSettings& measured, const FacetOptions& options,
                               double snap_tolerance);

// The triangles of the picker's mesh whose corners are all seen inside the
// polygon (pixels of view), re-indexed.
photogrammetry::SurfaceMesh outline_submesh(const MeshPicker& picker, const PhotoView& view,
                                            const std::vector<Eigen::Vector2d>& polygon);

// The facets grouped by the plane they lie in (at most max_planes): a facet
// joins a group when its normal is within options.angle_tolerance_deg of the
// group's and its points lie within `gate` (m, RMS) of the group's plane;
// else it starts a group with its own plane.
std::vector<geometry::Plane> facet_planes(const photogrammetry::SurfaceMesh& sub,
                                          const std::vector<Facet>& facets,
                                          const FacetOptions& options, double gate,
                                          std::size_t max_planes);

// The points of the sub-mesh by plane, and the area of its triangles (each
// given to the plane of two or more of its corners, else its first's).
struct Labelled {
  std::vector<std::vector<Eigen::Vector3d>> points;
  std::vector<double> area;
};
// label[v]: the plane nearest to vertex v (the first of equals).
Labelled label_points(const photogrammetry::SurfaceMesh& sub,
                      const std::vector<geometry::Plane>& planes, std::vector<int>& label);

// The planes after every point went to its nearest and the planes were
// refitted, the parts too small (under options.min_area_m2) or too rough
// (RMS over gate) dropped one by one, each said in a note.
struct SettledPlanes {
  std::vector<geometry::Plane> planes;   // the last planes the points were labelled with
  std::vector<int> label;                // per sub-mesh vertex
  Labelled parts;                        // per plane
  std::vector<PlaneEstimate> estimates;  // per plane, fitted to its part
  std::vector<std::string> notes;        // the parts dropped
  bool too_few = false;                  // fewer than two planes remain
};
SettledPlanes settle_planes(const photogrammetry::SurfaceMesh& sub,
                            std::vector<geometry::Plane> planes, const MeasureSettings& measured,
                            const FacetOptions& options, double gate);

// touch[a][b]: a triangle of the sub-mesh has corners on planes a and b.
std::vector<std::vector<char>> touching_pieces(const photogrammetry::SurfaceMesh& sub,
                                               const std::vector<int>& label, std::size_t n);

// Each piece's polygon: the outline cut along the line where its plane
// meets each touching neighbour's, projected into the photograph, keeping
// its own side (the side most of its points, seen_at, are seen on). Notes
// say where no line was drawn (parallel planes, a line the photograph does
// not see, both pieces on one side).
struct FoldOutlines {
  std::vector<std::vector<Eigen::Vector2d>> outline;  // per piece, pixels
  std::vector<std::string> notes;
};
FoldOutlines fold_outlines(const PhotoView& view, const std::vector<Eigen::Vector2d>& polygon,
                           const std::vector<geometry::Plane>& planes,
                           const std::vector<PlaneEstimate>& estimates,
                           const std::vector<std::vector<char>>& touch,
                           const std::vector<std::vector<Eigen::Vector2d>>& seen_at);

// One piece measured as an area: its outline's corners lifted to its plane
// along their pixels' rays (a ray along or away from the plane gives no
// corner), its plane judged as measure_area judges one.
AreaMeasurement measure_piece(const PhotoView& view, const std::string& name,
                              const std::vector<Eigen::Vector2d>& outline,
                              const geometry::Plane& plane, const PlaneEstimate& estimate,
                              std::size_t vertices, double area, const MeasureSettings& measured,
                              const std::string& where);

// The pieces (largest first, ids `id` + a, b, ...) appended to out, each
// measured over its outline with its plane; a piece without an outline of
// its own is left out, and with three pieces or more one whose outline
// holds too few of its points is said, in out.notes.
void measure_pieces(const PhotoView& view, const std::string& id,
                    const std::vector<geometry::Plane>& planes,
                    const std::vector<PlaneEstimate>& estimates, const Labelled& parts,
                    const std::vector<std::vector<Eigen::Vector2d>>& outline,
                    const std::vector<std::vector<Eigen::Vector2d>>& seen_at,
                    const MeasureSettings& measured, const std::string& where, OutlinePieces& out);

}  // namespace rockface::measure::outline_phases
