#pragma once
// A face outlined on the 3D image (issue 27), split into the flat pieces it
// covers: a face that is folded (two walls a few degrees apart, a ridge
// left by the blast) is no one plane, and the analysis snaps a trace onto
// the face's patches within a few centimetres (SCENE.md surface.patches), so
// an outline stored as one flat patch leaves every trace off the surface.
//
// The pieces are found with the facet finder (facets/facets.h: region
// growing on the normals, each region held to a plane by measuring's
// planarity test), its facets grouped by the plane they lie in, and every
// point inside the outline given to the nearest of those planes. Each
// piece is then an area measurement as `rockface measure` makes of a
// polygon (measure_area): its polygon in the photograph is the outline cut
// along the lines where its plane meets its neighbours' (the projection of
// the planes' intersection), and its corners are those pixels' rays met
// with its plane, so that neighbouring pieces share their common edge in
// 3D. A flat face stays one piece, measured as measure_area measures it.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/measure/facets/facet_options.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "core/measure/plane_measurement.h"

namespace rockface::measure {

struct OutlinePieces {
  // Largest first. One piece: the outline as measure_area measures it, with
  // `id` as given; several: ids `id` + "a", "b", ... Each piece's RMS off
  // its plane (plane.fit.rms_off_plane()) is its margin as a plane. Its
  // corners turn counter-clockwise seen from the camera (from outside the
  // rock, as SCENE.md's surface patches do), whichever way they were tapped
  // (wind_toward_camera, free_face_side.h: a piece the camera sees edge-on
  // keeps the order tapped, and its note says so).
  std::vector<AreaMeasurement> pieces;
  // What a geologist should know, in words: a part too small or too rough
  // to be a plane (and where its area went), why a folded outline stayed
  // one piece.
  std::vector<std::string> notes;
};

// The outline `polygon` (pixels of `view`, 3 or more corners) split into
// flat pieces. `options`: the facet finder's knobs (facet_options(preset));
// its planarity_in_sigmas and min_area_m2 also judge each piece.
// `snap_tolerance` (m): how far off a patch the analysis still takes a
// trace's point to lie on it (SCENE.md analysis.snap_tolerance, 0.05 m): a
// piece is held to an RMS of half of it (95 % of a normal spread then lies
// within it), however coarse the stated point precision. Throws
// InputError naming `where` for a degenerate outline (fewer than 3 corners,
// corners on one line, edges that cross) or one with no surface under it.
OutlinePieces split_outline(const MeshPicker& picker, const PhotoView& view, const std::string& id,
                            const std::vector<Eigen::Vector2d>& polygon,
                            const MeasureSettings& settings, const FacetOptions& options,
                            double snap_tolerance, const std::string& where);

// The outline cut by the half-plane of pixels p with
// (p - a) x d >= 0 (cross product's z), Sutherland-Hodgman: a polygon that
// is not convex comes out as one polygon, perhaps with edges along the line.
std::vector<Eigen::Vector2d> clip_polygon(const std::vector<Eigen::Vector2d>& polygon,
                                          const Eigen::Vector2d& a, const Eigen::Vector2d& d);

}  // namespace rockface::measure
