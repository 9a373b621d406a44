#include "core/photogrammetry/estimators/triangulation.h"

#include <cmath>

#include "core/photogrammetry/camera/camera_cv.h"

namespace rockface::photogrammetry {

SurfaceMesh triangulate_lattice(const DisparityMap& disparity, const Rectification& rect,
                                const cv::Mat& rectified_left, const CameraIntrinsics& left,
                                const LatticeOptions& options, Progress& progress) {
  const cv::Mat& D = disparity.disparity;
  const int step = std::max(1, options.step);
  const int cols = (D.cols + step - 1) / step, rows = (D.rows + step - 1) / step;
  Eigen::Matrix4d Q;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) Q(i, j) = rect.Q(i, j);
  Eigen::Matrix3d R1t;  // rectified frame -> left camera frame
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R1t(i, j) = rect.R1(j, i);

  SurfaceMesh mesh;
  mesh.texture_width = left.width;
  mesh.texture_height = left.height;
  std::vector<int> index(static_cast<std::size_t>(cols) * rows, -1);
  const bool colour = rectified_left.channels() == 3;
  for (int r = 0; r < rows; ++r) {
    if (r % 64 == 0) progress.step("triangulation", 0.8 * r / rows);
    const int y = r * step;
    const float* d = D.ptr<float>(y);
    for (int c = 0; c < cols; ++c) {
      const int x = c * step;
      if (std::isnan(d[x])) continue;
      const Eigen::Vector4d h = Q * Eigen::Vector4d(x, y, d[x], 1.0);
      if (std::abs(h.w()) < 1e-12) continue;
      const Eigen::Vector3d p = R1t * (h.head<3>() / h.w());
      if (p.z() <= 0 || p.norm() > options.max_depth_in_bases) continue;
      index[static_cast<std::size_t>(r) * cols + c] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(p);
      if (colour) {
        const cv::Vec3b bgr = rectified_left.at<cv::Vec3b>(y, x);
        mesh.colours.push_back({bgr[2], bgr[1], bgr[0]});
      } else {
        const std::uint8_t g = rectified_left.at<std::uint8_t>(y, x);
        mesh.colours.push_back({g, g, g});
      }
    }
  }

  progress.step("triangulation: texture coordinates", 0.8);
  // Projection in chunks keeps the temporary buffers small for big images.
  const std::size_t chunk = 1 << 16;
  mesh.pixels.reserve(mesh.vertices.size());
  mesh.texcoords.reserve(mesh.vertices.size());
  for (std::size_t begin = 0; begin < mesh.vertices.size(); begin += chunk) {
    const std::size_t end = std::min(mesh.vertices.size(), begin + chunk);
    const std::vector<Eigen::Vector3d> part(mesh.vertices.begin() + begin,
                                            mesh.vertices.begin() + end);
    for (const Eigen::Vector2d& px : project(part, left)) {
      mesh.pixels.push_back(px.cast<float>());
      mesh.texcoords.emplace_back(static_cast<float>((px.x() + 0.5) / left.width),
                                  static_cast<float>(1.0 - (px.y() + 0.5) / left.height));
    }
  }

  progress.step("triangulation: mesh", 0.9);
  const double max_jump = options.max_jump_px * step;
  auto disp_at = [&](int r, int c) { return D.at<float>(r * step, c * step); };
  auto add = [&](int r0, int c0, int r1, int c1, int r2, int c2) {
    const int a = index[static_cast<std::size_t>(r0) * cols + c0];
    const int b = index[static_cast<std::size_t>(r1) * cols + c1];
    const int c = index[static_cast<std::size_t>(r2) * cols + c2];
    if (a < 0 || b < 0 || c < 0) return;
    const float da = disp_at(r0, c0), db = disp_at(r1, c1), dc = disp_at(r2, c2);
    if (std::abs(da - db) > max_jump || std::abs(db - dc) > max_jump ||
        std::abs(da - dc) > max_jump)
      return;
    mesh.triangles.push_back({a, b, c});
  };
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      // Counter-clockwise seen from the camera (image y points down, so the
      // lattice order (c, r) -> (c, r+1) -> (c+1, r) faces the camera).
      add(r, c, r + 1, c, r, c + 1);
      add(r, c + 1, r + 1, c, r + 1, c + 1);
    }
  progress.step("triangulation", 1.0);
  return mesh;
}

}  // namespace rockface::photogrammetry
