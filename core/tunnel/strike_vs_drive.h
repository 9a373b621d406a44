#pragma once
// A joint set's orientation against the drive: Bieniawski's RMR89 table
// "effect of discontinuity strike and dip orientation in tunnelling"
// (Bieniawski 1989, Engineering Rock Mass Classifications, the RMR89 table's
// part on discontinuity orientation and its rating adjustment for tunnels):
//
//   strike perpendicular to the tunnel axis (60-90 deg between strike and axis)
//     drive with dip,    dip 45-90   very favourable     0
//     drive with dip,    dip 20-45   favourable         -2
//     drive against dip, dip 45-90   fair               -5
//     drive against dip, dip 20-45   unfavourable      -10
//   strike parallel to the tunnel axis (0-30 deg)
//     dip 45-90                      very unfavourable -12
//     dip 20-45                      fair               -5
//   irrespective of strike: dip 0-20 fair               -5
//
// "Drive with dip": the dip direction has a component along the drive (the
// face advances down the dip of the joints).
//
// Oblique strikes (30-60 deg between strike and axis) are not in the table.
// They get the LESS favourable of the two classes they lie between (the
// perpendicular class for their dip and sense, and the parallel class for
// their dip), and are flagged `oblique`: the rating adjustment feeds a
// support design, where an optimistic class costs more than a pessimistic
// one, and a geologist who knows better overrides it with the angle in hand.
//
// Every classification carries its margin: degrees to the nearest boundary
// across which the class would change (strike angle 30 / 60, dip 20 / 45,
// and for steep joints whose class depends on the sense, the distance of the
// dip from 90 where "with" and "against" swap).
#include <string>

#include <Eigen/Core>

#include "core/geometry/orientation.h"

namespace rockface::tunnel {

enum class DriveClass { very_favourable, favourable, fair, unfavourable, very_unfavourable };

// "very favourable", ..., as the table words them.
const char* drive_class_words(DriveClass c);
// The RMR89 rating adjustment for tunnels: 0, -2, -5, -10, -12.
int drive_class_rmr_adjustment(DriveClass c);

enum class StrikeRelation { perpendicular, oblique, parallel, irrespective };

struct StrikeVsDrive {
  DriveClass cls = DriveClass::fair;
  std::string
      words;  // e.g. "strike perpendicular to the axis, drive with dip 45-90: very favourable"
  int rmr_adjustment = 0;
  StrikeRelation relation = StrikeRelation::irrespective;
  bool with_dip = true;           // the drive advances down the dip
  double strike_to_axis_deg = 0;  // [0, 90]: 0 = strike parallel to the axis
  double dip_deg = 0;
  double margin_deg = 0;  // to the nearest class boundary
  bool oblique = false;   // 30-60 deg: not in Bieniawski's table (see above)
  bool marginal = false;  // margin_deg <= the uncertainty given
};

// Plane orientation (radians, geometry's convention) against the drive's
// trend (radians, azimuth of the drive direction; Alignment::drive_trend_at).
// `uncertainty_deg` marks a class within that many degrees of a boundary as
// marginal.
StrikeVsDrive strike_vs_drive(const geometry::PlaneOrientation& plane, double drive_trend,
                              double uncertainty_deg = 5.0);
// The same from a plane's normal (either sense) and the drive's direction
// (any vector with a horizontal part; e.g. Alignment::tangent_at).
StrikeVsDrive strike_vs_drive(const Eigen::Vector3d& normal, const Eigen::Vector3d& drive,
                              double uncertainty_deg = 5.0);

}  // namespace rockface::tunnel
