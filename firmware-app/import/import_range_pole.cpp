#include "firmware-app/import/import_range_pole.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/common/error.h"

namespace rockface::app {

ImportPoleRegistration register_import_to_pole(const ImportPole& pole, double length_m,
                                               const std::optional<ImportCompassLine>& north,
                                               const photogrammetry::Similarity& camera_to_cloud) {
  // 50 m: no site's pole is longer; a typo (2000 for 2.000).
  if (!(length_m > 0 && length_m <= 50))
    throw InputError("--range-pole", "the pole length must be > 0 m and at most 50 m");
  const Eigen::Vector3d along = pole.upper - pole.lower;
  // 1e-9 of the targets' coordinates: the same point as far as doubles say.
  if (!(along.norm() > 1e-9 * std::max(1.0, pole.lower.norm())))
    throw InputError("--pole", "the lower and the upper target are the same point");
  // The cloud's frame seen from the virtual view's camera, then levelled as a
  // photographed visit's left camera is (x East-ish, the optical axis
  // North-ish, up Up), then tilted onto the pole by the smallest rotation.
  // Unlike a photograph's pole, no lean is refused: a local frame may be
  // turned any way, and the geologist said which target is the lower.
  const Eigen::Matrix3d cloud_to_level =
      photogrammetry::levelled_camera_frame().R * camera_to_cloud.R.transpose();
  const Eigen::Vector3d up_level = cloud_to_level * along.normalized();
  const Eigen::Matrix3d tilt =
      Eigen::Quaterniond::FromTwoVectors(up_level, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  ImportPoleRegistration out;
  out.transform.scale = length_m / along.norm();
  out.transform.R = tilt * cloud_to_level;
  out.transform.t = -out.transform.scale * (out.transform.R * pole.lower);
  if (north) {
    if (!(std::isfinite(north->azimuth_deg) && north->azimuth_deg >= 0 &&
          north->azimuth_deg <= 360))
      throw InputError("--azimuth", "a compass bearing is 0 to 360 degrees");
    if (!(std::abs(north->declination_deg) <= 90))
      throw InputError("--declination", "a declination is -90 to 90 degrees (east positive)");
    // About the vertical through the lower target (the origin), as a
    // photographed visit's north turns it.
    const photogrammetry::Similarity turn = photogrammetry::north_rotation(
        out.transform.apply(north->from), out.transform.apply(north->to), north->azimuth_deg,
        north->declination_deg);
    const Eigen::AngleAxisd a(turn.R);
    out.north_rotation_deg = a.angle() * 180 / M_PI * (a.axis().z() < 0 ? -1 : 1);
    out.transform = out.transform.then(turn);
  }
  return out;
}

}  // namespace rockface::app
