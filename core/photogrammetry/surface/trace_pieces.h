#pragma once
// Pieces of joint traces in the one face frame, each marked on one image (a
// stereo pair's photograph), joined where they are one trace crossing from
// one image to the next. Used on pixels lifted to each image's surface
// (face_traces.h) and on traces stored with their pair's model (the scene of
// a visit, storage/scene/export_scene_json.h). Eigen only.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

// A polyline of one image, in the face frame.
struct TracePiece {
  std::string label;  // "T1"
  std::string joint;  // the joint it belongs to; empty when unassigned
  int image = 0;      // which image (pair) it was marked on
  std::vector<Eigen::Vector3d> points;
};

struct FaceTrace {
  std::string label;  // of its first piece
  std::string joint;
  std::vector<Eigen::Vector3d> points;  // face frame, ordered along the trace
  std::vector<std::string> pieces;      // labels of the pieces joined into it
  std::vector<int> images;              // the image of each piece
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

// Joins pieces that continue each other: marked on different images, of the
// same (or an unassigned) joint, within join_distance and running the same
// way within max_angle_deg. Pieces of one image are traces the geologist drew
// apart and are not joined to each other (only through a piece of another
// image that both continue). A piece with fewer than two points stays alone.
// The traces come in the order of their first pieces; a joined trace's
// points are ordered along its run.
std::vector<FaceTrace> join_trace_pieces(const std::vector<TracePiece>& pieces,
                                         const FaceTraceOptions& options = {});

}  // namespace rockface::photogrammetry
