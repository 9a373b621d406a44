#include "ui/blocks/block_summary.h"

#include <algorithm>
#include <optional>

#include <Eigen/Core>

#include <nlohmann/json.hpp>

#include "core/common/number_format.h"
#include "core/common/units.h"
#include "core/geometry/orientation.h"
#include "ui/blocks/block_verdict.h"
#include "ui/widgets/format.h"

namespace rockface::ui {

namespace {

const nlohmann::json* field(const nlohmann::json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() || it->is_null() ? nullptr : &*it;
}

std::optional<double> number_field(const nlohmann::json& obj, const char* key) {
  const auto* v = field(obj, key);
  if (!v || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

std::optional<Eigen::Vector3d> vector3(const nlohmann::json& obj, const char* key) {
  const auto* v = field(obj, key);
  if (!v || !v->is_array() || v->size() != 3) return std::nullopt;
  for (const auto& x : *v)
    if (!x.is_number()) return std::nullopt;
  return Eigen::Vector3d((*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>());
}

std::string joined_planes(const nlohmann::json& mode) {
  std::string out;
  if (const auto* planes = field(mode, "planes"); planes && planes->is_array())
    for (const auto& p : *planes)
      if (p.is_string()) out += (out.empty() ? "" : ", ") + p.get<std::string>();
  return out;
}

void add_mode(std::vector<std::string>& lines, const storage::BlockResult& b,
              const nlohmann::json& report) {
  if (!b.finite || !b.removable) return;
  const auto* mode = field(report, "mode");
  std::string line = "Mode: " + b.mode;
  if (mode) {
    const std::string planes = joined_planes(*mode);
    if (!planes.empty()) line += " on " + planes;
    if (const auto d = vector3(*mode, "direction"); d && d->norm() > 0) {
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

void add_rotation(std::vector<std::string>& lines, const nlohmann::json& report) {
  const auto* rotation = field(report, "rotation");
  if (!rotation) return;
  int corners = 0, corners_free = 0, edges = 0, edges_free = 0;
  std::optional<double> least_margin;
  if (const auto* cs = field(*rotation, "corners"); cs && cs->is_array())
    for (const auto& c : *cs) {
      ++corners;
      if (c.value("rotatable", false)) ++corners_free;
      if (const auto m = number_field(c, "margin_deg"))
        least_margin = least_margin ? std::min(*least_margin, *m) : *m;
    }
  if (const auto* es = field(*rotation, "edges"); es && es->is_array())
    for (const auto& e : *es) {
      ++edges;
      if (e.value("rotatable", false)) ++edges_free;
    }
  std::string line = "Rotation: " + std::to_string(corners_free) + " of " +
                     std::to_string(corners) + " corners and " + std::to_string(edges_free) +
                     " of " + std::to_string(edges) + " edges can rotate";
  if (least_margin)
    line += " (least corner margin " + format::text(format::Angle{*least_margin}) + ")";
  lines.push_back(line);
}

void add_remote_axis(std::vector<std::string>& lines, const nlohmann::json& report) {
  const auto* axis = field(report, "remote_axis");
  if (!axis) return;
  const auto starts = number_field(*axis, "starts"), hits = number_field(*axis, "hits");
  std::string line = axis->value("found", false) ? "Remote axis: found" : "Remote axis: none found";
  if (starts && *starts == 0)
    line = "Remote axis: not searched, the block already rotates about a corner or an edge";
  else if (starts && hits)
    line += " (" + format_fixed(*hits, 0) + " of " + format_fixed(*starts, 0) + " starts)";
  lines.push_back(line);
}

void add_mechanics(std::vector<std::string>& lines, const nlohmann::json& report) {
  const auto* m = field(report, "mechanics");
  if (!m) return;
  std::string line = "Equilibrium path: ";
  if (const auto fos = number_field(*m, "fos_limit_point"))
    line += "limit point at load factor " + format_fixed(*fos, 2);
  else if (const auto* outcome = field(*m, "outcome"); outcome && outcome->is_string())
    line += outcome->get<std::string>();  // e.g. "no limit point within the step budget"
  else
    line += "no limit point reached";
  if (const auto* s = field(*m, "stability"); s && s->is_string())
    line += ", " + s->get<std::string>();
  lines.push_back(line);
}

}  // namespace

std::vector<std::string> block_summary(const storage::BlockResult& b,
                                       const nlohmann::json& report) {
  std::vector<std::string> lines;
  std::string head = "Block " + b.label + ": " + verdict_name(verdict_of(b));
  if (b.marginal) head += " (a verdict within its margin: check on site)";
  lines.push_back(head);
  std::string what = std::string(b.finite ? "finite" : "not finite") + ", " +
                     (b.removable ? "removable" : "not removable");
  if (!b.source.empty()) what += ", from " + b.source;
  lines.push_back(what);
  if (const auto margin = number_field(report, "margin_deg"))
    lines.push_back("Margin " + format::text(format::Angle{*margin}));
  add_mode(lines, b, report);
  const auto volume = number_field(report, "volume"), mass = number_field(report, "mass");
  if (volume && mass)
    lines.push_back("Volume " + format::text(format::Volume{*volume}) + ", mass " +
                    format_fixed(*mass / 1000.0, 2, " t"));
  else if (volume)
    lines.push_back("Volume " + format::text(format::Volume{*volume}));
  add_rotation(lines, report);
  add_remote_axis(lines, report);
  add_mechanics(lines, report);
  if (const auto* areas = field(report, "face_areas"); areas && areas->is_object()) {
    std::string line = "Face areas:";
    std::string sep = " ";
    for (const auto& [name, area] : areas->items())
      if (area.is_number()) {
        line += sep + name + " " + format::text(format::Area{area.get<double>()});
        sep = ", ";
      }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace rockface::ui
