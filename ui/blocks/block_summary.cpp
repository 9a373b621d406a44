#include "ui/blocks/block_summary.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Core>

#include "core/analysis/block_verdict.h"
#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

// A number the stored report knows (a null in it reads as NaN).
std::optional<double> known(std::optional<double> v) {
  return v && !std::isnan(*v) ? v : std::nullopt;
}

std::string joined_planes(const analysis::ReportMode& mode) {
  std::string out;
  for (const auto& p : mode.planes) out += (out.empty() ? "" : ", ") + p;
  return out;
}

void add_mode(std::vector<std::string>& lines, const analysis::ReportBlock& b) {
  if (!b.finite || !b.removable) return;
  std::string line = "Mode: " + (b.mode ? b.mode->type : std::string("none"));
  if (b.mode) {
    const std::string planes = joined_planes(*b.mode);
    if (!planes.empty()) line += " on " + planes;
    if (const auto& d = b.mode->direction; d && d->norm() > 0) {
      const auto o = geometry::line_orientation(*d);
      line += ", towards " + format::azimuth(rad_to_deg(o.trend)) + " trend, " +
              format::text(format::Angle{rad_to_deg(o.plunge)}) + " plunge";
    }
  }
  lines.push_back(line);
  if (b.fos) {
    std::string fos =
        "Factor of safety " + format::text(format::FactorOfSafety{*b.fos}) + " (limit equilibrium";
    fos += *b.fos < 1 ? "): it slides" : ")";
    lines.push_back(fos);
  }
}

void add_rotation(std::vector<std::string>& lines, const analysis::ReportBlock& b) {
  if (!b.rotation) return;
  int corners_free = 0, edges_free = 0;
  std::optional<double> least_margin;
  for (const auto& c : b.rotation->corners) {
    if (c.rotatable) ++corners_free;
    if (!std::isnan(c.margin_deg))
      least_margin = least_margin ? std::min(*least_margin, c.margin_deg) : c.margin_deg;
  }
  for (const auto& e : b.rotation->edges)
    if (e.rotatable) ++edges_free;
  std::string line = "Rotation: " + std::to_string(corners_free) + " of " +
                     std::to_string(b.rotation->corners.size()) + " corners and " +
                     std::to_string(edges_free) + " of " +
                     std::to_string(b.rotation->edges.size()) + " edges can rotate";
  if (least_margin)
    line += " (least corner margin " + format::text(format::Angle{*least_margin}) + ")";
  lines.push_back(line);
}

void add_remote_axis(std::vector<std::string>& lines, const analysis::ReportBlock& b) {
  if (!b.remote_axis) return;
  const analysis::ReportRemoteAxis& axis = *b.remote_axis;
  std::string line = axis.found ? "Remote axis: found" : "Remote axis: none found";
  if (axis.starts == 0)
    line = "Remote axis: not searched, the block already rotates about a corner or an edge";
  else
    line += " (" + format_fixed(axis.hits, 0) + " of " + format_fixed(axis.starts, 0) + " starts)";
  lines.push_back(line);
}

void add_mechanics(std::vector<std::string>& lines, const analysis::ReportBlock& b) {
  if (!b.mechanics) return;
  const analysis::ReportMechanics& m = *b.mechanics;
  std::string line = "Equilibrium path: ";
  if (const auto fos = known(m.fos_limit_point))
    line += "limit point at load factor " + format_fixed(*fos, 2);
  else if (!m.outcome.empty())
    line += m.outcome;  // e.g. "no limit point within the step budget"
  else
    line += "no limit point reached";
  if (!m.stability.empty()) line += ", " + m.stability;
  lines.push_back(line);
}

}  // namespace

std::vector<std::string> block_summary(const analysis::ReportBlock& b) {
  std::vector<std::string> lines;
  std::string head = "Block " + b.id + ": " + analysis::verdict_name(analysis::verdict_of(b));
  if (b.marginal) head += " (a verdict within its margin: check on site)";
  lines.push_back(head);
  std::string what = std::string(b.finite ? "finite" : "not finite") + ", " +
                     (b.removable ? "removable" : "not removable");
  if (!b.source.empty()) what += ", from " + b.source;
  lines.push_back(what);
  if (!std::isnan(b.margin_deg))
    lines.push_back("Margin " + format::text(format::Angle{b.margin_deg}));
  add_mode(lines, b);
  const auto volume = known(b.volume), mass = known(b.mass);
  if (volume && mass)
    lines.push_back("Volume " + format::text(format::Volume{*volume}) + ", mass " +
                    format_fixed(*mass / 1000.0, 2, " t"));
  else if (volume)
    lines.push_back("Volume " + format::text(format::Volume{*volume}));
  add_rotation(lines, b);
  add_remote_axis(lines, b);
  add_mechanics(lines, b);
  if (!b.face_areas.empty()) {
    std::string line = "Face areas:";
    std::string sep = " ";
    for (const auto& [name, area] : b.face_areas) {
      line += sep + name + " " + format::text(format::Area{area});
      sep = ", ";
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace rockface::ui
