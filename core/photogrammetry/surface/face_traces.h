#pragma once
// Traces marked on the photographs of several 3D images, in the one face
// frame: each picked pixel is lifted to its image's surface and moved by that
// image's registration; pieces of one joint trace marked on overlapping
// images (they cross from one photograph to the next) become one trace
// (trace_pieces.h).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/reconstruction/multi_image_registration.h"
#include "core/photogrammetry/surface/trace_pieces.h"

namespace rockface::photogrammetry {

// A polyline marked on one image's photograph.
struct ImageTrace {
  std::string label;  // "T1"
  std::string joint;  // the joint it belongs to; empty when unassigned
  int image = 0;      // index into the FaceImages
  std::vector<Eigen::Vector2d> pixels;
};

// Each trace's pixels lifted to its image's surface (a pixel off the surface
// is skipped, a trace with fewer than two on it left out) and moved into the
// face frame, then joined (join_trace_pieces).
// Throws InputError naming a trace whose image index is out of range.
std::vector<FaceTrace> traces_in_face_frame(const std::vector<FaceImage>& images,
                                            const FaceRegistration& face,
                                            const std::vector<ImageTrace>& traces,
                                            const FaceTraceOptions& options = {});

}  // namespace rockface::photogrammetry
