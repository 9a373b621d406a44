#include "firmware-app/support/support_drive.h"

#include <sstream>

#include "core/analysis/support_classes.h"
#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/rockmass/visit_rock_mass.h"

namespace rockface::app {

namespace {

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::vector<RoundSupport> drive_support(storage::ProjectStore& store) {
  std::vector<RoundSupport> out;
  const auto classes = store.load_support_classes();
  // Read once for every round, not once per round (issue 46).
  const RockMassProject project = rock_mass_project(store);
  for (const auto& p : store.list_visit_placements()) {
    RoundSupport r;
    r.visit = p.visit_id;
    r.chainage = p.chainage;
    analysis::VisitFigures f;
    try {
      const rockmass::RockMassFigures rm = visit_rock_mass(store, project, p.visit_id);
      r.rmr = rm.rmr.adjusted.value;
      r.q = rm.q.q;
      f.rmr = r.rmr;
      f.q = r.q;
    } catch (const InputError&) {
      // No traces: RMR and Q open.
    }
    if (classes) {
      const auto proposal = analysis::match_support_classes(*classes, f);
      if (proposal.proposed) r.proposed = *proposal.proposed;
    }
    if (const auto d = store.load_support_decision(p.visit_id)) {
      r.decided = d->class_name;
      r.decided_by = d->decided_by;
      r.decided_at = d->decided_at;
    }
    out.push_back(r);
  }
  return out;
}

std::string drive_support_csv(const std::vector<RoundSupport>& rounds) {
  std::ostringstream s;
  s << "chainage_m,visit,rmr,q,proposed,decided,decided_by,decided_at\n";
  for (const auto& r : rounds)
    s << format_fixed(r.chainage, 2) << "," << r.visit << ","
      << (r.rmr ? format_fixed(*r.rmr, 0) : "") << "," << (r.q ? format_significant(*r.q, 3) : "")
      << "," << csv_field(r.proposed) << "," << csv_field(r.decided) << ","
      << csv_field(r.decided_by) << "," << csv_field(r.decided_at) << "\n";
  return s.str();
}

std::vector<std::string> drive_support_summary(const std::vector<RoundSupport>& rounds) {
  std::vector<std::string> out;
  for (const auto& r : rounds)
    out.push_back("round at " + format_fixed(r.chainage, 2, " m") + " (visit " +
                  std::to_string(r.visit) + "): RMR " + (r.rmr ? format_fixed(*r.rmr, 0) : "open") +
                  ", Q " + (r.q ? format_significant(*r.q, 3) : "open") + "; proposed " +
                  (r.proposed.empty() ? "-" : r.proposed) + ", decided " +
                  (r.decided.empty() ? "-" : r.decided + " by " + r.decided_by));
  return out;
}

}  // namespace rockface::app
