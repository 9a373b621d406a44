// The tablet's Support view (ui::SupportRunner): the round's support as
// `rockface support PROJECT --visit N [--decide CLASS --by NAME --reason
// TEXT] [--change ...]` finds and stores it, laid out in words for the
// three proposals.
#include "core/common/number_format.h"
#include "firmware-app/services/ui_services.h"
#include "firmware-app/support/support_json.h"
#include "firmware-app/support/visit_support.h"

namespace rockface::app {

ui::SupportProposals StoreSupportRunner::support(const std::filesystem::path& project,
                                                 storage::RecordId visit_id,
                                                 const std::optional<ui::SupportChoice>& decide,
                                                 Progress& progress) {
  progress.step(decide ? "storing the decision" : "the round's support", 0.1);
  SupportRequest q;
  q.project = project.string();
  q.visit = visit_id;
  if (decide) {
    q.decide = decide->class_name;
    q.by = decide->by;
    if (!decide->reason.empty()) q.reason = decide->reason;
    q.changes = decide->changes;
  }
  const VisitSupport s = visit_support(q);
  ui::SupportProposals out;
  out.figures = "Visit " + std::to_string(static_cast<long long>(s.visit)) +
                (s.chainage ? " at chainage " + format_fixed(*s.chainage, 2, " m") : "") +
                ": RMR89 " + (s.figures.rmr ? format_fixed(*s.figures.rmr, 0) : "not known") +
                ", Q " + (s.figures.q ? format_significant(*s.figures.q, 3) : "not known");
  if (s.q_support) {
    out.from_q.push_back(q_support_words(*s.q_support));
    if (s.q_support->marginal) out.from_q.push_back("Marginal: " + s.q_support->marginal_note);
  } else {
    out.from_q.push_back("None: " + s.q_support_why);
  }
  if (s.rmr_support) {
    out.from_rmr.push_back(rmr_support_words(*s.rmr_support));
    if (s.rmr_support->span_caveat) out.from_rmr.push_back(*s.rmr_support->span_caveat);
  } else {
    out.from_rmr.push_back("None: " + s.rmr_support_why);
  }
  if (s.classes) {
    for (const auto& c : s.classes->classes) out.classes.push_back(c.name);
    if (s.proposal && s.proposal->proposed) {
      out.proposed = *s.proposal->proposed;
      out.from_classes.push_back("Class " + out.proposed +
                                 (s.proposal->marginal ? " (marginal)" : ""));
    } else {
      out.from_classes.push_back("No class is met");
    }
    if (s.proposal)
      for (const auto& n : s.proposal->notes) out.from_classes.push_back(n);
  } else {
    out.from_classes.push_back(
        "None: the tunnel has no support classes (rockface support --classes FILE)");
  }
  for (const auto& c : s.checks) out.checks.push_back(checks_words(c));
  if (s.decided_check) {
    out.decided_check.push_back(checks_words(*s.decided_check));
    for (const auto& n : s.decided_check->notes) out.decided_check.push_back(n);
  }
  if (s.decision)
    out.decision = ui::SupportDecided{
        s.decision->class_name, s.decision->proposed, s.decision->reason, s.decision->decided_by,
        s.decision->decided_at, s.decision->checks,   s.decision->changes};
  out.notes = s.notes;
  return out;
}

}  // namespace rockface::app
