#pragma once
// Planar facets on the 3D image, as qFacets (Dewez et al. 2016) and the
// Discontinuity Set Extractor (Riquelme et al. 2014) find them: region
// growing over the mesh's triangles on their (smoothed) normals, each region
// held to a plane by the planarity test of measuring (plane_measurement.h);
// then, over what that left, growing led by the points' distance to a
// fitted plane (plane_led_growing.h: a face seen obliquely, whose single
// triangles' normals scatter too much); each region measured like an area
// picked by hand, its plane on its interior: dip / dip direction, sigma,
// area, centroid and outline. Sets from facets: facet_sets.h.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/common/progress.h"
#include "core/measure/facets/facet_options.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

struct Facet {
  int id = 0;  // 1, 2, ... largest first
  // The plane of the facet's vertices (plane_of_points): orientation,
  // sigma (radians, one standard deviation of the normal), centroid and
  // spreads; always `known` for a facet that is kept.
  PlaneEstimate plane;
  double area = 0;                                     // m^2, of its triangles
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // area-weighted, model frame
  std::vector<Eigen::Vector3d> outline;                // outer boundary, closed, thinned
  int holes = 0;
  std::size_t triangles = 0;
  std::size_t vertices = 0;  // of its interior, whose plane it is (facets.cpp)
  // Margins of the two tests it passed (positive: inside): planarity in
  // point sigmas (the limit minus the RMS off the plane), and orientation
  // in degrees (kMaxPlaneSigmaDeg minus sigma). A facet is marginal when
  // its planarity margin is under one sigma.
  double planarity_margin_sigmas = 0;
  double orientation_margin_deg = 0;
  bool marginal = false;
  // The facet's triangles (indices into the mesh), for drawing it.
  std::vector<int> mesh_triangles;
};

struct FacetSearch {
  std::vector<Facet> facets;  // largest first
  FacetOptions options;       // the knobs used
  double point_sigma = 0;     // m, the point precision the tests used
  double mapped_area = 0;     // m^2, every usable triangle of the mesh
  double facet_area = 0;      // m^2, the facets' sum
  // Area-weighted mean normal of the whole mapped surface: the face's
  // general attitude (facet_sets.h compares sets with it).
  Eigen::Vector3d surface_normal = Eigen::Vector3d::UnitZ();
  // Regions that grew past the minimum area but failed the planarity or
  // orientation test (rounded or rough surfaces), with their area.
  int rejected_regions = 0;
  double rejected_area = 0;
  std::vector<std::string> notes;  // what a geologist should know (empty mesh, ...)
};

// The facets of `mesh` (model frame: x East, y North, z Up, metres).
// `settings.point_sigma` is the 3D image's point precision (the
// reconstruction's sigma_Z) and must be positive. An empty mesh, or one
// without a usable triangle, gives no facet and a note saying why; options
// out of range throw InputError naming the knob.
FacetSearch find_facets(const photogrammetry::SurfaceMesh& mesh, const MeasureSettings& settings,
                        const FacetOptions& options, Progress& progress);

}  // namespace rockface::measure
