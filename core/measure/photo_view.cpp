#include "core/measure/photo_view.h"

#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>

#include "core/common/error.h"
#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::measure {

namespace {

std::string pixel_text(const Eigen::Vector2d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
}

}  // namespace

bool pixel_in_image(const PhotoView& view, const Eigen::Vector2d& pixel) {
  return std::isfinite(pixel.x()) && std::isfinite(pixel.y()) && pixel.x() >= -0.5 &&
         pixel.y() >= -0.5 && pixel.x() <= view.camera.width - 0.5 &&
         pixel.y() <= view.camera.height - 0.5;
}

Ray ray_through_pixel(const PhotoView& view, const Eigen::Vector2d& pixel,
                      const std::string& where) {
  if (!std::isfinite(pixel.x()) || !std::isfinite(pixel.y()))
    throw InputError(where, "pixel is not a number");
  if (!pixel_in_image(view, pixel))
    throw InputError(where, "pixel " + pixel_text(pixel) + " is outside the " + view.name +
                                " image (" + std::to_string(view.camera.width) + "x" +
                                std::to_string(view.camera.height) + " px)");
  const Eigen::Vector2d xy = photogrammetry::undistort_to_normalised({pixel}, view.camera)[0];
  Ray ray;
  ray.origin = view.pose.centre;
  ray.direction = (view.pose.R.transpose() * Eigen::Vector3d(xy.x(), xy.y(), 1.0)).normalized();
  return ray;
}

std::vector<Eigen::Vector2d> project_to_view(const PhotoView& view,
                                             const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> cam(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) cam[i] = view.pose.to_camera(points[i]);
  std::vector<Eigen::Vector2d> px = photogrammetry::project(cam, view.camera);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < px.size(); ++i)
    if (cam[i].z() <= 0) px[i] = {nan, nan};
  return px;
}

PhotoView left_view(const photogrammetry::Similarity& model_to_world,
                    const photogrammetry::CameraIntrinsics& left) {
  // x_world = s R x_model + t and the model frame is the left camera's, so
  // the camera sits at t looking along R's columns.
  PhotoView v;
  v.name = "left";
  v.camera = left;
  v.pose.R = model_to_world.R.transpose();
  v.pose.centre = model_to_world.t;
  return v;
}

PhotoView right_view(const photogrammetry::Similarity& model_to_world, const Eigen::Matrix3d& R_rel,
                     const Eigen::Vector3d& t_rel, const photogrammetry::CameraIntrinsics& right) {
  PhotoView v;
  v.name = "right";
  v.camera = right;
  v.pose.R = R_rel * model_to_world.R.transpose();
  v.pose.centre = model_to_world.apply(-R_rel.transpose() * t_rel);
  return v;
}

PhotoView left_view_from_lattice(const photogrammetry::SurfaceMesh& mesh,
                                 const photogrammetry::CameraIntrinsics& left) {
  if (mesh.pixels.size() != mesh.vertices.size() || mesh.vertices.size() < 6)
    throw InputError("mesh",
                     "the 3D image has no pixel of the left photograph per vertex (texture "
                     "coordinates), so the photograph's pose cannot be recovered");
  // A few thousand well-spread pairs determine the pose far below a pixel.
  const std::size_t wanted = 4000;
  const std::size_t stride = std::max<std::size_t>(1, mesh.vertices.size() / wanted);
  const Eigen::Vector3d origin = mesh.vertices[mesh.vertices.size() / 2];
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (std::size_t i = 0; i < mesh.vertices.size(); i += stride) {
    const Eigen::Vector3d p = mesh.vertices[i] - origin;  // small numbers for solvePnP
    object.emplace_back(p.x(), p.y(), p.z());
    image.emplace_back(mesh.pixels[i].x(), mesh.pixels[i].y());
  }
  cv::Mat rvec, tvec;
  const cv::Matx33d K = photogrammetry::camera_matrix(left);
  const cv::Mat dist = photogrammetry::distortion_vector(left);
  bool ok = cv::solvePnP(object, image, K, dist, rvec, tvec, false, cv::SOLVEPNP_EPNP);
  ok = ok && cv::solvePnP(object, image, K, dist, rvec, tvec, true, cv::SOLVEPNP_ITERATIVE);
  if (!ok)
    throw InputError("mesh",
                     "the pose of the left photograph cannot be recovered from the 3D "
                     "image (are the camera and the model from the same capture?)");
  cv::Matx33d R;
  cv::Rodrigues(rvec, R);
  PhotoView v;
  v.name = "left";
  v.camera = left;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v.pose.R(i, j) = R(i, j);
  const Eigen::Vector3d t(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  v.pose.centre = origin - v.pose.R.transpose() * t;
  return v;
}

}  // namespace rockface::measure
