#pragma once
// The support the Q-system calls for: the support chart of Grimstad &
// Barton (1993) as redrawn in NGI's handbook "Using the Q-system" (2015),
// with the excavation support ratio (ESR) from the handbook's table by the
// excavation's use.
//
// The chart plots Q (0.001-1000, log) against the equivalent dimension
// De = span (or height) / ESR (1-100, log) and divides the plane into nine
// support categories:
//   1 unsupported or spot bolting          6 Sfr 12-15 cm + RRS I + B
//   2 spot bolting (SB)                     7 Sfr > 15 cm + RRS II + B
//   3 B + Sfr 5-6 cm                        8 CCA, or Sfr > 25 cm + RRS III + B
//   4 Sfr 6-9 cm + B                        9 special evaluation
//   5 Sfr 9-12 cm + B
// (B systematic bolting, Sfr fibre reinforced sprayed concrete, RRS
// reinforced ribs of sprayed concrete, CCA cast concrete lining).
//
// Boundaries: the boundary between categories 1 and 2 is Barton's largest
// unsupported span, De = 2 Q^0.4 (Barton 2002). The printed chart's other
// boundaries are hand-drawn; here each is a straight line of the same slope
// (0.4 in log-log) through the category limits read on the chart at
// De = 10 (Q = 10, 4, 1, 0.4, 0.1, 0.022, 0.004 for the boundaries 2|3 to
// 8|9). That is a simplification of the drawing: it matches the chart
// near De = 10 (a 10-13 m road or rail tunnel) and departs from it towards
// the chart's corners, which the result says in its note.
// Checked against the published chart (issue 44): the handbook prints the
// boundaries 2|3 to 8|9 as a drawing only; neither it nor Grimstad &
// Barton (1993) gives equations or tabulated points for them, and none
// were found in the public material searched (handbook excerpts, papers
// re-using the chart, open code that draws it: those overlay a scanned
// image of the chart). What is published as formulas is encoded as such:
// the ESR table, L = 2 + 0.15 B / ESR and the unsupported span 2 ESR
// Q^0.4 (the boundary 1|2). The limits at De = 10 and the spacing lines
// remain readings of the printed chart.
// The bolt spacings (in the shotcreted and the unshotcreted area) are read
// from the chart's spacing lines as functions of Q, the shotcrete
// thickness from the category, the bolt length is L = 2 + 0.15 B / ESR.
//
// Energy absorption of the fibre reinforced sprayed concrete: the 2015
// chart's legend adds to the Sfr of categories 4 to 8 the energy the
// sprayed concrete must absorb in the plate test (EN 14488-5): E500 (500
// J) for category 4, E700 for 5 and 6, E1000 for 7 and 8; categories 1-3
// state none (3's 5-6 cm of Sfr carries no class). The classes come from
// the NGI update of the chart for poor rock (Grimstad, Kankes, Bhasin,
// Magnussen & Kaynia 2002, "Rock mass quality Q used in designing
// reinforced ribs of sprayed concrete and energy absorption", which took
// the energy absorption of the sprayed concrete into the chart). Searched
// for this change (issue 44): that paper's summary and the handbook's
// table of contents are public; the legend's text itself was not found in
// the material searched, so the mapping above is the legend as the 2015
// handbook prints it ("Sfr (E500)+B", "Sfr (E700)+B", "Sfr (E700)+RRS
// I+B", "Sfr (E1000)+RRS II+B", "CCA or Sfr (E1000)+RRS III+B"), to be
// read against the printed chart like its boundaries.
//
// A point on or within kQChartMarginalLog10 of a boundary is given the
// heavier category (the conservative side, the chart's convention that the
// line belongs to the support above it) and marked marginal with the
// category across the line named.
#include <optional>
#include <string>
#include <vector>

namespace rockface::rockmass {

// NGI 2015, Table "ESR": the excavation's use and its ratio.
struct EsrUse {
  const char* key;    // "road_rail_major", ...
  const char* words;  // "power stations, storage rooms, ... major road and railway tunnels"
  double esr;
};
const std::vector<EsrUse>& esr_table();
// The row by key; nullopt for an unknown key.
std::optional<EsrUse> esr_for(const std::string& key);

struct QSupportCategory {
  int number = 0;                                   // 1..9
  const char* name = "";                            // "Sfr 6-9 cm + B"
  const char* words = "";                           // the chart's legend in words
  double shotcrete_min_m = 0, shotcrete_max_m = 0;  // 0 when none
  const char* ribs = "";                            // "", "RRS I", "RRS II", "RRS III"
  // The Sfr's energy absorption class of the 2015 legend, "" none ("E700"),
  // and its energy in joules (0 none).
  const char* energy_class = "";
  int energy_absorption_j = 0;
  bool systematic_bolting = false;
  bool special_evaluation = false;
};
const QSupportCategory& q_support_category(int number);  // 1..9

struct QChartPoint {
  double q = 0;
  double span_m = 0;  // span or height
  double esr = 1;
};

struct QSupport {
  double equivalent_dimension = 0;  // De = span / ESR
  QSupportCategory category;
  // The signed distance in log10 Q from the nearest boundary of the
  // category (>= 0; 0 on the line) and the category across it.
  double margin_log10 = 0;
  int nearest_other = 0;
  bool marginal = false;
  std::string marginal_note;  // "on the line 4|5: given 5 (the heavier); 4 across it"
  double bolt_length_m = 0;   // 2 + 0.15 span / ESR
  std::optional<double> bolt_spacing_shotcreted_m, bolt_spacing_unshotcreted_m;
  double max_unsupported_span_m = 0;  // 2 ESR Q^0.4
  std::string source;                 // the chart and the simplification in words
  std::vector<std::string> notes;
};

// The boundary between categories k and k + 1 (k = 1..8): De on the line
// at a given Q.
double q_chart_boundary_de(int k, double q);

// Throws InputError naming "Q", "span" or "ESR" for a value that is not
// positive and finite. Q outside the chart (0.001-1000) or De outside 1-100
// is answered from the nearest category and said in the notes.
QSupport q_support(const QChartPoint& point);

}  // namespace rockface::rockmass
