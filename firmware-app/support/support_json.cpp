#include "firmware-app/support/support_json.h"

#include <cmath>

#include "core/common/number_format.h"
#include "firmware-app/support/support_change_text.h"

namespace rockface::app {

namespace {

using nlohmann::json;

json optional_figure(const std::optional<double>& v, int digits, const char* unit) {
  return v ? json(format_significant(*v, digits, unit)) : json(nullptr);
}

json fos(const std::optional<double>& v) {
  if (!v) return nullptr;
  return std::isinf(*v) ? json("stable") : json(format_fixed(*v, 2));
}

json strings(const std::vector<std::string>& v) {
  return v;
}

json check_json(const analysis::SupportCheck& c) {
  json wedges = json::array(), blocks = json::array();
  for (const auto& w : c.wedges)
    wedges.push_back(
        {{"id", w.id},
         {"place", w.place},
         {"volume", format_significant(w.volume_m3, 3, " m³")},
         {"weight", format_significant(w.weight_n / 1000, 3, " kN")},
         {"mode", w.mode},
         {"fos", fos(w.fos_unsupported)},
         {"fos_supported", fos(w.fos_supported)},
         {"bolts", w.bolts},
         {"bolts_anchored", w.bolts_anchored},
         {"apex_depth", format_fixed(w.apex_depth_m, 2, " m")},
         {"bolts_reach_past_apex", w.bolts_reach_past_apex},
         {"required_bolt_length", format_fixed(w.required_bolt_length_m, 2, " m")},
         {"required_capacity",
          w.required_capacity_n ? json(format_significant(*w.required_capacity_n / 1000, 3, " kN"))
                                : json(nullptr)},
         {"below_target", w.below_target},
         {"fixes", strings(w.fixes)}});
  for (const auto& b : c.blocks)
    blocks.push_back({{"id", b.id},
                      {"mode", b.mode},
                      {"fos", fos(b.fos_unsupported)},
                      {"fos_supported", fos(b.fos_supported)},
                      {"face_bolts", b.bolts},
                      {"face_bolts_anchored", b.bolts_anchored},
                      {"bolt_force", format_significant(b.bolt_force_n / 1000, 3, " kN")},
                      {"shotcrete_force", format_significant(b.shotcrete_force_n / 1000, 3, " kN")},
                      {"required_bolt_length", format_fixed(b.required_bolt_length_m, 2, " m")},
                      {"required_face_force",
                       b.required_face_force_n
                           ? json(format_significant(*b.required_face_force_n / 1000, 3, " kN"))
                           : json(nullptr)},
                      {"below_target", b.below_target},
                      {"fixes", strings(b.fixes)},
                      {"notes", strings(b.notes)}});
  return {{"class", c.class_name},
          {"target_fos", format_fixed(c.target_fos, 2)},
          {"below_target", c.below_target},
          {"wedges", wedges},
          {"blocks", blocks},
          {"notes", strings(c.notes)}};
}

}  // namespace

std::string q_support_words(const rockmass::QSupport& q) {
  std::string s = "category " + std::to_string(q.category.number) + ", " + q.category.name;
  if (q.category.systematic_bolting || q.category.number == 2)
    s += ": bolts " + format_fixed(q.bolt_length_m, 2, " m") + " long";
  if (q.bolt_spacing_shotcreted_m)
    s += ", spaced " + format_fixed(*q.bolt_spacing_shotcreted_m, 1, " m") +
         " in the shotcreted area";
  if (q.bolt_spacing_unshotcreted_m)
    s += ", " + format_fixed(*q.bolt_spacing_unshotcreted_m, 1, " m") + " where not shotcreted";
  if (q.category.shotcrete_max_m > 0)
    s += "; shotcrete " + format_fixed(q.category.shotcrete_min_m * 100, 0) + "-" +
         format_fixed(q.category.shotcrete_max_m * 100, 0, " cm");
  if (*q.category.energy_class)
    s += ", fibre reinforced, energy absorption " + std::string(q.category.energy_class) + " (" +
         std::to_string(q.category.energy_absorption_j) + " J, EN 14488-5 plate)";
  if (*q.category.ribs)
    s += "; reinforced ribs of sprayed concrete (" + std::string(q.category.ribs) + ")";
  return s;
}

std::string rmr_support_words(const rockmass::RmrSupport& r) {
  return std::string("class ") + r.row.class_name + ": " + r.row.excavation +
         "; bolts: " + r.row.rock_bolts + "; shotcrete: " + r.row.shotcrete +
         "; steel sets: " + r.row.steel_sets;
}

json support_json(const VisitSupport& s) {
  json out = {{"format", "rockface-support/1"}, {"visit", s.visit}};
  out["chainage"] = s.chainage ? json(format_fixed(*s.chainage, 2, " m")) : json(nullptr);
  out["rock_mass"] = {
      {"rmr", optional_figure(s.figures.rmr, 3, "")},
      {"rmr_missing", strings(s.figures.rmr_missing)},
      {"q", optional_figure(s.figures.q, 3, "")},
      {"q_missing", strings(s.figures.q_missing)},
      {"behaviour", s.figures.behaviour ? json(*s.figures.behaviour) : json(nullptr)},
      {"largest_wedge", optional_figure(s.figures.largest_wedge_volume_m3, 3, " m³")},
      {"largest_wedge_apex", optional_figure(s.figures.largest_wedge_apex_m, 3, " m")},
      {"span", optional_figure(s.span_m, 3, " m")},
      {"esr", optional_figure(s.esr, 3, "")},
      {"esr_source", s.esr_source}};
  if (s.q_support) {
    const auto& q = *s.q_support;
    out["q_chart"] = {
        {"category", q.category.number},
        {"support", q.category.name},
        {"words", q_support_words(q)},
        {"equivalent_dimension", format_significant(q.equivalent_dimension, 3, " m")},
        {"bolt_length", format_fixed(q.bolt_length_m, 2, " m")},
        {"bolt_spacing_shotcreted", optional_figure(q.bolt_spacing_shotcreted_m, 2, " m")},
        {"bolt_spacing_unshotcreted", optional_figure(q.bolt_spacing_unshotcreted_m, 2, " m")},
        {"max_unsupported_span", format_fixed(q.max_unsupported_span_m, 2, " m")},
        // The Sfr's energy absorption class of the 2015 chart's legend.
        {"energy_absorption",
         *q.category.energy_class ? json(q.category.energy_class) : json(nullptr)},
        {"energy_absorption_j",
         q.category.energy_absorption_j > 0 ? json(q.category.energy_absorption_j) : json(nullptr)},
        {"marginal", q.marginal},
        {"marginal_note", q.marginal_note},
        {"source", q.source},
        {"notes", strings(q.notes)}};
  } else {
    out["q_chart"] = {{"none", s.q_support_why}};
  }
  if (s.rmr_support) {
    const auto& r = *s.rmr_support;
    out["bieniawski"] = {{"class", r.row.class_name},
                         {"excavation", r.row.excavation},
                         {"rock_bolts", r.row.rock_bolts},
                         {"shotcrete", r.row.shotcrete},
                         {"steel_sets", r.row.steel_sets},
                         {"marginal", r.marginal},
                         {"marginal_note", r.marginal_note},
                         {"source", r.source},
                         {"span_caveat", r.span_caveat ? json(*r.span_caveat) : json(nullptr)}};
  } else {
    out["bieniawski"] = {{"none", s.rmr_support_why}};
  }
  if (s.proposal) {
    json matches = json::array();
    for (const auto& m : s.proposal->matches) {
      json checks = json::array();
      for (const auto& c : m.checks)
        checks.push_back(
            {{"criterion", c.criterion}, {"status", words(c.status)}, {"words", c.words}});
      matches.push_back({{"class", m.name}, {"status", words(m.status)}, {"criteria", checks}});
    }
    out["classes"] = {
        {"source", s.classes->source},
        {"proposed", s.proposal->proposed ? json(*s.proposal->proposed) : json(nullptr)},
        {"marginal", s.proposal->marginal},
        {"matches", matches},
        {"notes", strings(s.proposal->notes)}};
  } else {
    out["classes"] = nullptr;
  }
  json checks = json::array();
  for (const auto& c : s.checks) checks.push_back(check_json(c));
  out["checks"] = checks;
  // The pattern as decided (the chosen class with the decision's changes);
  // null when the decision changes nothing: its class's check above is it.
  out["decided_check"] = s.decided_check ? check_json(*s.decided_check) : json(nullptr);
  if (s.decision) {
    json changes = json::array();
    for (const auto& c : s.decision->changes)
      changes.push_back({{"what", c.what}, {"from", c.from}, {"to", c.to}, {"reason", c.reason}});
    out["decision"] = {{"class", s.decision->class_name},
                       {"proposed", s.decision->proposed},
                       {"changes", changes},
                       {"reason", s.decision->reason},
                       {"decided_by", s.decision->decided_by},
                       {"decided_at", s.decision->decided_at},
                       {"checks", s.decision->checks}};
  } else {
    out["decision"] = nullptr;
  }
  out["notes"] = strings(s.notes);
  return out;
}

std::vector<std::string> support_summary(const VisitSupport& s) {
  std::vector<std::string> out;
  out.push_back("visit " + std::to_string(s.visit) +
                (s.chainage ? " at chainage " + format_fixed(*s.chainage, 2, " m") : "") +
                ": RMR89 " + (s.figures.rmr ? format_fixed(*s.figures.rmr, 0) : "open") + ", Q " +
                (s.figures.q ? format_significant(*s.figures.q, 3) : "open"));
  out.push_back(
      "Q chart: " +
      (s.q_support
           ? q_support_words(*s.q_support) +
                 (s.q_support->marginal ? " (marginal: " + s.q_support->marginal_note + ")" : "")
           : "none: " + s.q_support_why));
  out.push_back("Bieniawski: " +
                (s.rmr_support ? rmr_support_words(*s.rmr_support) : "none: " + s.rmr_support_why));
  if (s.rmr_support && s.rmr_support->span_caveat)
    out.push_back("  " + *s.rmr_support->span_caveat);
  if (s.proposal)
    out.push_back("classes: " + (s.proposal->proposed
                                     ? "proposed " + *s.proposal->proposed +
                                           (s.proposal->marginal ? " (marginal)" : "")
                                     : std::string("none proposed")));
  else
    out.push_back("classes: none stored for the tunnel (--classes FILE)");
  if (s.proposal)
    for (const auto& n : s.proposal->notes) out.push_back("  " + n);
  auto check_lines = [&out](const analysis::SupportCheck& c) {
    out.push_back("check " + checks_words(c));
    for (const auto& w : c.wedges)
      for (const auto& f : w.fixes) out.push_back("  " + w.id + ": " + f);
    for (const auto& b : c.blocks)
      for (const auto& f : b.fixes) out.push_back("  block " + b.id + ": " + f);
  };
  for (const auto& c : s.checks) check_lines(c);
  if (s.decided_check) {
    check_lines(*s.decided_check);
    for (const auto& n : s.decided_check->notes) out.push_back("  " + n);
  }
  if (s.decision)
    out.push_back("decision: " + s.decision->class_name + " by " + s.decision->decided_by + " at " +
                  s.decision->decided_at +
                  (s.decision->reason.empty() ? "" : " (" + s.decision->reason + ")"));
  if (s.decision)
    for (const auto& c : s.decision->changes) out.push_back("  change: " + support_change_words(c));
  for (const auto& n : s.notes) out.push_back("note: " + n);
  return out;
}

}  // namespace rockface::app
