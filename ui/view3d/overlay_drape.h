#pragma once
// Lines and areas laid on the 3D image as it is drawn (the decimated display
// mesh), so that what the geologist sees on the photograph's texture is
// where the trace or block is, never a line in the air in front of or beyond
// the face.
//
// A point goes onto the surface along the drape direction (the face's mean
// normal, toward the viewer): the surface point on that line within
// `tolerance()` of it, or nothing (off the mapped area, or in a hole of the
// 3D image). A polyline is sampled at the mesh's point spacing, each sample
// put on the surface, and the pieces between two samples on neighbouring
// triangles split at their shared edge, so that every drawn segment lies in
// one triangle; the parts that leave the surface are cut out (a run ends).
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/measure/mesh_picker.h"
#include "core/photogrammetry/surface/surface_mesh.h"
#include "ui/view3d/display_mesh.h"

namespace rockface::ui {

class SurfaceDrape {
 public:
  // Builds the surface (project frame) and its pick index from the display
  // mesh; the mesh need not outlive the drape.
  explicit SurfaceDrape(const DisplayMesh& mesh);
  SurfaceDrape(const SurfaceDrape&) = delete;
  SurfaceDrape& operator=(const SurfaceDrape&) = delete;

  // Unit direction along which points are laid on the surface (out of the
  // rock, toward the viewer of the framed view).
  const Eigen::Vector3d& direction() const { return direction_; }
  // How far (m) a point may be from the drawn surface and still be on it:
  // the decimation's displacement (a cell's diagonal) plus three point
  // spacings of the drawn surface (the roughness a trace picked on the
  // full-resolution surface, or on a further pair's 3D image registered to
  // this one within a few centimetres, shows against the decimated one).
  double tolerance() const { return tolerance_; }
  // Median edge of the drawn surface (m): the sampling step of draping.
  double spacing() const { return spacing_; }

  // The surface point for `point`, with its triangle, or nothing; `slack`
  // (m) is added to the tolerance.
  std::optional<measure::PickHit> project(const Eigen::Vector3d& point, double slack = 0) const;
  // The runs of a polyline (closed: the last point joins the first) that
  // lie on the surface, each with two points or more. `sag` (a fraction of
  // each segment's length) widens the tolerance on that segment: a straight
  // edge between two points of a bent surface (a block's corners on two
  // patches of the face) leaves the surface by up to half its length times
  // the sine of half the bend.
  std::vector<std::vector<Eigen::Vector3d>> drape(const std::vector<Eigen::Vector3d>& line,
                                                  bool closed, double sag = 0) const;

  // Coordinates in the plane across the drape direction.
  Eigen::Vector2d to_plane(const Eigen::Vector3d& point) const;
  // Triangles of the surface whose centre lies inside a polygon given in
  // plane coordinates (to_plane).
  std::vector<int> triangles_inside(const std::vector<Eigen::Vector2d>& polygon) const;
  // The border of the mapped area (surface edges with one triangle) where
  // its edges' middles lie inside a polygon in plane coordinates, chained
  // into polylines: where what the polygon outlines goes on beyond the 3D
  // image.
  std::vector<std::vector<Eigen::Vector3d>> open_edges_inside(
      const std::vector<Eigen::Vector2d>& polygon) const;

  const photogrammetry::SurfaceMesh& surface() const { return surface_; }
  const measure::MeshPicker& picker() const { return *picker_; }

 private:
  void refine(const measure::PickHit& from, const measure::PickHit& to, int depth, double slack,
              std::vector<std::vector<Eigen::Vector3d>>& runs) const;
  std::optional<std::array<int, 2>> shared_edge(int a, int b) const;

  photogrammetry::SurfaceMesh surface_;
  std::unique_ptr<measure::MeshPicker> picker_;
  Eigen::Vector3d direction_ = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d e1_ = Eigen::Vector3d::UnitX(), e2_ = Eigen::Vector3d::UnitY();
  double tolerance_ = 0, spacing_ = 0;
  std::vector<std::array<int, 2>> boundary_;  // vertex pairs of the edges with one triangle
};

// Lines laid on one surface, kept by their points: the Mapping screen shows
// the same stored traces frame after frame.
class DrapeCache {
 public:
  using Runs = std::vector<std::vector<Eigen::Vector3d>>;
  // `sag` as SurfaceDrape::drape's (a polygon's straight edges between
  // corners on a bent surface).
  const Runs& runs(const SurfaceDrape& drape, const std::vector<Eigen::Vector3d>& line, bool closed,
                   double sag = 0);
  void clear() { cache_.clear(); }

 private:
  std::map<std::vector<double>, Runs> cache_;
};

// Whether a point lies inside a polygon (even-odd rule), plane coordinates.
bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace rockface::ui
