#include "core/analysis/support_classes.h"

#include <algorithm>
#include <cmath>

#include "core/common/number_format.h"
#include "core/rockmass/tolerances.h"

namespace rockface::analysis {

namespace {

std::string words_list(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string range_words(const FigureRange& r) {
  return "[" + (r.min ? format_significant(*r.min, 4) : std::string("-")) + ", " +
         (r.max ? format_significant(*r.max, 4) : std::string("-")) + ")";
}

// The distance from v to a range's end in the figure's own measure: RMR in
// points, Q in log10 (its tables multiply).
double distance(double v, double end, bool logarithmic) {
  return logarithmic ? std::abs(std::log10(v / end)) : std::abs(v - end);
}

CriterionCheck check_range(const char* name, const FigureRange& r, const std::optional<double>& v,
                           const std::vector<std::string>& missing, bool logarithmic) {
  CriterionCheck c;
  c.criterion = name;
  const std::string range = range_words(r);
  if (!v) {
    c.status = CriterionStatus::unknown;
    c.words = std::string(name) + " " + range + ": " + name + " is open" +
              (missing.empty() ? std::string() : " (not entered: " + words_list(missing) + ")");
    return c;
  }
  const double tol =
      logarithmic ? rockmass::kQChartMarginalLog10 : rockmass::kRmrClassMarginalPoints;
  const std::string value = std::string(name) + " " + format_significant(*v, 3);
  const bool above_min = !r.min || *v >= *r.min;
  const bool below_max = !r.max || *v < *r.max;
  if (!(above_min && below_max)) {
    c.status = CriterionStatus::not_met;
    c.words = value + " outside " + range;
    return c;
  }
  double nearest = 1e300;
  if (r.min) nearest = std::min(nearest, distance(*v, *r.min, logarithmic));
  if (r.max) nearest = std::min(nearest, distance(*v, *r.max, logarithmic));
  if (nearest <= tol) {
    c.status = CriterionStatus::marginal;
    c.words = value + " in " + range + ", at its end (marginal: within " +
              (logarithmic ? std::string("10 %") : format_fixed(tol, 0) + " points") + ")";
  } else {
    c.status = CriterionStatus::met;
    c.words = value + " in " + range;
  }
  return c;
}

CriterionCheck check_upper(const char* name, double max, const std::optional<double>& v, bool known,
                           const char* unit) {
  CriterionCheck c;
  c.criterion = name;
  const std::string limit = "up to " + format_significant(max, 3, unit);
  if (!known) {
    c.status = CriterionStatus::unknown;
    c.words = std::string(name) + " " + limit + ": no wedge analysis for this visit";
  } else if (!v || *v <= max) {
    c.status = CriterionStatus::met;
    c.words = std::string(name) + " " +
              (v ? format_significant(*v, 3, unit) : std::string("none")) + ", " + limit;
  } else {
    c.status = CriterionStatus::not_met;
    c.words = std::string(name) + " " + format_significant(*v, 3, unit) + " over " +
              format_significant(max, 3, unit);
  }
  return c;
}

int severity(CriterionStatus s) {
  switch (s) {
    case CriterionStatus::met:
      return 0;
    case CriterionStatus::marginal:
      return 1;
    case CriterionStatus::unknown:
      return 2;
    case CriterionStatus::not_met:
      return 3;
  }
  return 3;
}

}  // namespace

double target_fos(const SupportClass& c) {
  return c.target_fos.value_or(kDefaultTargetFos);
}

const char* words(CriterionStatus s) {
  switch (s) {
    case CriterionStatus::met:
      return "met";
    case CriterionStatus::marginal:
      return "marginal";
    case CriterionStatus::not_met:
      return "not met";
    case CriterionStatus::unknown:
      return "unknown";
  }
  return "unknown";
}

const SupportClass* find_class(const SupportClasses& classes, const std::string& name) {
  for (const auto& c : classes.classes)
    if (c.name == name) return &c;
  return nullptr;
}

ClassProposal match_support_classes(const SupportClasses& classes, const VisitFigures& v) {
  ClassProposal out;
  for (const auto& cls : classes.classes) {
    ClassMatch m;
    m.name = cls.name;
    const SupportCriteria& k = cls.criteria;
    if (k.rmr) m.checks.push_back(check_range("RMR", *k.rmr, v.rmr, v.rmr_missing, false));
    if (k.q) m.checks.push_back(check_range("Q", *k.q, v.q, v.q_missing, true));
    if (!k.behaviour.empty()) {
      CriterionCheck c;
      c.criterion = "behaviour";
      const std::string wanted = words_list(k.behaviour);
      if (!v.behaviour) {
        c.status = CriterionStatus::unknown;
        c.words = "behaviour " + wanted + ": not known (no wedges or blocks analysed)";
      } else if (std::find(k.behaviour.begin(), k.behaviour.end(), *v.behaviour) !=
                 k.behaviour.end()) {
        c.status = CriterionStatus::met;
        c.words = "behaviour " + *v.behaviour;
      } else {
        c.status = CriterionStatus::not_met;
        c.words = "behaviour " + *v.behaviour + ", not " + wanted;
      }
      m.checks.push_back(c);
    }
    if (k.max_wedge_volume_m3)
      m.checks.push_back(check_upper("wedge volume", *k.max_wedge_volume_m3,
                                     v.largest_wedge_volume_m3, v.wedges_known, " m³"));
    if (k.max_wedge_apex_m)
      m.checks.push_back(check_upper("wedge apex", *k.max_wedge_apex_m, v.largest_wedge_apex_m,
                                     v.wedges_known, " m"));
    m.status = m.checks.empty() ? CriterionStatus::unknown : CriterionStatus::met;
    for (const auto& c : m.checks)
      if (severity(c.status) > severity(m.status)) m.status = c.status;
    out.matches.push_back(std::move(m));
  }
  // The heaviest class met (marginally or not).
  std::vector<const ClassMatch*> met;
  for (const auto& m : out.matches)
    if (m.status == CriterionStatus::met || m.status == CriterionStatus::marginal)
      met.push_back(&m);
  if (!met.empty()) {
    const ClassMatch& p = *met.back();
    out.proposed = p.name;
    out.marginal = p.status == CriterionStatus::marginal;
    for (const auto& c : p.checks)
      if (c.status == CriterionStatus::marginal) out.notes.push_back(p.name + ": " + c.words);
    for (std::size_t i = 0; i + 1 < met.size(); ++i)
      out.notes.push_back(met[i]->name + " is also met; the heavier " + p.name + " is proposed");
  } else {
    bool unknown = false;
    for (const auto& m : out.matches)
      if (m.status == CriterionStatus::unknown) {
        unknown = true;
        for (const auto& c : m.checks)
          if (c.status == CriterionStatus::unknown) out.notes.push_back(m.name + ": " + c.words);
      }
    out.notes.push_back(unknown ? "no class proposed: a criterion is unknown (above)"
                                : "no class proposed: the visit meets no class's criteria");
  }
  if (!v.rmr && !v.rmr_missing.empty())
    out.notes.push_back("RMR open: " + words_list(v.rmr_missing) + " not entered");
  if (!v.q && !v.q_missing.empty())
    out.notes.push_back("Q open: " + words_list(v.q_missing) + " not entered");
  return out;
}

}  // namespace rockface::analysis
