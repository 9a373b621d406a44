#pragma once
// The range pole's two circular targets found in a point cloud's colours
// (issue 43): a scanner's or a drone's cloud in a local frame that saw the
// pole standing at the face is scaled and levelled by it without anyone
// picking the targets' centres.
//
// The cloud is drawn as a picture, looking along `toward_viewer` with a
// parallel projection (each pixel the colour of the point of the surface
// nearest the viewer that lies nearest the pixel's centre, a pixel about the
// point spacing), and the targets are found in it
// by the photographs' detector (circular_target.h: a white disk in a black
// ring, checked along rays). Each target's centre is then taken back into
// the cloud: the plane fitted (least squares) to the points drawn inside its
// white disk, cut by the line of sight through the disk's centre in the
// picture. Under a parallel projection a circle's centre is the centre of
// its ellipse, so the photographs' perspective correction is not needed.
//
// The two targets of one pole are told from other target-like blobs by what
// a pole is: two disks of one size facing the same way, the line between
// them in their planes, several diameters apart. Which one is the lower is
// read from `up` (the cloud's own z: scanners level their frame, drone
// software keeps z up); a pole lying within kMinPoleRise of the cloud's
// horizontal is refused, as is a second pair that nearly qualifies.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace rockface::photogrammetry {

struct CloudTarget {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // the cloud's frame
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, toward the viewer
  double white_diameter = 0;                         // the white disk across, the cloud's units
  int disk_points = 0;                               // points the plane was fitted to
};

struct CloudRangePole {
  std::array<CloudTarget, 2> targets;  // lower, upper
  std::size_t targets_seen = 0;        // target-like disks found in the picture
  double pixel = 0;                    // the picture's pixel, the cloud's units
};

struct CloudPoleOptions {
  // The picture's pixel in median point spacings: 1.5, so that nearly every
  // pixel on the surface holds a point (a scanner's spacing varies).
  double pixel_to_spacing = 1.5;
  int max_side_px = 4096;  // a 16 Mpx picture at most (the detector searches 2400 px wide)
  // A pole's two targets: sizes within this ratio (one maker's plates;
  // a disk 10 px across is measured to a pixel or so)...
  double max_size_ratio = 1.3;
  // ...facing within this angle of each other (plates turned on the pole
  // toward the instrument)...
  double max_normal_angle_deg = 40;
  // ...the pole within this angle of their planes...
  double max_pole_to_plane_deg = 30;
  // ...and this many to this many white diameters apart.
  double min_separation_diameters = 5, max_separation_diameters = 400;
  // A second pair whose worst criterion is within this factor of its
  // limit makes the pole ambiguous.
  double ambiguity_margin = 2.0;
};

// The pole's rise above the cloud's horizontal below which which target is
// the lower is not known: 30 degrees.
constexpr double kMinPoleRiseDeg = 30;

// colours: RGB, one per point (as the project's Mesh). toward_viewer: unit,
// from the surface to where it is seen from. point_spacing: the median
// nearest-neighbour distance (> 0). up: the cloud's up (unit). Throws
// InputError("range pole", ...) saying what was seen: no colours, no
// target, one target, no pair of a pole, two pairs, a pole lying flat.
CloudRangePole find_range_pole_in_cloud(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<std::array<std::uint8_t, 3>>& colours,
                                        const Eigen::Vector3d& toward_viewer, double point_spacing,
                                        const Eigen::Vector3d& up,
                                        const CloudPoleOptions& options = {});

}  // namespace rockface::photogrammetry
