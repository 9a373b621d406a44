#pragma once
// Bieniawski's guidelines for excavation and support of rock tunnels by
// RMR class (Bieniawski 1989, Table 4.6): a 10 m span horseshoe tunnel,
// vertical stress below 25 MPa, drill and blast. Each row as the table
// prints it (excavation, rock bolts, shotcrete, steel sets) and its figures
// (advance, bolt length and spacing, shotcrete in the crown) for the
// comparison with the other proposals.
//
// The table is for that tunnel only: for another span (or shape, or
// method) the result says plainly that the row is an indication, not a
// design (the table's own heading names the 10 m span).
// An RMR within kRmrClassMarginalPoints of a class boundary keeps its class
// (the table's: 81-100 I, 61-80 II, 41-60 III, 21-40 IV, < 21 V) and is
// marked marginal with the class across the boundary named.
#include <optional>
#include <string>
#include <vector>

namespace rockface::rockmass {

struct RmrSupportRow {
  int rock_class = 0;           // 1..5
  const char* class_name = "";  // "III fair rock"
  const char* excavation = "";
  const char* rock_bolts = "";
  const char* shotcrete = "";
  const char* steel_sets = "";
  // Figures of the row (0 / nullopt where the row has none).
  double advance_min_m = 0, advance_max_m = 0;
  std::optional<double> bolt_length_min_m, bolt_length_max_m;
  std::optional<double> bolt_spacing_min_m, bolt_spacing_max_m;
  double shotcrete_crown_min_m = 0, shotcrete_crown_max_m = 0;
  bool systematic_bolts = false, wire_mesh = false, steel_ribs = false;
};
const RmrSupportRow& rmr_support_row(int rock_class);  // 1..5; InputError otherwise

struct RmrSupport {
  double rmr = 0;
  RmrSupportRow row;
  double margin_points = 0;  // distance to the nearest class boundary
  int nearest_other = 0;     // the class across it
  bool marginal = false;
  std::string marginal_note;
  std::string source;                      // the table and its conditions in words
  std::optional<std::string> span_caveat;  // when the span is not about 10 m
};

// span_m: the tunnel's span when known (a caveat when it is not 10 m
// within 15 %, or unknown). Throws InputError("RMR") outside 0-100.
RmrSupport rmr_support_guidelines(double rmr, std::optional<double> span_m);

}  // namespace rockface::rockmass
