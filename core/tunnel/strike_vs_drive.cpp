#include "core/tunnel/strike_vs_drive.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/degrees_per_radian.h"
#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::tunnel {

namespace {

// How far past a boundary the class is probed (degrees): far below any
// measurement's resolution, far above rounding.
constexpr double kProbeDeg = 1e-6;

StrikeRelation relation_of(double angle_deg, double dip_deg) {
  if (dip_deg < 20) return StrikeRelation::irrespective;
  if (angle_deg >= 60) return StrikeRelation::perpendicular;
  if (angle_deg <= 30) return StrikeRelation::parallel;
  return StrikeRelation::oblique;
}

DriveClass perpendicular_class(double dip_deg, bool with_dip) {
  if (with_dip) return dip_deg >= 45 ? DriveClass::very_favourable : DriveClass::favourable;
  return dip_deg >= 45 ? DriveClass::fair : DriveClass::unfavourable;
}

DriveClass parallel_class(double dip_deg) {
  return dip_deg >= 45 ? DriveClass::very_unfavourable : DriveClass::fair;
}

DriveClass class_of(double angle_deg, double dip_deg, bool with_dip) {
  switch (relation_of(angle_deg, dip_deg)) {
    case StrikeRelation::irrespective:
      return DriveClass::fair;
    case StrikeRelation::perpendicular:
      return perpendicular_class(dip_deg, with_dip);
    case StrikeRelation::parallel:
      return parallel_class(dip_deg);
    case StrikeRelation::oblique:
      // The less favourable of its two neighbours (see the header).
      return std::max(perpendicular_class(dip_deg, with_dip), parallel_class(dip_deg));
  }
  return DriveClass::fair;
}

std::string band(double dip_deg) {
  return dip_deg >= 45 ? "dip 45-90" : "dip 20-45";
}

}  // namespace

const char* drive_class_words(DriveClass c) {
  switch (c) {
    case DriveClass::very_favourable:
      return "very favourable";
    case DriveClass::favourable:
      return "favourable";
    case DriveClass::fair:
      return "fair";
    case DriveClass::unfavourable:
      return "unfavourable";
    case DriveClass::very_unfavourable:
      return "very unfavourable";
  }
  return "fair";
}

int drive_class_rmr_adjustment(DriveClass c) {
  switch (c) {
    case DriveClass::very_favourable:
      return 0;
    case DriveClass::favourable:
      return -2;
    case DriveClass::fair:
      return -5;
    case DriveClass::unfavourable:
      return -10;
    case DriveClass::very_unfavourable:
      return -12;
  }
  return -5;
}

StrikeVsDrive strike_vs_drive(const geometry::PlaneOrientation& plane, double drive_trend,
                              double uncertainty_deg) {
  if (!std::isfinite(plane.dip) || !std::isfinite(plane.dipdir) || plane.dip < 0 ||
      plane.dip > std::numbers::pi / 2 + 1e-12)
    throw InputError("plane", "dip must be in [0, 90] degrees and the dip direction finite");
  if (!std::isfinite(drive_trend)) throw InputError("drive_trend", "must be finite");
  StrikeVsDrive r;
  r.dip_deg = std::clamp(plane.dip * kDegPerRad, 0.0, 90.0);
  // Angle between the dip direction and the drive, in [0, 180].
  double delta = std::fmod(std::abs(plane.dipdir - drive_trend) * kDegPerRad, 360.0);
  if (delta > 180) delta = 360 - delta;
  r.with_dip = delta < 90;
  // The strike is normal to the dip direction.
  r.strike_to_axis_deg = 90 - std::min(delta, 180 - delta);
  r.relation = relation_of(r.strike_to_axis_deg, r.dip_deg);
  r.oblique = r.relation == StrikeRelation::oblique;
  r.cls = class_of(r.strike_to_axis_deg, r.dip_deg, r.with_dip);
  r.rmr_adjustment = drive_class_rmr_adjustment(r.cls);

  // Margin: the nearest boundary across which the class changes.
  const double a = r.strike_to_axis_deg, d = r.dip_deg;
  double margin = 90;
  auto probe = [&](double a2, double d2, bool w2, double distance) {
    if (class_of(a2, d2, w2) != r.cls) margin = std::min(margin, distance);
  };
  for (double b : {20.0, 45.0}) probe(a, d < b ? b : b - kProbeDeg, r.with_dip, std::abs(d - b));
  for (double b : {30.0, 60.0})
    probe(a <= b ? b + kProbeDeg : b - kProbeDeg, d, r.with_dip, std::abs(a - b));
  // Through the vertical the dip direction turns round: with becomes against.
  probe(a, d, !r.with_dip, 90 - d);
  // Strike parallel to the axis (a = 0): the sense swaps there too.
  probe(a, d, !r.with_dip, a);
  r.margin_deg = margin;
  r.marginal = margin <= uncertainty_deg;

  std::string text;
  const std::string sense = r.with_dip ? "drive with dip" : "drive against dip";
  switch (r.relation) {
    case StrikeRelation::irrespective:
      text = "dip 0-20, irrespective of strike";
      break;
    case StrikeRelation::perpendicular:
      text = "strike perpendicular to the axis, " + sense + ", " + band(d);
      break;
    case StrikeRelation::parallel:
      text = "strike parallel to the axis, " + band(d);
      break;
    case StrikeRelation::oblique:
      text = "strike oblique to the axis (" + format_fixed(a, 0) +
             " deg; taken as the less favourable of "
             "perpendicular, " +
             sense + ", and parallel), " + band(d);
      break;
  }
  r.words = text + ": " + drive_class_words(r.cls);
  return r;
}

StrikeVsDrive strike_vs_drive(const Eigen::Vector3d& normal, const Eigen::Vector3d& drive,
                              double uncertainty_deg) {
  if (!normal.allFinite() || normal.norm() == 0)
    throw InputError("normal", "must be a finite, non-zero vector");
  if (!drive.allFinite() || drive.head<2>().norm() == 0)
    throw InputError("drive", "must have a horizontal direction");
  double trend = std::atan2(drive.x(), drive.y());
  if (trend < 0) trend += 2 * std::numbers::pi;
  return strike_vs_drive(geometry::plane_orientation(normal), trend, uncertainty_deg);
}

}  // namespace rockface::tunnel
