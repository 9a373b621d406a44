#include "firmware-app/propose/proposals_picture.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/measure/pair_photo.h"

namespace rockface::app {

namespace {

// Colour-blind-safe (Okabe-Ito), BGR; sets beyond the eighth reuse them.
const cv::Scalar kSetColours[] = {{0, 159, 230}, {233, 180, 86}, {115, 158, 0},   {66, 228, 240},
                                  {178, 114, 0}, {0, 94, 213},   {167, 121, 204}, {0, 0, 0}};
const cv::Scalar kNoSet(170, 170, 170);

}  // namespace

cv::Mat proposals_picture(const ProposeResult& r, int max_width) {
  const auto& mesh = r.model.mesh;
  cv::Mat photo;
  if (const auto it = r.model.photos.find(measure::pair_photo(1, "left"));
      it != r.model.photos.end())
    photo = it->second;
  const int width = !photo.empty() ? photo.cols : std::max(1, mesh.texture_width);
  const int height = !photo.empty() ? photo.rows : std::max(1, mesh.texture_height);
  const double scale = std::min(1.0, static_cast<double>(max_width) / width);
  const cv::Size size(std::max(1, static_cast<int>(std::lround(width * scale))),
                      std::max(1, static_cast<int>(std::lround(height * scale))));
  cv::Mat picture;
  if (photo.empty())
    picture = cv::Mat(size, CV_8UC3, cv::Scalar(90, 90, 90));
  else
    cv::resize(photo, picture, size, 0, 0, cv::INTER_AREA);

  // Facet labels painted triangle by triangle at the picture's scale.
  cv::Mat label(size, CV_32S, cv::Scalar(0));
  std::vector<cv::Point2d> centre(r.facets.facets.size(), cv::Point2d(0, 0));
  const bool placed = mesh.pixels.size() == mesh.vertices.size();
  for (std::size_t i = 0; i < r.facets.facets.size() && placed; ++i) {
    const auto& f = r.facets.facets[i];
    double n = 0;
    for (const int t : f.mesh_triangles) {
      cv::Point corners[3];
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2f& px = mesh.pixels[mesh.triangles[t][k]];
        corners[k] = cv::Point(static_cast<int>(std::lround(px.x() * scale)),
                               static_cast<int>(std::lround(px.y() * scale)));
        centre[i] += cv::Point2d(px.x() * scale, px.y() * scale);
        n += 1;
      }
      cv::fillConvexPoly(label, corners, 3, cv::Scalar(static_cast<int>(i) + 1));
    }
    if (n > 0) centre[i] *= 1.0 / n;
  }
  auto colour_of = [&](int facet) {
    const int s = r.sets.set_of.empty() ? -1 : r.sets.set_of[static_cast<std::size_t>(facet)];
    return s < 0 ? kNoSet : kSetColours[s % 8];
  };
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const int l = label.at<int>(y, x);
      if (l == 0) continue;
      const cv::Scalar c = colour_of(l - 1);
      cv::Vec3b& p = picture.at<cv::Vec3b>(y, x);
      const bool edge = (x + 1 < size.width && label.at<int>(y, x + 1) != l) ||
                        (y + 1 < size.height && label.at<int>(y + 1, x) != l) ||
                        (x > 0 && label.at<int>(y, x - 1) != l) ||
                        (y > 0 && label.at<int>(y - 1, x) != l);
      const double a = edge ? 1.0 : 0.45;
      for (int k = 0; k < 3; ++k)
        p[k] = cv::saturate_cast<uchar>((edge ? 0.4 : 1.0) * a * c[k] + (1 - a) * p[k]);
    }
  const double font = std::max(0.4, size.width / 1600.0);
  const int thick = std::max(1, static_cast<int>(std::lround(font * 1.5)));
  for (std::size_t i = 0; i < r.facets.facets.size() && placed; ++i) {
    const std::string text = "F" + std::to_string(r.facets.facets[i].id);
    const cv::Point at(static_cast<int>(centre[i].x), static_cast<int>(centre[i].y));
    cv::putText(picture, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.6 * font, cv::Scalar(0, 0, 0),
                thick + 2);
    cv::putText(picture, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.6 * font, cv::Scalar(255, 255, 255),
                thick);
  }

  // The legend: one line per set, then the facets in no set.
  std::vector<std::pair<cv::Scalar, std::string>> rows;
  for (std::size_t s = 0; s < r.sets.sets.size(); ++s) {
    const auto& set = r.sets.sets[s];
    const auto o = set.summary.fisher.plane();
    rows.emplace_back(
        kSetColours[s % 8],
        set.summary.label + "  " + format_fixed(rad_to_deg(o.dip), 0) + "/" +
            format_fixed(rad_to_deg(o.dipdir), 0) + "  K " +
            (std::isfinite(set.summary.fisher.kappa) ? format_fixed(set.summary.fisher.kappa, 0)
                                                     : std::string("inf")) +
            "  spacing " +
            (set.summary.spacing ? format_fixed(*set.summary.spacing, 2) + " m" : "-") + "  " +
            std::to_string(set.facet_ids.size()) + " facets");
  }
  int unset = 0;
  for (int s : r.sets.set_of) unset += s < 0;
  if (unset > 0) rows.emplace_back(kNoSet, "in no set: " + std::to_string(unset) + " facets");
  if (rows.empty()) rows.emplace_back(kNoSet, "no facets");
  const int line = static_cast<int>(std::lround(28 * font));
  const int box_w = static_cast<int>(std::lround(560 * font));
  const cv::Rect box(10, 10, std::min(box_w, size.width - 20),
                     std::min(line * static_cast<int>(rows.size() + 1), size.height - 20));
  if (box.width > 0 && box.height > 0) {
    cv::Mat roi = picture(box);
    cv::addWeighted(roi, 0.3, cv::Mat(roi.size(), roi.type(), cv::Scalar(255, 255, 255)), 0.7, 0,
                    roi);
    cv::putText(picture, "facets by joint set (dip/dip direction)",
                cv::Point(box.x + 8, box.y + static_cast<int>(0.75 * line)),
                cv::FONT_HERSHEY_SIMPLEX, 0.5 * font, cv::Scalar(0, 0, 0), thick);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int y = box.y + static_cast<int>((i + 1) * line);
      cv::rectangle(picture, cv::Rect(box.x + 8, y + line / 5, line / 2, line / 2), rows[i].first,
                    cv::FILLED);
      cv::putText(picture, rows[i].second, cv::Point(box.x + 16 + line / 2, y + 3 * line / 4),
                  cv::FONT_HERSHEY_SIMPLEX, 0.5 * font, cv::Scalar(0, 0, 0), thick);
    }
  }
  return picture;
}

}  // namespace rockface::app
