#include "firmware-app/support/report_support.h"

#include <cmath>

#include "core/common/number_format.h"
#include "firmware-app/support/support_change_text.h"
#include "firmware-app/support/support_json.h"
#include "firmware-app/support/visit_support.h"
#include "storage/field_report/support_pictures.h"

namespace rockface::app {

namespace {

std::string fos_text(const std::optional<double>& v) {
  if (!v) return "-";
  return std::isinf(*v) ? "stable" : format_fixed(*v, 2);
}

}  // namespace

void add_support_to_report(storage::ProjectStore& store, storage::FieldReport& report) {
  if (!store.load_support_classes() && !store.load_support_decision(report.visit_id)) return;
  const VisitSupport s = visit_support(store, report.visit_id);
  storage::ReportedSupport out;
  out.proposals.push_back(
      "Q chart: " +
      (s.q_support
           ? q_support_words(*s.q_support) +
                 (s.q_support->marginal ? " (marginal: " + s.q_support->marginal_note + ")" : "")
           : "none: " + s.q_support_why));
  out.proposals.push_back("Bieniawski 1989: " + (s.rmr_support ? rmr_support_words(*s.rmr_support)
                                                               : "none: " + s.rmr_support_why));
  if (s.rmr_support && s.rmr_support->span_caveat)
    out.proposals.push_back(*s.rmr_support->span_caveat);
  if (s.proposal) {
    out.proposals.push_back("designer's classes: " +
                            (s.proposal->proposed ? "proposed " + *s.proposal->proposed +
                                                        (s.proposal->marginal ? " (marginal)" : "")
                                                  : std::string("none proposed")));
    for (const auto& n : s.proposal->notes) out.proposals.push_back(n);
  }
  if (s.q_point) out.chart = storage::q_chart_picture(s.q_point);
  const analysis::SupportCheck* chosen = nullptr;
  auto check_lines = [&out](const analysis::SupportCheck& c) {
    out.checks.push_back(checks_words(c));
    for (const auto& w : c.wedges)
      for (const auto& f : w.fixes) out.checks.push_back("  " + w.id + ": " + f);
    for (const auto& b : c.blocks)
      for (const auto& f : b.fixes) out.checks.push_back("  block " + b.id + ": " + f);
  };
  for (const auto& c : s.checks) {
    check_lines(c);
    if (s.decision ? c.class_name == s.decision->class_name : !chosen) chosen = &c;
  }
  // The pattern as decided, beside the class unchanged above; its rows
  // are the table's.
  if (s.decided_check) {
    check_lines(*s.decided_check);
    for (const auto& n : s.decided_check->notes) out.checks.push_back("  " + n);
    chosen = &*s.decided_check;
  }
  if (chosen) {
    out.rows_pattern = chosen->class_name;
    for (const auto& w : chosen->wedges)
      out.rows.push_back({w.id, w.place, w.mode, fos_text(w.fos_unsupported),
                          fos_text(w.fos_supported),
                          std::to_string(w.bolts_anchored) + "/" + std::to_string(w.bolts),
                          format_fixed(w.required_bolt_length_m, 2), w.below_target ? "yes" : ""});
    for (const auto& b : chosen->blocks)
      out.rows.push_back({"block " + b.id, "face", b.mode, fos_text(b.fos_unsupported),
                          fos_text(b.fos_supported),
                          std::to_string(b.bolts_anchored) + "/" + std::to_string(b.bolts),
                          format_fixed(b.required_bolt_length_m, 2), b.below_target ? "yes" : ""});
  }
  if (s.decision) {
    const auto& d = *s.decision;
    out.decision.push_back("class " + d.class_name +
                           " (proposed: " + (d.proposed.empty() ? "none" : d.proposed) + ")");
    if (!d.reason.empty()) out.decision.push_back("reason: " + d.reason);
    for (const auto& c : d.changes) out.decision.push_back("change: " + support_change_words(c));
    out.decision.push_back("decided by " + d.decided_by + " at " + d.decided_at);
    if (!d.checks.empty()) out.decision.push_back("checks then: " + d.checks);
    if (s.decided_check) out.decision.push_back("checks now: " + decision_checks_words(s));
  } else {
    out.decision.push_back("not decided yet");
  }
  report.support = std::move(out);
}

}  // namespace rockface::app
