#include "firmware-app/wedges/wedges_json.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/analysis/effect_words.h"
#include "core/common/degrees_per_radian.h"
#include "storage/field_report/field_report.h"

namespace rockface::app {

namespace {

using nlohmann::json;

// v to a multiple of step; a step below 1 as a whole number of steps
// divided by their count per unit, so that 453.251 is written so and not
// as 453.25100000000003 (k * 0.001 is not the double nearest to k / 1000).
double round_to_step(double v, double step) {
  if (step < 1) {
    const double per_unit = std::round(1 / step);
    return std::round(v * per_unit) / per_unit;
  }
  return std::round(v / step) * step;
}

// Survey coordinates (apexes, vertices, bolt heads) to 0.1 mm, as the
// report writes them (issue 40): 1 mm at 5.2e6 m lost the size of a
// small wedge's corners.
constexpr double kCoordinateStepM = 1e-4;

json vec3(const Eigen::Vector3d& v, double step) {
  return {round_to_step(v.x(), step), round_to_step(v.y(), step), round_to_step(v.z(), step)};
}

json number_or_null(const std::optional<double>& v, double step) {
  if (!v || !std::isfinite(*v)) return nullptr;  // JSON has no infinity
  return round_to_step(*v, step);
}

const char* places_text(const tunnel::SupportPlaces& p, std::string& out) {
  out.clear();
  for (auto [on, name] : {std::pair{p.roof, "roof"}, std::pair{p.walls, "walls"},
                          std::pair{p.floor, "floor"}, std::pair{p.face, "face"}})
    if (on) out += (out.empty() ? "" : ", ") + std::string(name);
  return out.c_str();
}

json wedge_json(const tunnel::Wedge& w, const std::vector<WedgeSetInput>& sets) {
  (void)sets;
  json j;
  j["id"] = w.id;
  j["place"] = tunnel::wedge_place_name(w.place);
  j["position_deg"] = round_to_step(w.position_deg, 0.1);
  j["code"] = w.code;
  j["sets"] = w.sets;
  j["volume_m3"] = round_to_step(w.mass.volume, 1e-4);
  j["mass_kg"] = round_to_step(w.mass.mass, 0.1);
  j["weight_n"] = round_to_step(w.weight, 1);
  j["apex"] = vec3(w.apex, kCoordinateStepM);
  j["apex_height_m"] = round_to_step(w.apex_height, 0.001);
  j["bolt_length_to_apex_m"] = round_to_step(w.bolt_length_to_apex, 0.001);
  j["face_area_m2"] = round_to_step(w.face_area, 1e-4);
  j["face_perimeter_m"] = round_to_step(w.face_perimeter, 0.001);
  json traces = json::object();
  for (const auto& [id, len] : w.trace_lengths) traces[id] = round_to_step(len, 0.001);
  j["trace_lengths_m"] = traces;
  j["scaled"] = w.scaled;
  if (w.scaled) j["scale"] = round_to_step(w.scale, 1e-4);
  j["removable"] = w.removable.value;
  j["margin_deg"] = round_to_step(w.removable.margin * kDegPerRad, 0.01);
  j["marginal"] = w.removable.marginal;
  if (w.mode) {
    json m;
    m["type"] = kinematics::mode_name(w.mode->type);
    json planes = json::array();
    for (int p : w.mode->planes)
      for (const auto& bp : w.block.planes())
        if (bp.index == p && bp.kind == blocks::PlaneKind::Joint) planes.push_back(bp.name);
    m["planes"] = planes;
    m["direction"] = vec3(w.mode->direction, 1e-4);
    m["margin_deg"] = round_to_step(w.mode->margin * kDegPerRad, 0.01);
    m["marginal"] = w.mode->marginal;
    j["mode"] = m;
    j["fos"] = number_or_null(w.fos, 0.001);
  }
  if (w.fos_supported) j["fos_supported"] = number_or_null(w.fos_supported, 0.001);
  j["effects_used"] = w.effects_used;
  if (!w.bolts.empty() || w.bolts_anchored > 0) {
    json b;
    b["on_face"] = w.bolts.size();
    b["anchored"] = w.bolts_anchored;
    b["force_n"] = round_to_step(w.bolt_force, 1);
    json list = json::array();
    for (const auto& bolt : w.bolts)
      list.push_back({{"head", vec3(bolt.head, kCoordinateStepM)},
                      {"direction", vec3(bolt.direction, 1e-4)},
                      {"depth_in_wedge_m", round_to_step(bolt.depth_in_wedge, 0.001)},
                      {"anchorage_m", round_to_step(bolt.anchorage, 0.001)},
                      {"force_n", round_to_step(bolt.force, 1)}});
    b["list"] = list;
    j["bolts"] = b;
  }
  if (w.shotcrete_force > 0) j["shotcrete_force_n"] = round_to_step(w.shotcrete_force, 1);
  if (w.support_pressure > 0) j["support_pressure_pa"] = round_to_step(w.support_pressure, 1);
  j["weight_pressure_pa"] = round_to_step(w.weight_pressure, 1);
  json segs = json::array();
  for (auto s : w.segments) segs.push_back(s + 1);
  j["profile_segments"] = segs;
  j["corners"] = w.corners;
  json outline = json::array();
  for (const auto& p : w.outline)
    outline.push_back({round_to_step(p.x(), 0.001), round_to_step(p.y(), 0.001)});
  j["section_outline"] = outline;
  json vertices = json::array();
  for (int v = 0; v < static_cast<int>(w.block.vertices().size()); ++v)
    vertices.push_back(vec3(w.block.absolute_vertex(v), kCoordinateStepM));
  j["vertices"] = vertices;
  j["notes"] = w.notes;
  return j;
}

}  // namespace

std::string wedge_mode_words(const tunnel::Wedge& w) {
  if (!w.mode) return "-";
  switch (w.mode->type) {
    case kinematics::ModeType::Falling:
      return "falls";
    case kinematics::ModeType::Lifting:
      return "lifts";
    case kinematics::ModeType::None:
      return "stays (pushed into the rock)";
    case kinematics::ModeType::Sliding: {
      std::string s = "slides on ";
      bool first = true;
      for (int p : w.mode->planes)
        for (const auto& bp : w.block.planes())
          if (bp.index == p && bp.kind == blocks::PlaneKind::Joint) {
            s += (first ? "" : " and ") + bp.name;
            first = false;
          }
      return s;
    }
  }
  return "-";
}

std::string wedge_fos_text(const std::optional<double>& fos) {
  if (!fos) return "-";
  // Only sliding_mode's "no driving force" (+infinity) is stable; a NaN
  // (an overflow, 0 / 0) is no verdict at all (issue 41).
  if (std::isnan(*fos) || *fos < 0) return "unknown";
  if (std::isinf(*fos)) return "stable";
  return storage::report_number(*fos, 2);
}

std::string wedges_json(const WedgeRun& run, const tunnel::WedgeAnalysis& a) {
  json j;
  j["format"] = "rockface-wedges/1";
  j["source"] = run.source;
  if (run.visit) j["visit"] = *run.visit;
  j["preset"] = std::string(preset_name(run.preset));
  j["profile"] = {{"source", run.profile_source},
                  {"name", run.profile.name()},
                  {"perimeter_m", round_to_step(run.profile.perimeter(), 0.001)},
                  {"area_m2", round_to_step(run.profile.area(), 0.001)},
                  {"segments", run.profile.segments().size()},
                  {"chords_sagitta_m", run.options.sagitta_m},
                  {"convex_hull_used", a.section.hull_used}};
  j["axis"] = {{"trend", round_to_step(run.trend_deg, 0.01)},
               {"plunge", round_to_step(run.plunge_deg, 0.01)}};
  j["origin"] = vec3(run.frame.origin + run.datum, kCoordinateStepM);
  if (run.chainage) j["chainage"] = round_to_step(*run.chainage, 0.001);
  json sets = json::array();
  for (const auto& s : run.sets) {
    json x{{"id", s.id},
           {"dip", round_to_step(s.dip_deg, 0.1)},
           {"dipdir", round_to_step(s.dipdir_deg, 0.1)},
           {"cohesion_pa", s.cohesion_pa},
           {"source", s.source}};
    x["friction_deg"] = s.friction_deg ? json(round_to_step(*s.friction_deg, 0.1)) : json(nullptr);
    sets.push_back(x);
  }
  j["sets"] = sets;
  if (run.options.trace_length_limit) j["trace_length_limit_m"] = *run.options.trace_length_limit;
  json support = json::object();
  std::string where;
  if (run.options.bolts) {
    const auto& b = *run.options.bolts;
    support["bolts"] = {{"length_m", b.length},
                        {"spacing_m", b.spacing},
                        {"capacity_n", b.capacity},
                        {"on", places_text(b.places, where)}};
    if (b.bond_strength) support["bolts"]["bond_strength_n_per_m"] = *b.bond_strength;
  }
  if (run.options.shotcrete) {
    const auto& s = *run.options.shotcrete;
    support["shotcrete"] = {{"thickness_m", s.thickness},
                            {"shear_strength_pa", s.shear_strength},
                            {"on", places_text(s.places, where)}};
  }
  j["support"] = support;
  j["effects_simulated"] = a.effects_simulated;
  json wedges = json::array();
  for (const auto& w : a.wedges) wedges.push_back(wedge_json(w, run.sets));
  j["wedges"] = wedges;
  json none = json::array();
  for (const auto& n : a.none)
    none.push_back({{"code", n.code},
                    {"sets", n.sets},
                    // An unbuilt wedge claims no margin.
                    {"margin_deg",
                     n.unbuilt ? json(nullptr) : json(round_to_step(n.margin * kDegPerRad, 0.01))},
                    {"marginal", n.marginal},
                    {"reason", n.reason}});
  j["no_wedge"] = none;
  j["notes"] = a.notes;
  return j.dump(2) + "\n";
}

std::vector<std::string> wedges_summary(const WedgeRun& run, const tunnel::WedgeAnalysis& a) {
  std::vector<std::string> lines;
  std::ostringstream head;
  head << "wedges around " << (run.profile.name().empty() ? run.profile_source : run.profile.name())
       << ", axis " << storage::report_number(run.trend_deg, 1) << "/"
       << storage::report_number(run.plunge_deg, 1) << ", sets";
  for (const auto& s : run.sets)
    head << " " << s.id << " " << storage::report_number(s.dip_deg, 1) << "/"
         << storage::report_number(s.dipdir_deg, 1);
  lines.push_back(head.str());
  lines.push_back("effects simulated: " + analysis::effects_in_words(a.effects_simulated));
  lines.push_back(
      "wedge  place       code      volume m3  weight kN  apex m  bolt to apex m  margin    "
      "mode                FoS     FoS supported");
  for (const auto& w : a.wedges) {
    char buf[320];
    std::snprintf(
        buf, sizeof buf, "%-6s %-11s %-9s %-10s %-10s %-7s %-15s %-9s %-19s %-7s %s", w.id.c_str(),
        tunnel::wedge_place_name(w.place), w.code.c_str(),
        storage::report_number(w.mass.volume, 3).c_str(),
        storage::report_number(w.weight / 1000, 1).c_str(),
        storage::report_number(w.apex_height, 2).c_str(),
        storage::report_number(w.bolt_length_to_apex, 2).c_str(),
        (storage::report_number(w.removable.margin * kDegPerRad, 1) + " deg" +
         (w.removable.marginal ? "?" : ""))
            .c_str(),
        wedge_mode_words(w).c_str(), wedge_fos_text(w.fos).c_str(),
        run.options.bolts || run.options.shotcrete ? wedge_fos_text(w.fos_supported).c_str() : "-");
    lines.push_back(buf);
    for (const auto& c : w.corners) lines.push_back("       " + w.id + " " + c);
  }
  for (const auto& n : a.none)
    lines.push_back("no wedge " + n.code + (n.marginal ? " (marginal)" : "") + ": " + n.reason);
  for (const auto& n : a.notes) lines.push_back("note: " + n);
  return lines;
}

}  // namespace rockface::app
