#pragma once
// Traces marked on the photographs of several 3D images, in the one face
// frame: each picked pixel is lifted to its image's surface and moved by that
// image's registration; pieces of one joint trace marked on overlapping
// images (they cross from one photograph to the next) become one trace.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/photogrammetry/multi_image_registration.h"

namespace rockface::photogrammetry {

// A polyline marked on one image's photograph.
struct ImageTrace {
  std::string label;  // "T1"
  std::string joint;  // the joint it belongs to; empty when unassigned
  int image = 0;      // index into the FaceImages
  std::vector<Eigen::Vector2d> pixels;
};

struct FaceTrace {
  std::string label;  // of its first piece
  std::string joint;
  std::vector<Eigen::Vector3d> points;  // face frame, ordered along the trace
  std::vector<std::string> pieces;      // labels of the image traces joined into it
};

struct FaceTraceOptions {
  // Pieces come within this distance (face units) of each other: candidates
  // to join. Pieces of one trace overlap on the common area of two images and
  // differ there by the registration residual; distinct parallel traces of a
  // joint set lie decimetres apart or more.
  double join_distance = 0.05;
  // ... and run in directions this close (degrees).
  double max_angle_deg = 10.0;
};

// Throws InputError naming a trace whose image index is out of range.
std::vector<FaceTrace> traces_in_face_frame(const std::vector<FaceImage>& images,
                                            const FaceRegistration& face,
                                            const std::vector<ImageTrace>& traces,
                                            const FaceTraceOptions& options = {});

}  // namespace rockface::photogrammetry
