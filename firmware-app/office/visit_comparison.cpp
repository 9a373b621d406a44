#include "firmware-app/office/visit_comparison.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/common/number_format.h"
#include "core/geometry/orientation.h"
#include "storage/project/visit_geologist.h"

namespace rockface::app::office_web {

using nlohmann::json;

namespace {

constexpr double kComparisonDegree = 3.14159265358979323846 / 180.0;

std::string compared_orientation_text(double dip, double dipdir) {
  return format_fixed(dip, 0, "°") + " / " + format_fixed(dipdir, 0, "°");
}

// The angle between two planes' poles, 0..90°.
double set_pole_angle_deg(const storage::ReportedJointSet& a, const storage::ReportedJointSet& b) {
  const double c = std::abs(geometry::plane_normal_deg(a.dip_deg, a.dipdir_deg)
                                .dot(geometry::plane_normal_deg(b.dip_deg, b.dipdir_deg)));
  return std::acos(std::min(1.0, c)) / kComparisonDegree;
}

Eigen::Vector3d compared_block_centre(const analysis::ReportBlock& b) {
  if (b.centroid) return *b.centroid;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& v : b.vertices) sum += v;
  return b.vertices.empty() ? sum : sum / static_cast<double>(b.vertices.size());
}

std::string compared_volume_text(const std::optional<double>& v) {
  return v ? format_significant(*v, 3, " m³") : std::string("–");
}

// Greedy nearest-first matching of a's items to b's: pairs (i, j) by
// increasing distance, each item used once, distances above `limit` (or
// refused by `fits`) never matched.
template <typename Distance, typename Fits>
std::vector<std::tuple<std::size_t, std::size_t, double>> match_nearest_first(
    std::size_t na, std::size_t nb, Distance distance, Fits fits, double limit) {
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j) {
      const double d = distance(i, j);
      if (d <= limit && fits(i, j)) pairs.emplace_back(d, i, j);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used_a(na, false), used_b(nb, false);
  std::vector<std::tuple<std::size_t, std::size_t, double>> out;
  for (const auto& [d, i, j] : pairs) {
    if (used_a[i] || used_b[j]) continue;
    used_a[i] = used_b[j] = true;
    out.emplace_back(i, j, d);
  }
  return out;
}

}  // namespace

json compare_visits(const storage::FieldReport& earlier, const storage::FieldReport& later) {
  json out;
  // Who mapped each: a round later it may be someone else.
  out["earlier"] = {
      {"started_at", earlier.visit_started_at},
      {"project", earlier.project_name},
      {"geologist", earlier.visit_geologist.value_or(storage::kGeologistNotRecorded)}};
  out["later"] = {{"started_at", later.visit_started_at},
                  {"project", later.project_name},
                  {"geologist", later.visit_geologist.value_or(storage::kGeologistNotRecorded)}};

  const auto& sa = earlier.sets;
  const auto& sb = later.sets;
  const auto set_pairs = match_nearest_first(
      sa.size(), sb.size(),
      [&](std::size_t i, std::size_t j) { return set_pole_angle_deg(sa[i], sb[j]); },
      [](std::size_t, std::size_t) { return true; }, kSameSetDeg);
  json sets = json::array();
  std::vector<bool> seen_a(sa.size(), false), seen_b(sb.size(), false);
  for (const auto& [i, j, angle] : set_pairs) {
    seen_a[i] = seen_b[j] = true;
    // Whole degrees: a set's mean is known to a few degrees (alpha95).
    sets.push_back(
        {{"state", "matched"},
         {"earlier",
          sa[i].label + " " + compared_orientation_text(sa[i].dip_deg, sa[i].dipdir_deg)},
         {"later", sb[j].label + " " + compared_orientation_text(sb[j].dip_deg, sb[j].dipdir_deg)},
         {"change_deg", angle},
         {"change", format_fixed(angle, 0, "°")},
         {"planes", std::to_string(sa[i].count) + " → " + std::to_string(sb[j].count)}});
  }
  for (std::size_t i = 0; i < sa.size(); ++i)
    if (!seen_a[i])
      sets.push_back({{"state", "vanished"},
                      {"earlier", sa[i].label + " " +
                                      compared_orientation_text(sa[i].dip_deg, sa[i].dipdir_deg)},
                      {"later", "–"},
                      {"change", "vanished"},
                      {"planes", std::to_string(sa[i].count) + " → 0"}});
  for (std::size_t j = 0; j < sb.size(); ++j)
    if (!seen_b[j])
      sets.push_back({{"state", "new"},
                      {"earlier", "–"},
                      {"later", sb[j].label + " " +
                                    compared_orientation_text(sb[j].dip_deg, sb[j].dipdir_deg)},
                      {"change", "new"},
                      {"planes", "0 → " + std::to_string(sb[j].count)}});
  out["sets"] = std::move(sets);

  const auto& ba = earlier.blocks;
  const auto& bb = later.blocks;
  // Both reports' points are absolute (the same datum for one pulled
  // project), so centroids compare directly.
  const auto block_pairs = match_nearest_first(
      ba.size(), bb.size(),
      [&](std::size_t i, std::size_t j) {
        return (compared_block_centre(ba[i]) - compared_block_centre(bb[j])).norm();
      },
      [&](std::size_t i, std::size_t j) {
        if (!ba[i].volume || !bb[j].volume)
          return ba[i].volume.has_value() == bb[j].volume.has_value();
        const double lo = std::min(*ba[i].volume, *bb[j].volume);
        const double hi = std::max(*ba[i].volume, *bb[j].volume);
        return lo > 0 && hi / lo <= kSameBlockVolume;
      },
      kSameBlockM);
  json blocks = json::array();
  std::vector<bool> used_a(ba.size(), false), used_b(bb.size(), false);
  for (const auto& [i, j, d] : block_pairs) {
    used_a[i] = used_b[j] = true;
    const std::string va = storage::report_verdict(ba[i]);
    const std::string vb = storage::report_verdict(bb[j]);
    // Centimetres: the traces are picked to about that.
    blocks.push_back({{"state", va == vb ? "same verdict" : "verdict changed"},
                      {"earlier", ba[i].id + ": " + va + ", " + compared_volume_text(ba[i].volume)},
                      {"later", bb[j].id + ": " + vb + ", " + compared_volume_text(bb[j].volume)},
                      {"moved", format_fixed(d * 100, 0, " cm")},
                      {"verdict_changed", va != vb}});
  }
  for (std::size_t i = 0; i < ba.size(); ++i)
    if (!used_a[i])
      blocks.push_back({{"state", "not found again"},
                        {"earlier", ba[i].id + ": " + storage::report_verdict(ba[i]) + ", " +
                                        compared_volume_text(ba[i].volume)},
                        {"later", "–"},
                        {"moved", "–"},
                        {"verdict_changed", false}});
  for (std::size_t j = 0; j < bb.size(); ++j)
    if (!used_b[j])
      blocks.push_back({{"state", "new"},
                        {"earlier", "–"},
                        {"later", bb[j].id + ": " + storage::report_verdict(bb[j]) + ", " +
                                      compared_volume_text(bb[j].volume)},
                        {"moved", "–"},
                        {"verdict_changed", false}});
  out["blocks"] = std::move(blocks);
  return out;
}

}  // namespace rockface::app::office_web
