#include "camera/synthetic_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

#include "camera/ray_patch_bins.h"
#include "camera/rock_texture.h"
#include "camera/sensor_effects.h"
#include "camera/tunnel_lighting.h"
#include "core/common/error.h"

namespace rockface::camera {

using Eigen::Vector2d;
using Eigen::Vector3d;
using photogrammetry::CameraIntrinsics;
using photogrammetry::CameraPose;

photogrammetry::CameraPose station_pose(const SyntheticStation& station, const std::string& where) {
  const Vector3d forward_raw = station.look_at - station.position;
  if (forward_raw.norm() < 1e-9)
    throw InputError(where,
                     "look_at is the station's own position; the camera must look somewhere");
  const Vector3d forward = forward_raw.normalized();
  const Vector3d right_raw = forward.cross(Vector3d::UnitZ());
  // Within 0.06 degrees of vertical the horizontal image axis is undefined.
  if (right_raw.norm() < 1e-3)
    throw InputError(where,
                     "looks straight up or down; without roll the image x-axis must be horizontal");
  const Vector3d right = right_raw.normalized();
  const Vector3d down = forward.cross(right);
  CameraPose pose;
  pose.R.row(0) = right.transpose();
  pose.R.row(1) = down.transpose();
  pose.R.row(2) = forward.transpose();
  pose.centre = station.position;
  return pose;
}

CameraIntrinsics rendered_intrinsics(const SyntheticScene& scene) {
  CameraIntrinsics c = scene.camera;
  if (!scene.effects.distortion) c.distortion = {};
  c.rms_px = 0;
  return c;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Luminance classes, tinted to colour at the end.
enum Material : uint8_t { kBackground = 0, kRock, kTarget, kPoleWhite, kPoleRed, kShotcrete };

struct JointOnPatch {
  Vector3d normal;
  double offset;            // normal . x = offset on the joint plane
  double in_surface_scale;  // distance in the patch plane = |normal . x - offset| * scale
};

struct PreparedPatch {
  std::string id;
  Vector3d normal;
  double offset = 0;
  Vector3d origin, eu, ev;  // in-plane frame
  std::vector<Vector2d> polygon;
  Vector2d lo, hi;  // bounding box in the plane frame
  std::vector<JointOnPatch> joints;
};

struct PreparedTarget {
  Vector3d centre, normal;
  double radius = 0;
};

struct PreparedScene {
  std::vector<PreparedPatch> patches;
  std::vector<PreparedTarget> targets;
  bool has_pole = false;
  Vector2d pole_xy;
  double pole_z0 = 0, pole_z1 = 0;
  Vector3d lamp;  // midpoint of the stations
  // Regions on the face (effects.wet, effects.shotcrete), in scene order.
  std::vector<PreparedRegion> wet, shotcrete;
};

bool inside_polygon(const std::vector<Vector2d>& poly, const Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vector2d& a = poly[i];
    const Vector2d& b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

PreparedPatch prepare_patch(const SyntheticPatch& patch, size_t index,
                            const std::vector<SyntheticJoint>& joints) {
  const std::string where = "surface.patches[" + std::to_string(index) + "]";
  if (patch.polygon.size() < 3) throw InputError(where, "a patch needs at least 3 points");
  // Newell's normal: robust for any simple polygon, convex or not.
  Vector3d n = Vector3d::Zero();
  Vector3d centroid = Vector3d::Zero();
  for (size_t i = 0; i < patch.polygon.size(); ++i) {
    const Vector3d& a = patch.polygon[i];
    const Vector3d& b = patch.polygon[(i + 1) % patch.polygon.size()];
    n += a.cross(b);
    centroid += a;
  }
  centroid /= static_cast<double>(patch.polygon.size());
  if (n.norm() < 1e-9) throw InputError(where, "the polygon has no area");
  PreparedPatch p;
  p.id = patch.id;
  p.normal = n.normalized();
  p.offset = p.normal.dot(centroid);
  p.origin = centroid;
  p.eu = (std::abs(p.normal.z()) < 0.9 ? Vector3d::UnitZ() : Vector3d::UnitX())
             .cross(p.normal)
             .normalized();
  p.ev = p.normal.cross(p.eu);
  p.lo = Vector2d::Constant(kInf);
  p.hi = Vector2d::Constant(-kInf);
  for (const auto& x : patch.polygon) {
    const Vector2d q((x - p.origin).dot(p.eu), (x - p.origin).dot(p.ev));
    p.polygon.push_back(q);
    p.lo = p.lo.cwiseMin(q);
    p.hi = p.hi.cwiseMax(q);
  }
  for (const auto& j : joints) {
    const Vector3d nj = j.normal.normalized();
    const double g = (nj - nj.dot(p.normal) * p.normal).norm();
    if (g < 1e-6) continue;  // joint parallel to the patch: no trace line
    p.joints.push_back({nj, nj.dot(j.point), 1.0 / g});
  }
  return p;
}

PreparedScene prepare(const SyntheticScene& scene) {
  PreparedScene s;
  for (size_t i = 0; i < scene.patches.size(); ++i)
    s.patches.push_back(prepare_patch(scene.patches[i], i, scene.joints));
  s.lamp = 0.5 * (scene.stations[0].position + scene.stations[1].position);
  for (std::size_t i = 0; i < scene.effects.wet.size(); ++i)
    s.wet.emplace_back(scene.effects.wet[i].region,
                       "imaging.effects.wet[" + std::to_string(i) + "].polygon");
  for (std::size_t i = 0; i < scene.effects.shotcrete.size(); ++i)
    s.shotcrete.emplace_back(scene.effects.shotcrete[i].region,
                             "imaging.effects.shotcrete[" + std::to_string(i) + "].polygon");
  if (scene.range_pole) {
    const auto& pole = *scene.range_pole;
    s.has_pole = true;
    s.pole_xy = pole.base.head<2>();
    s.pole_z0 = pole.base.z() - pole.target_diameter;
    s.pole_z1 = pole.base.z() + pole.length + pole.target_diameter / 2;
    for (const auto& t : range_pole_targets(scene))
      s.targets.push_back({t.centre, t.normal, pole.target_diameter / 2});
  }
  const Vector3d mid = 0.5 * (scene.stations[0].position + scene.stations[1].position);
  for (std::size_t k = 0; k < scene.control_targets.size(); ++k) {
    const auto& t = scene.control_targets[k];
    if ((mid - t.centre).norm() < 1e-6)
      throw InputError("imaging.control_targets[" + std::to_string(k) + "]",
                       "a target sits at the stations' midpoint");
    s.targets.push_back({t.centre, (mid - t.centre).normalized(), t.diameter / 2});
  }
  return s;
}

struct Hit {
  double t = kInf;
  Material material = kBackground;
  float luminance = 0.05f;
};

// Nearest surface or pole along the ray C + t d (d in world, camera z = 1).
struct Tracer {
  const PreparedScene& scene;
  RockTexture texture;
  double inv_focal;                           // 1 / fx: pixel footprint per metre of depth
  const SyntheticEffects* effects = nullptr;  // for wet and shotcrete regions
  const TunnelLights* lights = nullptr;       // flash, lamps; null: the default headlamp

  // `candidates`: the patches the ray can hit (RayPatchBins), in patch
  // order; nullptr tests every patch.
  double nearest_patch(const Vector3d& C, const Vector3d& d, int& which,
                       const std::vector<int>* candidates = nullptr) const {
    double best = kInf;
    which = -1;
    const size_t count = candidates ? candidates->size() : scene.patches.size();
    for (size_t i = 0; i < count; ++i) {
      const size_t k = candidates ? static_cast<size_t>((*candidates)[i]) : i;
      const PreparedPatch& p = scene.patches[k];
      const double denom = p.normal.dot(d);
      if (std::abs(denom) < 1e-12) continue;
      const double t = (p.offset - p.normal.dot(C)) / denom;
      if (t <= 1e-6 || t >= best) continue;
      const Vector3d q = C + t * d - p.origin;
      const Vector2d local(q.dot(p.eu), q.dot(p.ev));
      if (local.x() < p.lo.x() || local.y() < p.lo.y() || local.x() > p.hi.x() ||
          local.y() > p.hi.y())
        continue;
      if (!inside_polygon(p.polygon, local)) continue;
      best = t;
      which = static_cast<int>(k);
    }
    return best;
  }

  double pole(const Vector3d& C, const Vector3d& d, Vector3d& normal) const {
    if (!scene.has_pole) return kInf;
    const Vector2d o = C.head<2>() - scene.pole_xy;
    const Vector2d dd = d.head<2>();
    const double a = dd.squaredNorm();
    if (a < 1e-18) return kInf;
    const double b = o.dot(dd);
    const double r = SyntheticDrawing::kPoleRadius;
    const double disc = b * b - a * (o.squaredNorm() - r * r);
    if (disc < 0) return kInf;
    const double t = (-b - std::sqrt(disc)) / a;
    if (t <= 1e-6) return kInf;
    const double z = C.z() + t * d.z();
    if (z < scene.pole_z0 || z > scene.pole_z1) return kInf;
    normal = Vector3d(o.x() + t * dd.x(), o.y() + t * dd.y(), 0).normalized();
    return t;
  }

  Hit trace(const Vector3d& C, const Vector3d& d,
            const std::vector<int>* candidates = nullptr) const {
    Hit hit;
    const double dn = d.norm();
    int which = -1;
    const double t_patch = nearest_patch(C, d, which, candidates);
    // Targets are plates mounted on the pole: they win over the pole inside
    // their disk, and over a patch only when nearer.
    for (const auto& target : scene.targets) {
      const double denom = target.normal.dot(d);
      if (std::abs(denom) < 1e-12) continue;
      const double t = target.normal.dot(target.centre - C) / denom;
      if (t <= 1e-6 || t >= t_patch || t >= hit.t) continue;
      const double rho = (C + t * d - target.centre).norm();
      if (rho > target.radius) continue;
      const double cos_incidence = std::max(std::abs(denom) / dn, 0.1);
      const double footprint = t * dn * inv_focal / cos_incidence;
      const double white = std::clamp((target.radius / 2 - rho) / footprint + 0.5, 0.0, 1.0);
      hit.t = t;
      hit.material = kTarget;
      hit.luminance = static_cast<float>(0.06 + (0.92 - 0.06) * white);
      if (lights) {
        const Vector3d facing = denom < 0 ? target.normal : Vector3d(-target.normal);
        hit.luminance = static_cast<float>(hit.luminance * lights->diffuse(C + t * d, facing));
      }
    }
    if (hit.material == kTarget) return hit;
    Vector3d pole_normal = Vector3d::Zero();
    const double t_pole = pole(C, d, pole_normal);
    if (t_pole < t_patch) {
      const Vector3d q = C + t_pole * d;
      const auto band = static_cast<long long>(std::floor(q.z() / SyntheticDrawing::kPoleBand));
      hit.t = t_pole;
      hit.material = (band % 2 == 0) ? kPoleWhite : kPoleRed;
      const double lit = std::max(0.0, pole_normal.dot((scene.lamp - q).normalized()));
      hit.luminance =
          static_cast<float>((hit.material == kPoleWhite ? 0.85 : 0.6) *
                             (lights ? lights->diffuse(q, pole_normal) : 0.35 + 0.65 * lit));
      return hit;
    }
    if (which < 0) return hit;
    const PreparedPatch& p = scene.patches[which];
    const Vector3d q = C + t_patch * d;
    const double cos_incidence = std::max(std::abs(p.normal.dot(d)) / dn, 0.1);
    const double footprint = t_patch * dn * inv_focal / cos_incidence;
    const Vector3d facing = p.normal.dot(d) < 0 ? p.normal : Vector3d(-p.normal);
    hit.t = t_patch;
    if (!scene.shotcrete.empty() || !scene.wet.empty() || lights)
      return lit_surface(hit, q, facing, -d / dn, footprint, p);
    double lum = texture.albedo(q, footprint);
    const double lit = std::max(0.0, facing.dot((scene.lamp - q).normalized()));
    lum *= 0.3 + 0.7 * lit;
    for (const auto& j : p.joints) {
      const double s = std::abs(j.normal.dot(q) - j.offset) * j.in_surface_scale;
      const double cover =
          std::clamp((SyntheticDrawing::kTraceWidth / 2 - s) / footprint + 0.5, 0.0, 1.0);
      lum *= 1.0 - 0.85 * cover;
    }
    hit.material = kRock;
    hit.luminance = static_cast<float>(lum);
    return hit;
  }

  // A surface hit under the tunnel's effects: shotcrete hides the texture
  // and the traces; wet rock is darker and has a specular lobe; the light
  // is the flash and lamps when asked, else the default headlamp.
  Hit lit_surface(Hit hit, const Vector3d& q, const Vector3d& facing, const Vector3d& to_camera,
                  double footprint, const PreparedPatch& p) const {
    const double light = lights
                             ? lights->diffuse(q, facing)
                             : 0.3 + 0.7 * std::max(0.0, facing.dot((scene.lamp - q).normalized()));
    for (std::size_t k = 0; k < scene.shotcrete.size(); ++k)
      if (scene.shotcrete[k].contains(q)) {
        // Sprayed concrete is even: a grain of +-5 % (the texture's fine
        // octaves at a tenth of the rock's contrast), no joints.
        const double grain = 1.0 + 0.1 * (texture.albedo(q * 7.0, footprint * 7.0) - 0.5);
        hit.material = kShotcrete;
        hit.luminance = static_cast<float>(effects->shotcrete[k].albedo * grain * light);
        return hit;
      }
    double lum = texture.albedo(q, footprint);
    const SyntheticWet* wet = nullptr;
    for (std::size_t k = 0; k < scene.wet.size() && !wet; ++k)
      if (scene.wet[k].contains(q)) wet = &effects->wet[k];
    if (wet) lum *= wet->darkening;
    lum *= light;
    for (const auto& j : p.joints) {
      const double s = std::abs(j.normal.dot(q) - j.offset) * j.in_surface_scale;
      const double cover =
          std::clamp((SyntheticDrawing::kTraceWidth / 2 - s) / footprint + 0.5, 0.0, 1.0);
      lum *= 1.0 - 0.85 * cover;
    }
    if (wet) {
      // The water film follows the rock's relief, so the lobe breaks into
      // glints: the normal tilted by the texture's slope over 1 cm (a
      // relief of a few millimetres per centimetre, as on a blasted face).
      const double h = 0.01, relief = 3.0;
      const double su =
          texture.albedo(q + h * p.eu, footprint) - texture.albedo(q - h * p.eu, footprint);
      const double sv =
          texture.albedo(q + h * p.ev, footprint) - texture.albedo(q - h * p.ev, footprint);
      const Vector3d n = (facing - relief * (su * p.eu + sv * p.ev)).normalized();
      // The film reflects on top of the traces too.
      lum +=
          wet->specular * (lights ? lights->specular(q, n, to_camera, wet->shininess)
                                  : headlamp_specular(q, n, to_camera, scene.lamp, wet->shininess));
    }
    hit.material = kRock;
    hit.luminance = static_cast<float>(lum);
    return hit;
  }
};

// Fixed-point iterations that bring the undistortion of every pixel to
// 1e-10 of its distortion: the iteration contracts by about the derivative
// of the distortion at the image corner, q = |3 k1| r^2 + |5 k2| r^4 +
// |7 k3| r^6 + 6 (|p1| + |p2|) r.
int undistort_iterations(const CameraIntrinsics& cam) {
  const double xr = std::max(cam.cx, cam.width - 1 - cam.cx) / cam.fx;
  const double yr = std::max(cam.cy, cam.height - 1 - cam.cy) / cam.fy;
  const double r2 = xr * xr + yr * yr, r = std::sqrt(r2);
  const auto& d = cam.distortion;
  const double q = std::abs(3 * d[0]) * r2 + std::abs(5 * d[1]) * r2 * r2 +
                   std::abs(7 * d[4]) * r2 * r2 * r2 + 6 * (std::abs(d[2]) + std::abs(d[3])) * r;
  if (q >= 0.9) return 100;
  return std::clamp(static_cast<int>(std::ceil(std::log(1e-10) / std::log(q))), 3, 100);
}

// Normalised image coordinates of the pixel centres of one row.
void row_rays(int v, const CameraIntrinsics& cam, const cv::Matx33d& K, const cv::Mat& dist,
              int iterations, std::vector<cv::Point2d>& pixels,
              std::vector<cv::Point2d>& normalised) {
  pixels.resize(cam.width);
  for (int u = 0; u < cam.width; ++u) pixels[u] = {static_cast<double>(u), static_cast<double>(v)};
  if (!cam.has_distortion()) {
    normalised.resize(cam.width);
    for (int u = 0; u < cam.width; ++u)
      normalised[u] = {(u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy};
    return;
  }
  cv::undistortPoints(pixels, normalised, K, dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT, iterations, 0));
}

cv::Matx33d camera_matrix_of(const CameraIntrinsics& c) {
  return {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
}

cv::Mat dist_of(const CameraIntrinsics& c) {
  cv::Mat d(1, 5, CV_64F);
  for (int k = 0; k < 5; ++k) d.at<double>(k) = c.distortion[k];
  return d;
}

// Projects world points with pose and camera (distortion included).
std::vector<Vector2d> project(const std::vector<Vector3d>& world, const CameraPose& pose,
                              const CameraIntrinsics& cam) {
  if (world.empty()) return {};
  std::vector<cv::Point3d> in;
  for (const auto& x : world) {
    const Vector3d c = pose.to_camera(x);
    in.emplace_back(c.x(), c.y(), c.z());
  }
  std::vector<cv::Point2d> out;
  const cv::Vec3d zero(0, 0, 0);
  cv::projectPoints(in, zero, zero, camera_matrix_of(cam), dist_of(cam), out);
  std::vector<Vector2d> result;
  for (const auto& p : out) result.emplace_back(p.x, p.y);
  return result;
}

}  // namespace

std::vector<TargetTruth> range_pole_targets(const SyntheticScene& scene) {
  std::vector<TargetTruth> targets;
  if (!scene.range_pole) return targets;
  const auto& pole = *scene.range_pole;
  const Vector3d mid = 0.5 * (scene.stations[0].position + scene.stations[1].position);
  for (double up : {0.0, pole.length}) {
    TargetTruth t;
    t.centre = pole.base + Vector3d(0, 0, up);
    const Vector3d towards = mid - t.centre;
    if (towards.norm() < 1e-6)
      throw InputError("imaging.range_pole", "a target sits at the stations' midpoint");
    t.normal = towards.normalized();
    targets.push_back(t);
  }
  return targets;
}

SyntheticView render_view(const SyntheticScene& scene, int station, const CameraIntrinsics& cam,
                          bool with_depth, Progress& progress) {
  if (cam.width <= 0 || cam.height <= 0 || !(cam.fx > 0) || !(cam.fy > 0))
    throw InputError("imaging.camera", "width, height, fx and fy must be positive");
  const PreparedScene prepared = prepare(scene);
  SyntheticView view;
  view.pose =
      station_pose(scene.stations[station], "imaging.stations[" + std::to_string(station) + "]");
  const SyntheticEffects& fx = scene.effects;
  const TunnelLights lights(fx, scene.stations[station]);
  const Tracer tracer{prepared, RockTexture(scene.texture_seed), 1.0 / cam.fx, &fx,
                      fx.tunnel_lit() ? &lights : nullptr};
  const cv::Matx33d K = camera_matrix_of(cam);
  const cv::Mat dist = dist_of(cam);
  const int iterations = undistort_iterations(cam);
  const Eigen::Matrix3d Rt = view.pose.R.transpose();
  const Vector3d C = view.pose.centre;
  // The rays' window in normalised coordinates: the image corners, widened
  // by a quarter for distortion (a ray outside it tests every patch).
  const Eigen::Vector2d corner_lo(-cam.cx / cam.fx, -cam.cy / cam.fy);
  const Eigen::Vector2d corner_hi((cam.width - cam.cx) / cam.fx, (cam.height - cam.cy) / cam.fy);
  const Eigen::Vector2d widen = 0.25 * (corner_hi - corner_lo);
  std::vector<std::vector<Vector3d>> polygons;
  polygons.reserve(scene.patches.size());
  for (const auto& p : scene.patches) polygons.push_back(p.polygon);
  const RayPatchBins bins(polygons, view.pose, corner_lo - widen, corner_hi + widen);

  cv::Mat luminance(cam.height, cam.width, CV_32F);
  cv::Mat airlight;  // the dust's veil, of full white (effects.dust only)
  if (fx.dust) airlight.create(cam.height, cam.width, CV_32F);
  cv::Mat material(cam.height, cam.width, CV_8U);
  if (with_depth) view.depth.create(cam.height, cam.width, CV_32F);
  const char* stage = station == 0 ? "rendering left image" : "rendering right image";
  // Bands of rows in parallel; between bands the caller may cancel.
  const int band = 64;
  for (int v0 = 0; v0 < cam.height; v0 += band) {
    const int v1 = std::min(cam.height, v0 + band);
    cv::parallel_for_(cv::Range(v0, v1), [&](const cv::Range& rows) {
      std::vector<cv::Point2d> pixels, normalised;
      for (int v = rows.start; v < rows.end; ++v) {
        row_rays(v, cam, K, dist, iterations, pixels, normalised);
        auto* lum = luminance.ptr<float>(v);
        auto* mat = material.ptr<uint8_t>(v);
        float* depth = with_depth ? view.depth.ptr<float>(v) : nullptr;
        float* veil = fx.dust ? airlight.ptr<float>(v) : nullptr;
        for (int u = 0; u < cam.width; ++u) {
          const Vector3d d = Rt * Vector3d(normalised[u].x, normalised[u].y, 1.0);
          const Hit hit = tracer.trace(C, d, bins.candidates(normalised[u].x, normalised[u].y));
          lum[u] = hit.luminance;
          // Dust between the camera and what was hit (nothing hit: the
          // haze all the way): the surface's radiance attenuated, and the
          // airlight (neutral grey, not the surface's colour) added apart.
          if (fx.dust) {
            const double t = hit.material == kBackground
                                 ? 0.0
                                 : std::exp(-fx.dust->beta_per_m * hit.t * d.norm());
            lum[u] = static_cast<float>(lum[u] * t);
            veil[u] = static_cast<float>(fx.dust->airlight * (1 - t));
          }
          // The lens's fall-off toward the corners, on both.
          if (fx.vignetting) {
            const double f = vignetting_factor(normalised[u].x, normalised[u].y, *fx.vignetting);
            lum[u] = static_cast<float>(lum[u] * f);
            if (veil) veil[u] = static_cast<float>(veil[u] * f);
          }
          mat[u] = hit.material;
          if (depth) depth[u] = hit.material == kBackground ? 0.f : static_cast<float>(hit.t);
        }
      }
    });
    progress.step(stage, static_cast<double>(v1) / cam.height);
  }

  if (scene.effects.blur_px > 0) {
    cv::GaussianBlur(luminance, luminance, cv::Size(0, 0), scene.effects.blur_px, 0,
                     cv::BORDER_REFLECT);
    if (fx.dust)
      cv::GaussianBlur(airlight, airlight, cv::Size(0, 0), scene.effects.blur_px, 0,
                       cv::BORDER_REFLECT);
  }

  // Colour per material (B, G, R): brownish-grey rock, neutral targets, a
  // red and white pole, a dark background.
  static const float tint[6][3] = {
      {1.0f, 1.0f, 1.0f}, {0.82f, 0.92f, 1.0f}, {1.0f, 1.0f, 1.0f},
      {1.0f, 1.0f, 1.0f}, {0.25f, 0.25f, 1.0f}, {0.9f, 0.95f, 0.97f}};  // shotcrete: cement grey
  view.image.create(cam.height, cam.width, CV_8UC3);
  const float gain = static_cast<float>(255.0 * scene.effects.exposure);
  const double sigma = scene.effects.noise_sigma;
  // One generator walked in pixel order: the same noise on every run.
  cv::RNG rng(0x5EED0000ULL + 2ULL * scene.texture_seed + static_cast<uint64_t>(station));
  // The sensor's own generator, so that asking for it leaves noise_sigma's
  // sequence as it was.
  const std::optional<SensorNoise> sensor =
      fx.sensor ? std::optional<SensorNoise>(SensorNoise(*fx.sensor)) : std::nullopt;
  cv::RNG sensor_rng(0xC0FFEE00ULL + 2ULL * (fx.sensor ? fx.sensor->seed : 0) +
                     static_cast<uint64_t>(station));
  for (int v = 0; v < cam.height; ++v) {
    const float* lum = luminance.ptr<float>(v);
    const uint8_t* mat = material.ptr<uint8_t>(v);
    const float* veil = fx.dust ? airlight.ptr<float>(v) : nullptr;
    auto* out = view.image.ptr<cv::Vec3b>(v);
    for (int u = 0; u < cam.width; ++u)
      for (int c = 0; c < 3; ++c) {
        double value = tint[mat[u]][c] * lum[u] * gain;
        if (veil) value += veil[u] * gain;
        if (sensor) value = sensor->apply(value, sensor_rng);
        if (sigma > 0) value += rng.gaussian(sigma);
        out[u][c] = cv::saturate_cast<uint8_t>(value);
      }
  }
  if (fx.jpeg_quality) view.image = jpeg_round_trip(view.image, *fx.jpeg_quality);
  return view;
}

namespace {

// Where each joint cuts each patch, whole.
std::vector<TraceSegment> traces_on_patches(const SyntheticScene& scene) {
  std::vector<TraceSegment> segments;
  for (const auto& joint : scene.joints) {
    const Vector3d nj = joint.normal.normalized();
    for (const auto& patch : scene.patches) {
      const auto& poly = patch.polygon;
      if (poly.size() < 3) continue;
      Vector3d normal = Vector3d::Zero();
      for (size_t i = 0; i < poly.size(); ++i) normal += poly[i].cross(poly[(i + 1) % poly.size()]);
      const Vector3d direction = normal.normalized().cross(nj);
      if (direction.norm() < 1e-6) continue;  // joint parallel to the patch: no trace line
      // Crossings of the joint plane with the polygon's edges, ordered along
      // the trace line and paired inside / outside (even-odd rule).
      std::vector<std::pair<double, Vector3d>> crossings;
      for (size_t i = 0; i < poly.size(); ++i) {
        const Vector3d& a = poly[i];
        const Vector3d& b = poly[(i + 1) % poly.size()];
        const double da = nj.dot(a - joint.point), db = nj.dot(b - joint.point);
        // Half-open test so a vertex on the plane is counted once.
        if ((da < 0) == (db < 0)) continue;
        const Vector3d x = a + (b - a) * (da / (da - db));
        crossings.emplace_back(direction.dot(x), x);
      }
      std::sort(crossings.begin(), crossings.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (size_t i = 0; i + 1 < crossings.size(); i += 2)
        segments.push_back({joint.id, patch.id, {crossings[i].second, crossings[i + 1].second}});
    }
  }
  return segments;
}

}  // namespace

std::vector<TraceSegment> true_trace_segments(const SyntheticScene& scene) {
  std::vector<TraceSegment> segments = traces_on_patches(scene);
  // Shotcrete hides the rock: no trace is seen (or drawn) under it.
  for (std::size_t i = 0; i < scene.effects.shotcrete.size(); ++i) {
    const PreparedRegion region(scene.effects.shotcrete[i].region,
                                "imaging.effects.shotcrete[" + std::to_string(i) + "].polygon");
    std::vector<TraceSegment> kept;
    for (const auto& seg : segments)
      for (const auto& piece : region.outside(seg.world[0], seg.world[1]))
        kept.push_back({seg.joint, seg.patch, piece});
    segments = std::move(kept);
  }
  return segments;
}

SyntheticRender render_scene(const SyntheticScene& scene, Progress& progress) {
  SyntheticRender r;
  r.intrinsics = rendered_intrinsics(scene);
  for (int s = 0; s < 2; ++s) {
    SyntheticView view = render_view(scene, s, r.intrinsics, s == 0, progress);
    r.images[s] = std::move(view.image);
    r.poses[s] = view.pose;
    if (s == 0) r.depth_left = std::move(view.depth);
  }

  const PreparedScene prepared = prepare(scene);
  const Tracer tracer{prepared, RockTexture(scene.texture_seed), 1.0 / r.intrinsics.fx};
  r.targets = range_pole_targets(scene);
  for (auto& target : r.targets)
    for (int s = 0; s < 2; ++s) {
      target.image[s] = project({target.centre}, r.poses[s], r.intrinsics)[0];
      const Vector2d& p = target.image[s];
      const bool in_image = r.poses[s].to_camera(target.centre).z() > 0 && p.x() >= -0.5 &&
                            p.y() >= -0.5 && p.x() <= r.intrinsics.width - 0.5 &&
                            p.y() <= r.intrinsics.height - 0.5;
      // Hidden when a patch lies in front of the centre along the ray.
      const Vector3d d = target.centre - r.poses[s].centre;
      int which = -1;
      const double t_patch = tracer.nearest_patch(r.poses[s].centre, d, which);
      target.visible[s] = in_image && !(t_patch < 1.0);
    }

  if (scene.reference_line) {
    const auto ends = project({scene.reference_line->first, scene.reference_line->second},
                              r.poses[0], r.intrinsics);
    r.reference_line_left = std::array<Vector2d, 2>{ends[0], ends[1]};
  }

  for (const TraceSegment& segment : true_trace_segments(scene)) {
    TraceTruth trace;
    trace.joint = segment.joint;
    trace.patch = segment.patch;
    trace.world = segment.world;
    // Sampled about every 4 px so the distorted image curve is followed.
    const Vector3d c0 = r.poses[0].to_camera(trace.world[0]);
    const Vector3d c1 = r.poses[0].to_camera(trace.world[1]);
    const double zmin = std::max(std::min(c0.z(), c1.z()), 1e-3);
    const double length_px = (trace.world[1] - trace.world[0]).norm() * r.intrinsics.fx / zmin;
    const int n = std::clamp(static_cast<int>(length_px / 4.0) + 2, 2, 4000);
    std::vector<Vector3d> samples;
    for (int j = 0; j < n; ++j) {
      const Vector3d x = trace.world[0] + (trace.world[1] - trace.world[0]) * (j / (n - 1.0));
      if (r.poses[0].to_camera(x).z() > 1e-3) samples.push_back(x);
    }
    trace.left_image = project(samples, r.poses[0], r.intrinsics);
    r.traces.push_back(std::move(trace));
  }
  return r;
}

std::vector<std::string> SyntheticEffects::simulated() const {
  std::vector<std::string> out;
  if (distortion) out.push_back("distortion");
  if (noise_sigma > 0) out.push_back("noise_sigma");
  if (blur_px > 0) out.push_back("blur_px");
  if (exposure != 1.0) out.push_back("exposure");
  if (flash) out.push_back("flash");
  if (!lamps.empty()) out.push_back("lamps");
  if (vignetting) out.push_back("vignetting");
  if (sensor) out.push_back("sensor");
  if (jpeg_quality) out.push_back("jpeg_quality");
  if (!wet.empty()) out.push_back("wet");
  if (!shotcrete.empty()) out.push_back("shotcrete");
  if (dust) out.push_back("dust");
  return out;
}

}  // namespace rockface::camera
