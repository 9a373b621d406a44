#include "ui/view3d/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace rockface::ui {

namespace {
// Pitch stops short of straight up/down so that the z-up view stays defined.
constexpr double kMaxPitch = 1.5;
// A drag across the whole panel width turns the model by about 180 degrees.
constexpr double kOrbitRadPerPanel = 3.1;
}  // namespace

void OrbitCamera::frame(const Eigen::Vector3d& centre, double radius,
                        const Eigen::Vector3d& view_from) {
  origin_ = target_ = centre;
  radius_ = std::max(radius, 1e-3);
  // The sphere's outline fills about 85 % of the panel height.
  distance_ = radius_ / std::tan(fov_y_ / 2) / 0.85;
  Eigen::Vector3d d = view_from.normalized();
  if (!d.allFinite()) d = -Eigen::Vector3d::UnitY();
  // The camera sits at target + distance * (cos p sin y, cos p cos y, sin p).
  yaw_ = std::atan2(d.x(), d.y());
  pitch_ = std::clamp(std::asin(std::clamp(d.z(), -1.0, 1.0)), -kMaxPitch, kMaxPitch);
}

void OrbitCamera::set_viewport(int width, int height) {
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
}

void OrbitCamera::orbit(float dx_px, float dy_px) {
  const double per_px = kOrbitRadPerPanel / width_;
  yaw_ -= dx_px * per_px;
  pitch_ = std::clamp(pitch_ + dy_px * per_px, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dx_px, float dy_px) {
  const Eigen::Matrix4d v = view();
  const Eigen::Vector3d right = v.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = v.block<1, 3>(1, 0).transpose();
  // Pixels to metres at the target's distance.
  const double metres_per_px = 2 * distance_ * std::tan(fov_y_ / 2) / height_;
  target_ += (-dx_px * right + dy_px * up) * metres_per_px;
}

void OrbitCamera::zoom(float factor) {
  if (factor <= 0) return;
  distance_ = std::clamp(distance_ / factor, radius_ * 0.02, radius_ * 50);
}

Eigen::Vector3d OrbitCamera::eye() const {
  const Eigen::Vector3d d(std::cos(pitch_) * std::sin(yaw_), std::cos(pitch_) * std::cos(yaw_),
                          std::sin(pitch_));
  return target_ + distance_ * d;
}

Eigen::Matrix4d OrbitCamera::view() const {
  const Eigen::Vector3d eye_pos = eye();
  const Eigen::Vector3d f = (target_ - eye_pos).normalized();
  Eigen::Vector3d s = f.cross(Eigen::Vector3d::UnitZ());
  if (s.norm() < 1e-9) s = Eigen::Vector3d::UnitX();
  s.normalize();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye_pos);
  m(1, 3) = -u.dot(eye_pos);
  m(2, 3) = f.dot(eye_pos);
  return m;
}

Eigen::Matrix4d OrbitCamera::projection() const {
  const double aspect = static_cast<double>(width_) / height_;
  const double near = std::max(distance_ - 4 * radius_, distance_ * 0.01);
  const double far = distance_ + 4 * radius_;
  const double f = 1 / std::tan(fov_y_ / 2);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far + near) / (near - far);
  p(2, 3) = 2 * far * near / (near - far);
  p(3, 2) = -1;
  return p;
}

Eigen::Matrix4f OrbitCamera::view_projection() const {
  Eigen::Matrix4d shift = Eigen::Matrix4d::Identity();
  shift.block<3, 1>(0, 3) = origin_;
  return (projection() * view() * shift).cast<float>();
}

Eigen::Vector3d OrbitCamera::project(const Eigen::Vector3d& point) const {
  const Eigen::Vector4d clip = projection() * view() * point.homogeneous();
  const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
  return {(ndc.x() + 1) / 2 * width_, (1 - ndc.y()) / 2 * height_, ndc.z()};
}

bool OrbitCamera::in_front(const Eigen::Vector3d& point) const {
  return (view() * point.homogeneous()).z() < 0;
}

ScreenRay OrbitCamera::ray(float x_px, float y_px) const {
  const Eigen::Matrix4d inverse = (projection() * view()).inverse();
  const double nx = 2.0 * x_px / width_ - 1, ny = 1 - 2.0 * y_px / height_;
  const Eigen::Vector4d near = inverse * Eigen::Vector4d(nx, ny, -1, 1);
  const Eigen::Vector4d far = inverse * Eigen::Vector4d(nx, ny, 1, 1);
  const Eigen::Vector3d a = near.head<3>() / near.w(), b = far.head<3>() / far.w();
  return {a, (b - a).normalized()};
}

}  // namespace rockface::ui
