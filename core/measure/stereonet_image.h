#pragma once
// The stereonet picture (lower hemisphere, equal area by default): poles
// coloured by set, Fisher density contours, the sets' great circles and
// alpha95 cones, the free faces' great circles and a kinematic overlay for
// planar sliding on a free face (daylight envelope and friction circle,
// Markland's test: the critical zone is shaded).
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/geometry/orientation.h"
#include "core/geometry/stereonet.h"

namespace rockface::measure {

struct StereonetSet {
  std::string label;
  geometry::PlaneOrientation mean;  // radians
  double alpha95 = 0;               // radians; 0: no cone drawn
  // The variability cone (radians; fisher_cone in joint_sets.h): where 95 %
  // of the set's poles lie, drawn thin; 0: not drawn.
  double variability = 0;
};

struct StereonetFace {
  std::string label;
  geometry::PlaneOrientation orientation;  // radians
};

// Planar sliding on a free face: a plane slides when its pole lies outside
// the friction circle (dip > friction) and it daylights in the face (dips
// less than the face along its dip direction) within the lateral limit of
// the face's dip direction.
struct KinematicOverlay {
  geometry::PlaneOrientation face;            // radians
  double friction = 0;                        // radians
  double lateral_limit = 0.3490658503988659;  // radians (20 degrees)
};

struct StereonetPicture {
  std::string title;
  std::vector<Eigen::Vector3d> poles;  // plane normals (either sense)
  std::vector<int> pole_sets;          // per pole: set index into `sets`, or -1; may be empty
  std::vector<StereonetSet> sets;
  std::vector<StereonetFace> faces;
  std::optional<KinematicOverlay> kinematics;
  // The great circle of every pole's plane, thin, in its set's colour.
  bool plane_great_circles = false;
  // The friction circle alone (radians), when there is no free face for the
  // kinematic overlay (which draws its own): poles inside it dip less than
  // the friction angle.
  std::optional<double> friction;
  geometry::Projection projection = geometry::Projection::EqualArea;
  geometry::Hemisphere hemisphere = geometry::Hemisphere::Lower;
  bool density_contours = true;
  int size_px = 800;  // the picture is size_px square
};

// The colour (BGR) of set k; unassigned poles are grey.
cv::Scalar set_colour(int set);

// Pixel of a point of the net (unit circle, x East, y North) in a picture of
// `size_px`: where render_stereonet draws it.
Eigen::Vector2d net_to_pixel(const Eigen::Vector2d& net, int size_px);

// Where render_stereonet writes the net's "N" (its north mark's letter) and
// the title in a picture of `size_px`: the title starts right of the N and
// never covers it (issue 39).
cv::Rect north_label_box(int size_px);

// BGR CV_8UC3, size_px square. Throws InputError("stereonet", ...) for
// size_px below 200 or pole_sets of the wrong length.
cv::Mat render_stereonet(const StereonetPicture& picture);

}  // namespace rockface::measure
