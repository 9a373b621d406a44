#include "core/measure/stereonet_image.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/common/units.h"

namespace rockface::measure {

namespace {

namespace g = geometry;

// Concentration of the Fisher kernel that smooths the poles into a density
// (about 8 degrees of spread): fine enough to separate sets 20 degrees
// apart, coarse enough not to draw every pole as its own peak.
constexpr double kContourKappa = 50.0;
// Contour levels as fractions of the peak density.
constexpr double kContourLevels[] = {0.2, 0.4, 0.6, 0.8};
// The density is evaluated on a coarser grid and resized: contours need no
// more than ~4 px resolution.
constexpr int kDensityGrid = 200;

cv::Point to_cv(const Eigen::Vector2d& p) {
  return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

void draw_net_polyline(cv::Mat& img, const std::vector<Eigen::Vector2d>& net, const cv::Scalar& c,
                       int thickness) {
  std::vector<cv::Point> pts;
  for (const auto& p : net) pts.push_back(to_cv(net_to_pixel(p, img.cols)));
  cv::polylines(img, pts, false, c, thickness, cv::LINE_AA);
}

// A small circle of angular radius `angle` about the axis `centre` (lower
// hemisphere): split where it crosses the primitive.
void draw_small_circle(cv::Mat& img, const Eigen::Vector3d& centre_axis, double angle,
                       const StereonetPicture& pic, const cv::Scalar& c, int thickness) {
  Eigen::Vector3d axis = centre_axis.normalized();
  if (axis.z() > 0) axis = -axis;  // the lower hemisphere's copy
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  std::vector<Eigen::Vector2d> run;
  for (int i = 0; i <= 180; ++i) {
    const double t = 2 * kPi * i / 180;
    const Eigen::Vector3d d =
        std::cos(angle) * axis + std::sin(angle) * (std::cos(t) * u + std::sin(t) * v);
    if (d.z() > 0) {  // above the horizon: not on this hemisphere
      if (run.size() > 1) draw_net_polyline(img, run, c, thickness);
      run.clear();
      continue;
    }
    run.push_back(g::project_direction(d, pic.projection, pic.hemisphere));
  }
  if (run.size() > 1) draw_net_polyline(img, run, c, thickness);
}

// Half way to white: the thin lines under the sets' own.
cv::Scalar lighter(const cv::Scalar& c) {
  return {0.5 * (c[0] + 255), 0.5 * (c[1] + 255), 0.5 * (c[2] + 255)};
}

// Where and how large the north mark's "N" is written.
cv::Point north_label_origin(int S) {
  const cv::Point centre = to_cv(net_to_pixel({0, 0}, S));
  return {centre.x - S / 100, centre.y - static_cast<int>(std::lround(0.4 * S)) - S / 30};
}
double north_label_scale(int S) {
  return S / 1600.0 + 0.2;
}

// The daylight envelope (pole plot): for each dip direction within 90
// degrees of the face's, the pole of the plane that dips exactly as steeply
// as the face does along that direction (its apparent dip). Poles between
// it and the friction circle are of planes that daylight and slide.
std::vector<Eigen::Vector2d> daylight_envelope(const KinematicOverlay& k,
                                               const StereonetPicture& pic) {
  std::vector<Eigen::Vector2d> out;
  constexpr int kSteps = 90;
  for (int i = 0; i <= kSteps; ++i) {
    const double off = -kPi / 2 + kPi * i / kSteps;
    const double dip = std::atan(std::tan(k.face.dip) * std::cos(off));
    out.push_back(g::project_pole({dip, k.face.dipdir + off}, pic.projection, pic.hemisphere));
  }
  return out;
}

std::string orientation_text(const g::PlaneOrientation& o) {
  return format_zero_padded(rad_to_deg(o.dip), 2, 0) + "/" +
         format_zero_padded(rad_to_deg(o.dipdir), 3, 0);
}

// Planar sliding (Markland): dips steeper than the friction angle, daylights
// in the face (shallower than the face's apparent dip along its own dip
// direction) and dips within the lateral limit of the face's dip direction.
bool slides(const g::PlaneOrientation& plane, const KinematicOverlay& k) {
  double off = std::remainder(plane.dipdir - k.face.dipdir, 2 * kPi);
  if (std::abs(off) > k.lateral_limit) return false;
  const double apparent = std::atan(std::tan(k.face.dip) * std::cos(off));
  return plane.dip > k.friction && plane.dip < apparent;
}

}  // namespace

cv::Scalar set_colour(int set) {
  // Distinct on white and for the common colour blindnesses (Okabe-Ito), BGR.
  static const cv::Scalar palette[] = {{178, 114, 0},   {0, 94, 213},   {115, 158, 0},
                                       {167, 121, 204}, {233, 180, 86}, {66, 228, 240},
                                       {0, 0, 0}};
  if (set < 0) return {150, 150, 150};
  return palette[set % 7];
}

Eigen::Vector2d net_to_pixel(const Eigen::Vector2d& net, int size_px) {
  const double radius = 0.4 * size_px;
  const double c = 0.5 * size_px - 0.5;
  return {c + radius * net.x(), c - radius * net.y()};
}

cv::Rect north_label_box(int size_px) {
  int base = 0;
  const cv::Size size =
      cv::getTextSize("N", cv::FONT_HERSHEY_SIMPLEX, north_label_scale(size_px), 1, &base);
  const cv::Point o = north_label_origin(size_px);
  // The glyph's box above its baseline, and the antialiasing's pixel around it.
  return {o.x - 1, o.y - size.height - 1, size.width + 2, size.height + base + 2};
}

cv::Mat render_stereonet(const StereonetPicture& pic) {
  if (pic.size_px < 200)
    throw InputError("stereonet",
                     "size_px must be at least 200, got " + std::to_string(pic.size_px));
  if (!pic.pole_sets.empty() && pic.pole_sets.size() != pic.poles.size())
    throw InputError("stereonet", "pole_sets must have one entry per pole");
  for (std::size_t i = 0; i < pic.poles.size(); ++i)
    if (!pic.poles[i].allFinite() || pic.poles[i].norm() == 0)
      throw InputError("stereonet.poles[" + std::to_string(i) + "]", "is not a direction");
  const int S = pic.size_px;
  const double R = 0.4 * S;
  cv::Mat img(S, S, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Point centre = to_cv(net_to_pixel({0, 0}, S));

  // Kinematic critical zone, shaded pixel by pixel (poles of sliding planes).
  if (pic.kinematics) {
    for (int y = 0; y < S; ++y)
      for (int x = 0; x < S; ++x) {
        const Eigen::Vector2d net((x - (0.5 * S - 0.5)) / R, ((0.5 * S - 0.5) - y) / R);
        const auto d = g::direction_at(net, pic.projection, pic.hemisphere);
        if (!d) continue;
        if (slides(g::plane_orientation(*d), *pic.kinematics))
          img.at<cv::Vec3b>(y, x) = cv::Vec3b(210, 210, 255);
      }
  }

  // Fisher density contours of all poles.
  if (pic.density_contours && pic.poles.size() >= 3) {
    cv::Mat density(kDensityGrid, kDensityGrid, CV_32F, cv::Scalar(0));
    const double step = static_cast<double>(S) / kDensityGrid;
    for (int y = 0; y < kDensityGrid; ++y)
      for (int x = 0; x < kDensityGrid; ++x) {
        const double px = (x + 0.5) * step - 0.5, py = (y + 0.5) * step - 0.5;
        const Eigen::Vector2d net((px - (0.5 * S - 0.5)) / R, ((0.5 * S - 0.5) - py) / R);
        const auto d = g::direction_at(net, pic.projection, pic.hemisphere);
        if (!d) continue;
        double sum = 0;
        for (const auto& p : pic.poles)
          sum += std::exp(kContourKappa * (std::abs(d->dot(p.normalized())) - 1));
        density.at<float>(y, x) = static_cast<float>(sum);
      }
    double peak = 0;
    cv::minMaxLoc(density, nullptr, &peak);
    cv::Mat big;
    cv::resize(density, big, cv::Size(S, S), 0, 0, cv::INTER_LINEAR);
    for (std::size_t l = 0; l < std::size(kContourLevels); ++l) {
      cv::Mat mask = big >= kContourLevels[l] * peak;
      std::vector<std::vector<cv::Point>> contours;
      cv::findContours(mask, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
      const int shade = 200 - 40 * static_cast<int>(l);
      cv::drawContours(img, contours, -1, cv::Scalar(shade, shade, shade), 1, cv::LINE_AA);
    }
  }

  // The net: primitive circle, centre cross, north mark.
  const int radius_px = static_cast<int>(std::lround(R));
  cv::circle(img, centre, radius_px, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  cv::drawMarker(img, centre, cv::Scalar(0, 0, 0), cv::MARKER_CROSS, S / 60, 1);
  cv::line(img, {centre.x, centre.y - radius_px}, {centre.x, centre.y - radius_px - S / 40},
           cv::Scalar(0, 0, 0), 2);
  cv::putText(img, "N", north_label_origin(S), cv::FONT_HERSHEY_SIMPLEX, north_label_scale(S),
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);

  if (pic.kinematics) {
    // Friction circle: poles inside it dip less than the friction angle.
    draw_small_circle(img, -Eigen::Vector3d::UnitZ(), pic.kinematics->friction, pic,
                      cv::Scalar(0, 0, 200), 1);
    draw_net_polyline(img,
                      g::project_great_circle(pic.kinematics->face, pic.projection, pic.hemisphere),
                      cv::Scalar(0, 0, 200), 2);
    draw_net_polyline(img, daylight_envelope(*pic.kinematics, pic), cv::Scalar(0, 0, 200), 1);
  } else if (pic.friction && *pic.friction > 0 && *pic.friction < kPi / 2) {
    draw_small_circle(img, -Eigen::Vector3d::UnitZ(), *pic.friction, pic, cv::Scalar(0, 0, 200), 1);
  }
  int text_row = S / 30;
  const double font = S / 1600.0 + 0.15;
  for (const auto& f : pic.faces) {
    draw_net_polyline(img, g::project_great_circle(f.orientation, pic.projection, pic.hemisphere),
                      cv::Scalar(0, 0, 0), 2);
    cv::putText(img, "face " + f.label + " " + orientation_text(f.orientation),
                {S / 60, S - text_row}, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
    text_row += S / 30;
  }

  // The planes' great circles under everything else, lighter than the sets'.
  if (pic.plane_great_circles)
    for (std::size_t i = 0; i < pic.poles.size(); ++i) {
      const int set = pic.pole_sets.empty() ? -1 : pic.pole_sets[i];
      draw_net_polyline(img,
                        g::project_great_circle(g::plane_orientation(pic.poles[i]), pic.projection,
                                                pic.hemisphere),
                        lighter(set_colour(set)), 1);
    }
  // Poles, then the sets over them: great circle, mean pole and its cones.
  for (std::size_t i = 0; i < pic.poles.size(); ++i) {
    const int set = pic.pole_sets.empty() ? -1 : pic.pole_sets[i];
    const Eigen::Vector2d p =
        net_to_pixel(g::project_direction(pic.poles[i], pic.projection, pic.hemisphere), S);
    cv::circle(img, to_cv(p), std::max(3, S / 200), set_colour(set), cv::FILLED, cv::LINE_AA);
  }
  int legend_row = S / 30;
  for (std::size_t s = 0; s < pic.sets.size(); ++s) {
    const auto& set = pic.sets[s];
    const cv::Scalar c = set_colour(static_cast<int>(s));
    draw_net_polyline(img, g::project_great_circle(set.mean, pic.projection, pic.hemisphere), c, 2);
    const Eigen::Vector3d pole = g::plane_normal(set.mean);
    const Eigen::Vector2d p =
        net_to_pixel(g::project_direction(pole, pic.projection, pic.hemisphere), S);
    cv::drawMarker(img, to_cv(p), c, cv::MARKER_SQUARE, S / 50, 2);
    if (set.alpha95 > 0 && set.alpha95 < kPi / 2)
      draw_small_circle(img, pole, set.alpha95, pic, c, 1);
    if (set.variability > 0 && set.variability < kPi / 2)
      draw_small_circle(img, pole, set.variability, pic, lighter(c), 1);
    cv::putText(img, set.label + " " + orientation_text(set.mean), {S / 60, legend_row + S / 60},
                cv::FONT_HERSHEY_SIMPLEX, font, c, 1, cv::LINE_AA);
    legend_row += S / 30;
  }
  const std::string kind =
      std::string(pic.projection == g::Projection::EqualArea ? "equal area" : "equal angle") +
      (pic.hemisphere == g::Hemisphere::Lower ? ", lower" : ", upper");
  cv::putText(img, kind + " hemisphere, " + std::to_string(pic.poles.size()) + " poles",
              {S / 2, S - S / 30}, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(0, 0, 0), 1,
              cv::LINE_AA);
  // The title right of the N, right-aligned, shrunk to the room there.
  if (!pic.title.empty()) {
    const cv::Rect n = north_label_box(S);
    const int room = S - S / 60 - (n.x + n.width + S / 60);
    double scale = font;
    int base = 0;
    cv::Size size = cv::getTextSize(pic.title, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base);
    if (size.width > room) {
      scale *= static_cast<double>(room) / size.width;
      size = cv::getTextSize(pic.title, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base);
    }
    cv::putText(img, pic.title, {S - S / 60 - size.width, S / 30 + S / 60},
                cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  return img;
}

}  // namespace rockface::measure
