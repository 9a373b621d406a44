#include "core/rockmass/rmr_support_guidelines.h"

#include <array>
#include <cmath>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/rockmass/rmr89.h"
#include "core/rockmass/tolerances.h"

namespace rockface::rockmass {

namespace {

// A span within this fraction of 10 m is the table's tunnel.
constexpr double kTableSpanM = 10.0;
constexpr double kTableSpanRel = 0.15;

const std::array<RmrSupportRow, 5>& rows() {
  static const std::array<RmrSupportRow, 5> r = {{
      {1, "I very good rock", "full face, 3 m advance",
       "generally no support required except spot bolting", "-", "-", 3, 3, std::nullopt,
       std::nullopt, std::nullopt, std::nullopt, 0, 0, false, false, false},
      {2, "II good rock", "full face, 1-1.5 m advance; complete support 20 m from face",
       "locally, bolts in crown 3 m long, spaced 2.5 m, with occasional wire mesh",
       "50 mm in crown where required", "none", 1, 1.5, 3.0, 3.0, 2.5, 2.5, 0.05, 0.05, false,
       false, false},
      {3, "III fair rock",
       "top heading and bench, 1.5-3 m advance in top heading; commence support after each "
       "blast; complete support 10 m from face",
       "systematic bolts 4 m long, spaced 1.5-2 m in crown and walls with wire mesh in crown",
       "50-100 mm in crown and 30 mm in sides", "none", 1.5, 3, 4.0, 4.0, 1.5, 2.0, 0.05, 0.10,
       true, true, false},
      {4, "IV poor rock",
       "top heading and bench, 1.0-1.5 m advance in top heading; install support concurrently "
       "with excavation, 10 m from face",
       "systematic bolts 4-5 m long, spaced 1-1.5 m in crown and walls with wire mesh",
       "100-150 mm in crown and 100 mm in sides",
       "light to medium ribs spaced 1.5 m where required", 1.0, 1.5, 4.0, 5.0, 1.0, 1.5, 0.10, 0.15,
       true, true, true},
      {5, "V very poor rock",
       "multiple drifts, 0.5-1.5 m advance in top heading; install support concurrently with "
       "excavation; shotcrete as soon as possible after blasting",
       "systematic bolts 5-6 m long, spaced 1-1.5 m in crown and walls with wire mesh; bolt invert",
       "150-200 mm in crown, 150 mm in sides and 50 mm on face",
       "medium to heavy ribs spaced 0.75 m with steel lagging and forepoling if required; close "
       "invert",
       0.5, 1.5, 5.0, 6.0, 1.0, 1.5, 0.15, 0.20, true, true, true},
  }};
  return r;
}

}  // namespace

const RmrSupportRow& rmr_support_row(int c) {
  if (c < 1 || c > 5) throw InputError("rock class", std::to_string(c) + " is not I-V (1-5)");
  return rows()[static_cast<std::size_t>(c - 1)];
}

RmrSupport rmr_support_guidelines(double rmr, std::optional<double> span_m) {
  if (!(rmr >= 0 && rmr <= 100))
    throw InputError("RMR", format_significant(rmr, 4) + " is outside 0-100");
  RmrSupport out;
  out.rmr = rmr;
  const int c = rmr_class(rmr);
  out.row = rmr_support_row(c);
  // Class c spans (upper(c), lower(c)]: I > 80, II 60-80, ... V <= 20
  // (rmr_class: a value on a boundary belongs to the class below it).
  const double lower = c == 5 ? -1e300 : 100.0 - 20.0 * c;  // above this
  const double upper = c == 1 ? 1e300 : 120.0 - 20.0 * c;   // up to this
  const double to_lower = rmr - lower, to_upper = upper - rmr;
  if (to_lower <= to_upper) {
    out.margin_points = to_lower;
    out.nearest_other = c + 1;
  } else {
    out.margin_points = to_upper;
    out.nearest_other = c - 1;
  }
  out.marginal = out.margin_points <= kRmrClassMarginalPoints;
  if (out.marginal)
    out.marginal_note = "RMR " + format_fixed(rmr, 0) + " lies within " +
                        format_fixed(kRmrClassMarginalPoints, 0) + " points of class " +
                        rmr_support_row(out.nearest_other).class_name + ": given class " +
                        out.row.class_name;
  out.source =
      "Bieniawski 1989, Table 4.6: 10 m span horseshoe tunnel, vertical stress < 25 MPa, drill "
      "and blast";
  if (!span_m)
    out.span_caveat = "the span is not known: the row is for a 10 m span";
  else if (std::abs(*span_m - kTableSpanM) > kTableSpanRel * kTableSpanM)
    out.span_caveat = "the span is " + format_fixed(*span_m, 1, " m") +
                      ", the table's 10 m: the row is an indication, not a design for this span "
                      "(bolt lengths and shotcrete scale with the span; use the Q chart or the "
                      "designer's classes)";
  return out;
}

}  // namespace rockface::rockmass
