#pragma once
// The viewpoint of the model view: orbits a target point at a distance,
// with the project's z axis up (yaw about z, pitch above the horizon), in a
// perspective projection. Screen coordinates are pixels of the view panel,
// origin top left, y down.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rockface::ui {

struct ScreenRay {
  Eigen::Vector3d origin, direction;  // unit direction, project frame
};

class OrbitCamera {
 public:
  // Looks at `centre` from along `view_from` (a direction, e.g. the mean
  // normal of the face) so that a sphere of `radius` fills the view.
  void frame(const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& view_from);
  void set_viewport(int width, int height);

  // One-finger drag (pixels): turn around the target.
  void orbit(float dx_px, float dy_px);
  // Two-finger move (pixels): slide the target in the view plane.
  void pan(float dx_px, float dy_px);
  // Pinch: factor > 1 brings the camera closer.
  void zoom(float factor);

  // For the shader, whose positions are relative to the centre given to
  // frame(): float then keeps millimetres on a site of hundreds of metres.
  Eigen::Matrix4f view_projection() const;
  // Where a project point appears; z > 1 or behind the camera: not visible.
  Eigen::Vector3d project(const Eigen::Vector3d& point) const;
  bool in_front(const Eigen::Vector3d& point) const;
  ScreenRay ray(float x_px, float y_px) const;
  Eigen::Vector3d eye() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Eigen::Matrix4d view() const;
  Eigen::Matrix4d projection() const;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero(), target_ = Eigen::Vector3d::Zero();
  double distance_ = 10, radius_ = 1;
  double yaw_ = 0, pitch_ = 0;  // radians: yaw from +y (north) towards +x, pitch up
  double fov_y_ = 0.8;          // radians (about 46 degrees, a normal lens)
  int width_ = 1, height_ = 1;
};

}  // namespace rockface::ui
