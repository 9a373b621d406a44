#include "core/analysis/mechanics_plot.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/atomic_file.h"
#include "core/common/error.h"
#include "core/common/number_format.h"

namespace rockface::analysis {

namespace {

cv::Mat draw(const ReportMechanics& m, int width, int height) {
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int left = 48, right = 12, top = 12, bottom = 36;
  const cv::Point origin(left, height - bottom);
  const int w = width - left - right, h = height - top - bottom;
  double dmax = 0, lmax = 0;
  for (const auto& p : m.path) {
    dmax = std::max(dmax, p[1]);
    lmax = std::max(lmax, p[0]);
  }
  if (m.fos_limit_point) lmax = std::max(lmax, *m.fos_limit_point);
  if (!(dmax > 0)) dmax = 1;
  if (!(lmax > 0)) lmax = 1;
  lmax *= 1.1;
  auto at = [&](double d, double l) {
    return cv::Point(origin.x + static_cast<int>(std::lround(d / dmax * w)),
                     origin.y - static_cast<int>(std::lround(l / lmax * h)));
  };
  const cv::Scalar axis(0, 0, 0), curve(160, 60, 0), limit(0, 0, 200);
  cv::line(img, origin, {origin.x + w, origin.y}, axis, 1);
  cv::line(img, origin, {origin.x, origin.y - h}, axis, 1);
  if (m.fos_limit_point)
    for (int x = 0; x < w; x += 8)
      cv::line(img, at(x * dmax / w, *m.fos_limit_point),
               at(std::min(x + 4, w) * dmax / w, *m.fos_limit_point), limit, 1);
  for (size_t k = 1; k < m.path.size(); ++k)
    cv::line(img, at(m.path[k - 1][1], m.path[k - 1][0]), at(m.path[k][1], m.path[k][0]), curve, 2,
             cv::LINE_AA);
  for (const auto& p : m.path) cv::circle(img, at(p[1], p[0]), 2, curve, cv::FILLED);
  const double font = 0.4;
  cv::putText(img, "displacement (m), max " + format_significant(dmax, 3), {left, height - 10},
              cv::FONT_HERSHEY_SIMPLEX, font, axis, 1, cv::LINE_AA);
  cv::putText(img, format_significant(lmax, 3), {2, top + 10}, cv::FONT_HERSHEY_SIMPLEX, font, axis,
              1, cv::LINE_AA);
  cv::putText(img, "lambda", {2, origin.y - h / 2}, cv::FONT_HERSHEY_SIMPLEX, font, axis, 1,
              cv::LINE_AA);
  if (m.fos_limit_point)
    cv::putText(img, "FoS " + format_significant(*m.fos_limit_point, 3),
                at(0.05 * dmax, *m.fos_limit_point) + cv::Point(4, -4), cv::FONT_HERSHEY_SIMPLEX,
                font, limit, 1, cv::LINE_AA);
  return img;
}

std::string file_safe(const std::string& id) {
  std::string out = id;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return out;
}

}  // namespace

PlotImage plot_path(const ReportMechanics& m, int width, int height) {
  const cv::Mat img = draw(m, width, height);
  PlotImage out;
  out.width = img.cols;
  out.height = img.rows;
  out.bgr.assign(img.data, img.data + img.total() * img.elemSize());
  return out;
}

void write_mechanics_plots(Report& report, const std::string& report_path) {
  std::string stem = report_path;
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0)
    stem.resize(stem.size() - 5);
  for (ReportBlock& b : report.blocks) {
    if (!b.mechanics || b.mechanics->path.empty()) continue;
    const std::string file = stem + "." + file_safe(b.id) + ".path.png";
    // Encoded in memory, then written whole by the one atomic writer (a full
    // card leaves no truncated picture under the final name).
    std::vector<unsigned char> png;
    if (!cv::imencode(".png", draw(*b.mechanics, 360, 240), png))
      throw Error(file + ": cannot encode the plot of the equilibrium path");
    write_bytes_atomically(file, png.data(), png.size());
    const auto slash = file.find_last_of('/');
    b.mechanics->plot = slash == std::string::npos ? file : file.substr(slash + 1);
  }
}

}  // namespace rockface::analysis
