#include "core/rockmass/block_sizes.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>

namespace rockface::rockmass {

BlockShape block_shape(double a1, double a2, double a3) {
  double d[3] = {a1, a2, a3};
  std::sort(d, d + 3);
  BlockShape s;
  if (d[0] <= 0) {
    s.words = "degenerate";
    return s;
  }
  s.alpha2 = d[1] / d[0];
  s.alpha3 = d[2] / d[0];
  s.beta =
      std::pow(s.alpha2 + s.alpha2 * s.alpha3 + s.alpha3, 3) / std::pow(s.alpha2 * s.alpha3, 2);
  // Palmström's classes of beta; long (a3 stands out) or flat (a1 does).
  const char* degree = s.beta <= 28   ? nullptr
                       : s.beta <= 32 ? "slightly"
                       : s.beta < 60  ? "moderately"
                       : s.beta < 200 ? ""
                                      : "very";
  if (!degree) {
    s.words = "equidimensional (compact)";
  } else {
    const bool flat = s.alpha2 > std::sqrt(s.alpha3);  // a2 nearer a3 than a1
    s.words = std::string(degree) + (degree[0] ? " " : "") + (flat ? "flat" : "long");
  }
  return s;
}

const char* block_size_words(double v) {
  if (v < 0.0002) return "very small blocks (< 0.2 dm3)";
  if (v < 0.01) return "small blocks (0.2-10 dm3)";
  if (v < 0.2) return "moderate blocks (10-200 dm3)";
  if (v < 10) return "large blocks (0.2-10 m3)";
  return "very large blocks (> 10 m3)";
}

BlockSizes block_sizes(const std::vector<FaceBlock>& blocks,
                       const std::vector<SetSpacing>& spacings,
                       const std::vector<Eigen::Vector3d>& normals, std::optional<double> jv) {
  BlockSizes out;
  std::vector<double> betas;
  std::vector<BlockShape> shapes;
  for (const auto& b : blocks) {
    if (!(b.volume_m3 > 0)) continue;
    out.volumes_m3.push_back(b.volume_m3);
    if (b.principal_moments && b.mass_kg && *b.mass_kg > 0) {
      // The box with these principal moments: I1 = m (a2^2 + a3^2) / 12, ...
      const Eigen::Vector3d& I = *b.principal_moments;
      const double m = *b.mass_kg;
      double a[3];
      for (int k = 0; k < 3; ++k) a[k] = std::sqrt(std::max(0.0, 6.0 * (I.sum() - 2.0 * I[k]) / m));
      const BlockShape s = block_shape(a[0], a[1], a[2]);
      if (s.words != "degenerate") shapes.push_back(s);
    }
  }
  out.finite_blocks = static_cast<int>(out.volumes_m3.size());
  if (!out.volumes_m3.empty()) {
    const auto& v = out.volumes_m3;
    out.v50_m3 = quantile(v, 0.5);
    out.mean_m3 = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    out.min_m3 = *std::min_element(v.begin(), v.end());
    out.max_m3 = *std::max_element(v.begin(), v.end());
    // Half decades from below the smallest to above the largest.
    const double lo = std::floor(2 * std::log10(*out.min_m3)) / 2;
    const double hi = std::ceil(2 * std::log10(*out.max_m3) + 1e-12) / 2;
    for (double e = lo; e <= hi + 1e-9; e += 0.5) out.histogram.edges.push_back(std::pow(10, e));
    if (out.histogram.edges.size() < 2) out.histogram.edges.push_back(std::pow(10, lo + 0.5));
    out.histogram.counts.assign(out.histogram.edges.size() - 1, 0);
    for (double x : v) {
      std::size_t i = 0;
      while (i + 2 < out.histogram.edges.size() && x >= out.histogram.edges[i + 1]) ++i;
      ++out.histogram.counts[i];
    }
  }
  if (!shapes.empty()) {
    std::sort(shapes.begin(), shapes.end(),
              [](const BlockShape& a, const BlockShape& b) { return a.beta < b.beta; });
    out.shape_of_blocks = shapes[shapes.size() / 2];
  }

  // The three most closely spaced sets with a spacing.
  std::vector<std::size_t> with;
  for (std::size_t k = 0; k < spacings.size() && k < normals.size(); ++k)
    if (spacings[k].mean_m) with.push_back(k);
  std::sort(with.begin(), with.end(), [&](std::size_t a, std::size_t b) {
    return *spacings[a].mean_m < *spacings[b].mean_m;
  });
  if (with.size() >= 3) {
    Eigen::Matrix3d n;
    double s[3];
    for (int i = 0; i < 3; ++i) {
      n.col(i) = normals[with[i]].normalized();
      s[i] = *spacings[with[i]].mean_m;
      out.spacing_sets.push_back(spacings[with[i]].label);
    }
    const double det = std::abs(n.determinant());
    if (det > 1e-3) {
      out.vb_from_spacing_m3 = s[0] * s[1] * s[2] / det;
      out.shape_from_spacing = block_shape(s[0], s[1], s[2]);
    } else {
      out.note = "the three sets' normals are nearly coplanar: they cut no closed block";
    }
  }
  if (jv && *jv > 0)
    out.vb_from_jv_m3 =
        (out.shape_from_spacing ? out.shape_from_spacing->beta : 27.0) / std::pow(*jv, 3);
  const std::optional<double> shown =
      out.v50_m3 ? out.v50_m3
                 : (out.vb_from_spacing_m3 ? out.vb_from_spacing_m3 : out.vb_from_jv_m3);
  if (shown) out.size_words = block_size_words(*shown);
  return out;
}

}  // namespace rockface::rockmass
