#include "core/analysis/block_reading.h"

#include <string>

namespace rockface::analysis {

bool vertices_are_surface_loop(const ReportBlock& block) {
  static const std::string kNote = "vertices: the loop on the free surface";
  for (const auto& n : block.notes)
    if (n.rfind(kNote, 0) == 0) return true;
  return false;
}

std::optional<bool> can_rotate(const ReportBlock& block) {
  if (!block.rotation) return std::nullopt;
  bool any = false;
  for (const auto& c : block.rotation->corners) any = any || c.rotatable;
  for (const auto& e : block.rotation->edges) any = any || e.rotatable;
  return any;
}

std::vector<Eigen::Vector3d> relative_to(const std::vector<Eigen::Vector3d>& points,
                                         const Eigen::Vector3d& datum) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(p - datum);
  return out;
}

ReportDynamics relative_to(const ReportDynamics& dynamics, const Eigen::Vector3d& datum) {
  ReportDynamics d = dynamics;
  for (auto& s : d.path) s.position -= datum;
  if (d.landing) {
    d.landing->point -= datum;
    d.landing->centroid -= datum;
  }
  if (d.floor) d.floor->first -= datum;
  return d;
}

}  // namespace rockface::analysis
