#pragma once
// Trace proposals (issue 25): the lines of a visit's 3D image that look like
// joint traces, found without a tap, for the geologist to accept, correct or
// reject. Two cues, both read on the left photograph's lattice (every mesh
// vertex knows its pixel):
//  - folds of the surface: ridges and valleys of curvature, where the mesh
//    normal turns by more than a few degrees over a few centimetres (the
//    edge where two joint faces meet);
//  - dark lines of the photograph: a thin line darker than both its sides
//    (an open or filled joint seen face-on), from the Hessian of the grey
//    image at the widths a trace has on the rock.
// Each cue is thinned to one-pixel ridges (non-maximum suppression across
// the line, hysteresis linking), the two are joined, broken into polylines,
// gaps of a few centimetres bridged, and each polyline is measured exactly
// like a hand trace (measure_trace: points on the mesh, plane fit with its
// planarity and relief tests, length, censoring). A polyline that turns
// sharply is split where the two sides do not lie on one plane: two joints
// meeting, not one joint crossing a fold of the face.
//
// Each proposal carries a confidence in [0, 1] from its evidence (fold
// angle, contrast against the photograph's line noise, length, and the two
// cues agreeing), and the facet whose outline it follows, if any.
//
// The facets come from whoever finds them (core/measure/facets, the propose
// workflow); they enter here as plain outlines so that this module does not
// depend on how they were found.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/common/preset.h"
#include "core/common/progress.h"
#include "core/measure/mesh_picker.h"
#include "core/measure/photo_view.h"
#include "core/measure/plane_measurement.h"
#include "core/photogrammetry/surface/surface_mesh.h"

namespace rockface::measure {

// A planar facet found on the 3D image, as far as trace proposals need it:
// its id (the caller's) and its outline on the mesh (a closed polygon, mesh
// frame, metres; the last point joins the first).
struct ProposalFacet {
  int id = -1;
  std::vector<Eigen::Vector3d> outline;
};

// The knobs; proposal_options(preset) gives the defaults, each traded for
// time in docs/accuracy-cost.md ("Trace proposals").
struct ProposalOptions {
  // Widths (m) of the dark lines looked for: one Hessian scale per width.
  std::vector<double> line_widths_m{0.02, 0.04};
  // The photograph is reduced (never enlarged) so that the narrowest width
  // spans this many pixels: finer costs time and finds no more on a 24 Mpx
  // frame, where a 2 cm trace is ~18 px wide.
  double pixels_per_line = 4.0;
  // A dark-line pixel: Hessian response this many robust sigmas (of the
  // photograph's own response: rock texture and noise) above the median
  // (hysteresis: seed and continuation).
  double dark_seed_sigmas = 6.0, dark_keep_sigmas = 3.0;
  // ... and darker than both its sides by at least this (grey levels of
  // 255): a step in brightness (a shadow edge) is not a line.
  double min_contrast_grey = 6.0;
  // Folds: the normals are smoothed over fold_scale_m (at least three
  // lattice cells: the dense matching's noise) and a fold is where they turn
  // by at least min_fold_deg across it (seed), fold_keep_deg (continuation).
  double fold_scale_m = 0.05;
  double min_fold_deg = 12.0, fold_keep_deg = 7.0;
  // Gaps up to this (m) between collinear pieces are bridged.
  double max_gap_m = 0.06;
  // A polyline that turns by more than this at a vertex is split there
  // unless both sides lie on one plane.
  double split_turn_deg = 35.0;
  // Proposals shorter than this (m, along the surface) are dropped.
  double min_length_m = 0.3;
  // Proposals below this confidence are dropped.
  double min_confidence = 0.15;
  // A proposal follows a facet's edge when this fraction of its points lie
  // within facet_tolerance_m of the facet's outline.
  double facet_tolerance_m = 0.05;
  double facet_fraction = 0.6;
  // The plane fit, as for a hand trace on this model (point_sigma from the
  // reconstruction's depth precision).
  MeasureSettings measure;
};

ProposalOptions proposal_options(Preset preset);

// Which cues saw a proposal.
enum class ProposalCue { dark_line, fold, both };
const char* proposal_cue_name(ProposalCue cue);

struct TraceProposal {
  std::string id;          // "P1", "P2", ... by falling confidence
  TraceMeasurement trace;  // pixels in the view's photograph, points on the mesh, plane
  double confidence = 0;   // [0, 1]
  ProposalCue cue = ProposalCue::dark_line;
  double contrast_grey = 0;  // mean darkness against both sides (0 where no dark line)
  double fold_deg = 0;       // mean turn of the normal across it (0 where no fold)
  bool ridge = false;        // the fold is convex (a ridge), else concave (a valley)
  double dark_fraction = 0;  // of its length seen by each cue
  double fold_fraction = 0;
  std::optional<int> facet_id;  // the facet whose edge it follows
  double facet_fraction = 0;    // of its points on that edge
};

struct ProposalResult {
  std::vector<TraceProposal> proposals;          // by falling confidence
  double pixel_scale = 1;                        // working image / photograph
  double line_noise = 0;                         // robust sigma of the dark-line response
  std::size_t dark_pixels = 0, fold_pixels = 0;  // after thinning, in the working image
  std::vector<std::string> notes;                // what was left out, in words
};

// `photo`: the photograph of `view` (CV_8UC1 or CV_8UC3, BGR), whose pixels
// the mesh's lattice refers to (mesh.pixels). `picker` is built on `mesh`.
// Checks `progress` between stages (throws Cancelled). Throws InputError
// naming `where` for an empty photograph, a photograph whose size is not the
// view's, or a mesh without pixels.
ProposalResult propose_traces(const photogrammetry::SurfaceMesh& mesh, const MeshPicker& picker,
                              const PhotoView& view, const cv::Mat& photo,
                              const std::vector<ProposalFacet>& facets,
                              const ProposalOptions& options, Progress& progress,
                              const std::string& where);

}  // namespace rockface::measure
