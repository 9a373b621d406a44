#include "core/rockmass/q_system.h"

#include <algorithm>
#include <cmath>

#include "core/common/number_format.h"

namespace rockface::rockmass {

namespace {

constexpr const char* kTableRqd = "Barton 2002, Table RQD (Deere 1964; below 10 taken as 10)";
constexpr const char* kTableJn = "Barton 2002, Table Jn (joint set number)";
constexpr const char* kTableJr = "Barton 2002, Table Jr (joint roughness number)";
constexpr const char* kTableJa = "Barton 2002, Table Ja (joint alteration number)";
constexpr const char* kTableJw = "Barton 2002, Table Jw (joint water reduction factor)";
constexpr const char* kTableSrf = "Barton 2002, Table SRF (stress reduction factor)";

Rating entered(const char* parameter, const std::optional<double>& v, const char* table) {
  Rating r;
  r.parameter = parameter;
  r.table = table;
  if (v) {
    r.value = v;
    r.rating = v;
    r.value_words = format_fixed(*v, 2);
    r.source = Source::entered;
  }
  return r;
}

}  // namespace

double jn_from_sets(int sets, bool random) {
  if (sets <= 0) return random ? 2.0 : 1.0;  // massive, no or few joints: 0.5-1 (the upper end)
  if (sets == 1) return random ? 3.0 : 2.0;
  if (sets == 2) return random ? 6.0 : 4.0;
  if (sets == 3) return random ? 12.0 : 9.0;
  return 15.0;
}

std::string jn_words(int sets, bool random) {
  static constexpr const char* n[] = {"no set", "one set", "two sets", "three sets"};
  if (sets >= 4) return "four or more sets";
  if (sets <= 0) return random ? "random joints only (taken as one set)" : "massive, few joints";
  return std::string(n[sets]) + (random ? " plus random" : "");
}

const char* q_class_words(double q) {
  if (q < 0.01) return "exceptionally poor";
  if (q < 0.1) return "extremely poor";
  if (q < 1) return "very poor";
  if (q < 4) return "poor";
  if (q < 10) return "fair";
  if (q < 40) return "good";
  if (q < 100) return "very good";
  if (q < 400) return "extremely good";
  return "exceptionally good";
}

QSystem q_system(const MeasuredForQ& m, const ClassificationForm& f) {
  validate(f);
  QSystem out;
  out.rqd.parameter = "RQD";
  out.rqd.unit = "%";
  out.rqd.table = kTableRqd;
  if (m.rqd_percent) {
    out.rqd.value = m.rqd_percent;
    out.rqd.source = Source::measured;
    if (f.rqd_percent) out.rqd.note = "entered " + format_fixed(*f.rqd_percent, 0) + " % not used";
  } else if (f.rqd_percent) {
    out.rqd.value = f.rqd_percent;
    out.rqd.source = Source::entered;
  }
  if (out.rqd.value) {
    out.rqd.rating = std::max(10.0, *out.rqd.value);
    out.rqd.value_words = format_fixed(*out.rqd.value, 0) + " %";
    if (*out.rqd.value < 10) out.rqd.note = "below 10: taken as 10";
  }

  out.jn.parameter = "Jn";
  out.jn.table = kTableJn;
  if (m.sets) {
    out.jn.rating = jn_from_sets(*m.sets, m.random_joints);
    out.jn.value = out.jn.rating;
    out.jn.value_words = jn_words(*m.sets, m.random_joints);
    out.jn.source = Source::measured;
    if (f.jn) out.jn.note = "entered " + format_fixed(*f.jn, 1) + " not used";
  } else if (f.jn) {
    out.jn = entered("Jn", f.jn, kTableJn);
  }
  out.jr = entered("Jr", f.jr, kTableJr);
  out.ja = entered("Ja", f.ja, kTableJa);
  out.jw = entered("Jw", f.jw, kTableJw);
  out.srf = entered("SRF", f.srf, kTableSrf);

  // Q and, when open, its reach: numerators at their table's ends over
  // denominators at theirs.
  struct Factor {
    const Rating* r;
    double lo, hi;
    bool numerator;
  };
  const Factor factors[] = {{&out.rqd, 10, 100, true}, {&out.jn, 0.5, 20, false},
                            {&out.jr, 0.5, 5, true},   {&out.ja, 0.75, 20, false},
                            {&out.jw, 0.05, 1, true},  {&out.srf, 0.5, 400, false}};
  double low = 1, high = 1;
  for (const auto& x : factors) {
    if (x.r->rating) {
      const double v = x.numerator ? *x.r->rating : 1.0 / *x.r->rating;
      low *= v;
      high *= v;
    } else {
      out.missing.push_back(x.r->parameter);
      low *= x.numerator ? x.lo : 1.0 / x.hi;
      high *= x.numerator ? x.hi : 1.0 / x.lo;
    }
  }
  if (out.missing.empty()) {
    out.q = low;
    out.class_words = q_class_words(*out.q);
  } else {
    out.q_lowest = low;
    out.q_highest = high;
  }

  if (out.q && f.esr && f.span_m) {
    const double q = *out.q, esr = *f.esr, span = *f.span_m;
    out.equivalent_dimension = span / esr;
    out.max_unsupported_span_m = 2 * esr * std::pow(q, 0.4);
    out.bolt_length_m = 2 + 0.15 * span / esr;
    out.roof_pressure_kpa = 98.1 * (2.0 / *out.jr.rating) * std::pow(q, -1.0 / 3.0);
    out.support =
        span <= *out.max_unsupported_span_m
            ? "the span " + format_fixed(span, 1) + " m is within the largest unsupported span " +
                  format_fixed(*out.max_unsupported_span_m, 1) + " m (2 ESR Q^0.4)"
            : "support needed: span " + format_fixed(span, 1) + " m over the largest unsupported " +
                  format_fixed(*out.max_unsupported_span_m, 1) + " m; roof bolts " +
                  format_fixed(*out.bolt_length_m, 1) + " m (2 + 0.15 B/ESR), roof pressure " +
                  format_fixed(*out.roof_pressure_kpa, 0) + " kPa";
  }
  return out;
}

}  // namespace rockface::rockmass
