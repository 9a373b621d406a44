#include "core/photogrammetry/surface/virtual_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/common/error.h"

namespace rockface::photogrammetry {

namespace virtual_view_detail {

// Background of the view where no surface was measured: a mid grey no rock
// photograph is uniformly, so that a hole reads as a hole.
const cv::Vec3b kHoleGrey(96, 96, 96);

cv::Vec3b sample_texture(const cv::Mat& texture, float u, float v) {
  const int x =
      std::clamp(static_cast<int>(u * static_cast<float>(texture.cols)), 0, texture.cols - 1);
  const int y =
      std::clamp(static_cast<int>(v * static_cast<float>(texture.rows)), 0, texture.rows - 1);
  return texture.at<cv::Vec3b>(y, x);
}

}  // namespace virtual_view_detail

VirtualView render_virtual_view(const VirtualViewInput& in, const VirtualViewOptions& options) {
  using namespace virtual_view_detail;
  const auto& V = *in.vertices;
  const auto& T = *in.triangles;
  if (V.empty() || T.empty()) throw InputError("3D image", "no triangles to draw");
  const bool has_colours = in.colours && in.colours->size() == V.size();
  const bool has_texture = !in.texture.empty() && in.texcoords && in.texcoords->size() == V.size();

  // The camera's axes: forward against `toward_viewer`, up as the world's up
  // seen in the view (north for a surface lying flat).
  const Eigen::Vector3d forward = -in.toward_viewer.normalized();
  Eigen::Vector3d up =
      std::abs(forward.z()) > 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  up = (up - up.dot(forward) * forward).normalized();
  const Eigen::Vector3d down = -up;
  const Eigen::Vector3d right = down.cross(forward);
  VirtualView out;
  out.pose.R.row(0) = right.transpose();
  out.pose.R.row(1) = down.transpose();
  out.pose.R.row(2) = forward.transpose();

  // The extent seen squarely, then the camera that far away.
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
  for (const auto& p : V) {
    const Eigen::Vector3d d = p - in.centre;
    lo_x = std::min(lo_x, d.dot(right)), hi_x = std::max(hi_x, d.dot(right));
    lo_y = std::min(lo_y, d.dot(down)), hi_y = std::max(hi_y, d.dot(down));
  }
  const double extent = std::max({hi_x - lo_x, hi_y - lo_y, 1e-6});
  double relief = 0;
  for (const auto& p : V) relief = std::max(relief, (p - in.centre).dot(in.toward_viewer));
  const double distance = options.distance_to_extent * extent + relief;
  out.pose.centre = in.centre + distance * in.toward_viewer;
  // The pixel at the surface's plane about the point spacing, within the
  // sizes the options allow.
  double pixel = in.point_spacing > 0 ? in.point_spacing : extent / 1000;
  const double long_side = extent / pixel;
  if (long_side > options.max_side_px) pixel = extent / options.max_side_px;
  if (long_side < options.min_side_px) pixel = extent / options.min_side_px;
  // Near points are drawn larger than the plane's: the margin keeps them in.
  const double near_scale = distance / std::max(distance - relief, 1e-6);
  const double f = distance / pixel;
  auto& K = out.intrinsics;
  K.fx = K.fy = f;
  K.width = static_cast<int>(std::ceil((hi_x - lo_x) / pixel * near_scale)) + 4;
  K.height = static_cast<int>(std::ceil((hi_y - lo_y) / pixel * near_scale)) + 4;
  K.cx = K.width / 2.0 - (hi_x + lo_x) / 2 / pixel;
  K.cy = K.height / 2.0 - (hi_y + lo_y) / 2 / pixel;
  K.body = "virtual view of an imported 3D image";

  out.pixels.resize(V.size());
  out.texcoords.resize(V.size());
  std::vector<float> depth(V.size());
  for (std::size_t i = 0; i < V.size(); ++i) {
    const Eigen::Vector3d c = out.pose.R * (V[i] - out.pose.centre);
    depth[i] = static_cast<float>(c.z());
    out.pixels[i] = Eigen::Vector2f(static_cast<float>(K.fx * c.x() / c.z() + K.cx),
                                    static_cast<float>(K.fy * c.y() / c.z() + K.cy));
    out.texcoords[i] = {out.pixels[i].x() / static_cast<float>(K.width),
                        out.pixels[i].y() / static_cast<float>(K.height)};
  }

  out.image = cv::Mat(K.height, K.width, CV_8UC3, kHoleGrey);
  cv::Mat zbuffer(K.height, K.width, CV_32F, cv::Scalar(std::numeric_limits<float>::infinity()));
  for (const auto& t : T) {
    const auto a = static_cast<std::size_t>(t[0]), b = static_cast<std::size_t>(t[1]),
               c = static_cast<std::size_t>(t[2]);
    const Eigen::Vector2f pa = out.pixels[a], pb = out.pixels[b], pc = out.pixels[c];
    const float area = (pb - pa).x() * (pc - pa).y() - (pb - pa).y() * (pc - pa).x();
    if (area == 0 || !std::isfinite(area)) continue;
    // Grey shade for a mesh without colour: by the triangle's slope to the view.
    cv::Vec3b shade = kHoleGrey;
    if (!has_texture && !has_colours) {
      const Eigen::Vector3d n = (V[b] - V[a]).cross(V[c] - V[a]).normalized();
      const double lit = 0.25 + 0.75 * std::abs(n.dot(in.toward_viewer));
      shade = cv::Vec3b::all(static_cast<std::uint8_t>(std::lround(255 * lit)));
    }
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({pa.x(), pb.x(), pc.x()})))),
              x1 = std::min(K.width - 1,
                            static_cast<int>(std::ceil(std::max({pa.x(), pb.x(), pc.x()})))),
              y0 = std::max(0, static_cast<int>(std::floor(std::min({pa.y(), pb.y(), pc.y()})))),
              y1 = std::min(K.height - 1,
                            static_cast<int>(std::ceil(std::max({pa.y(), pb.y(), pc.y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        const float wa = ((pb - p).x() * (pc - p).y() - (pb - p).y() * (pc - p).x()) / area;
        const float wb = ((pc - p).x() * (pa - p).y() - (pc - p).y() * (pa - p).x()) / area;
        const float wc = 1 - wa - wb;
        if (wa < 0 || wb < 0 || wc < 0) continue;
        const float z = wa * depth[a] + wb * depth[b] + wc * depth[c];
        float& nearest = zbuffer.at<float>(y, x);
        if (z >= nearest) continue;
        nearest = z;
        cv::Vec3b colour = shade;
        if (has_texture) {
          const auto& ta = (*in.texcoords)[a];
          const auto& tb = (*in.texcoords)[b];
          const auto& tc = (*in.texcoords)[c];
          colour = sample_texture(in.texture, wa * ta[0] + wb * tb[0] + wc * tc[0],
                                  wa * ta[1] + wb * tb[1] + wc * tc[1]);
        } else if (has_colours) {
          const auto& ca = (*in.colours)[a];
          const auto& cb = (*in.colours)[b];
          const auto& cc = (*in.colours)[c];
          for (int k = 0; k < 3; ++k)  // RGB into BGR
            colour[2 - k] = static_cast<std::uint8_t>(std::lround(
                wa * ca[static_cast<std::size_t>(k)] + wb * cb[static_cast<std::size_t>(k)] +
                wc * cc[static_cast<std::size_t>(k)]));
        }
        out.image.at<cv::Vec3b>(y, x) = colour;
      }
  }
  return out;
}

}  // namespace rockface::photogrammetry
