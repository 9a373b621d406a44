#include "core/photogrammetry/estimators/registration.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <sstream>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"

namespace rockface::photogrammetry {

Similarity levelled_camera_frame() {
  Similarity s;
  s.R << 1, 0, 0,  //
      0, 0, 1,     //
      0, -1, 0;
  return s;
}

Similarity range_pole_registration(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper,
                                   double length_m) {
  if (!(length_m > 0)) throw InputError("--range-pole", "the pole length must be > 0 m");
  const Eigen::Vector3d pole = upper - lower;
  if (pole.norm() < 1e-9)
    throw InputError("range pole", "the two targets triangulate to the same point");
  // Start from the levelled camera frame, then tilt the pole onto +z by the
  // smallest rotation: the heading of the optical axis is kept.
  const Similarity level = levelled_camera_frame();
  const Eigen::Vector3d pole_level = level.R * pole.normalized();
  if (pole_level.z() < 0.5)
    throw InputError("range pole",
                     "the pole leans more than 60 deg from the camera's vertical: the targets "
                     "are mismatched or the upper and lower target swapped");
  const Eigen::Matrix3d tilt =
      Eigen::Quaterniond::FromTwoVectors(pole_level, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Similarity s;
  s.scale = length_m / pole.norm();
  s.R = tilt * level.R;
  s.t = -s.scale * (s.R * lower);
  return s;
}

Similarity baseline_scale(double base_m, double model_base) {
  if (!(base_m > 0)) throw InputError("--baseline", "the base length must be > 0 m");
  Similarity s;
  s.scale = base_m / model_base;
  return s;
}

double horizontal_azimuth_deg(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d d = to - from;
  const double horizontal = d.head<2>().norm();
  // Below 1/20 of its length horizontally (87 deg steep), a centimetre of
  // picking error turns the bearing by tens of degrees.
  if (horizontal < 0.05 * d.norm() || horizontal == 0)
    throw InputError("--reference-line",
                     "the reference line is (nearly) vertical in the model: its bearing is "
                     "undefined; pick two points at about the same height");
  double az = rad_to_deg(std::atan2(d.x(), d.y()));
  if (az < 0) az += 360;
  return az;
}

Similarity north_rotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                          double compass_deg, double declination_deg,
                          const Eigen::Vector3d& pivot) {
  const double measured = horizontal_azimuth_deg(from, to);
  const double target = compass_deg + declination_deg;
  // Rotating by +a about +z (counter-clockwise seen from above) decreases a
  // bearing (clockwise from north) by a.
  const double angle = deg_to_rad(measured - target);
  Similarity s;
  s.R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.t = pivot - s.R * pivot;
  return s;
}

ControlPointRegistration register_to_control_points(const std::vector<Eigen::Vector3d>& model,
                                                    const std::vector<ControlPoint>& points,
                                                    const std::string& where) {
  const std::size_t n = points.size();
  if (n < 3 || model.size() != n)
    throw InputError(where, "need three or more control points, got " + std::to_string(n));
  ControlPointRegistration out;
  out.datum = Eigen::Vector3d::Zero();
  for (const auto& p : points) out.datum += p.world;
  out.datum /= static_cast<double>(n);

  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (std::size_t i = 0; i < n; ++i) {
    src.col(i) = model[i];
    dst.col(i) = points[i].world - out.datum;
  }
  // Collinear (or coincident) points leave the rotation about their line free.
  const Eigen::Matrix3Xd centred = dst.colwise() - dst.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(centred);
  const Eigen::Vector3d sv = svd.singularValues();
  if (sv(1) < 1e-3 * sv(0) || sv(0) == 0)
    throw InputError(where,
                     "the control points are collinear: the rotation about their line is "
                     "undefined; use three points that span a triangle");
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, true);
  const Eigen::Matrix3d sR = T.topLeftCorner<3, 3>();
  out.transform.scale = std::cbrt(sR.determinant());
  out.transform.R = sR / out.transform.scale;
  out.transform.t = T.topRightCorner<3, 1>();

  double sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ControlPointResidual r;
    r.id = points[i].id;
    r.residual = out.transform.apply(model[i]) - dst.col(i);
    r.distance = r.residual.norm();
    sum2 += r.distance * r.distance;
    if (r.distance >= out.worst_m) {
      out.worst_m = r.distance;
      out.worst_id = r.id;
    }
    out.residuals.push_back(r);
  }
  out.rms_m = std::sqrt(sum2 / static_cast<double>(n));
  return out;
}

std::string control_points_summary(const ControlPointRegistration& r) {
  const auto on_target = std::count_if(r.residuals.begin(), r.residuals.end(),
                                       [](const ControlPointResidual& p) { return p.on_target; });
  return std::to_string(on_target) + " of " + std::to_string(r.residuals.size()) +
         " measured on their targets, rms " + format_fixed(1000 * r.rms_m, 1) + " mm, worst " +
         r.worst_id + " (" + format_fixed(1000 * r.worst_m, 1) + " mm)";
}

std::vector<ControlPoint> parse_control_points(std::istream& in, const std::string& where) {
  std::vector<ControlPoint> out;
  std::string line;
  int number = 0;
  bool first_line = true;  // of those not blank or comments: may be a header
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(field);
    const std::string at = where + " line " + std::to_string(number);
    if (fields.size() != 6)
      throw InputError(at, "expected 6 fields id,u,v,X,Y,Z, got " + std::to_string(fields.size()));
    ControlPoint p;
    p.id = fields[0];
    p.id.erase(0, p.id.find_first_not_of(" \t"));
    p.id.erase(p.id.find_last_not_of(" \t") + 1);
    double v[5];
    bool numeric = true;
    for (int i = 0; i < 5; ++i) {
      try {
        std::size_t used = 0;
        v[i] = std::stod(fields[i + 1], &used);
        if (fields[i + 1].find_first_not_of(" \t", used) != std::string::npos) numeric = false;
      } catch (const std::exception&) {
        numeric = false;
      }
      if (!numeric) break;
      if (!std::isfinite(v[i])) numeric = false;
    }
    if (!numeric) {
      if (first_line) {  // a header line, after comments or not
        first_line = false;
        continue;
      }
      throw InputError(at, "u, v, X, Y, Z must be numbers");
    }
    first_line = false;
    p.pixel = {v[0], v[1]};
    p.world = {v[2], v[3], v[4]};
    for (const auto& q : out)
      if (q.id == p.id) throw InputError(at, "control point id '" + p.id + "' appears twice");
    out.push_back(p);
  }
  return out;
}

}  // namespace rockface::photogrammetry
