#include "core/rockmass/q_support_chart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/rockmass/tolerances.h"

namespace rockface::rockmass {

namespace {

// Q of the boundaries 2|3 .. 8|9 where they cross De = 10, read on the
// chart (NGI 2015); the boundary 1|2 is De = 2 Q^0.4 (Q = 55.9 there).
constexpr std::array<double, 7> kBoundaryQAtDe10 = {10, 4, 1, 0.4, 0.1, 0.022, 0.004};
constexpr double kBoundarySlope = 0.4;  // Barton's exponent of the unsupported span

// The chart's spacing lines, (Q, spacing m), log-linear between them and
// held at the ends.
constexpr std::array<std::pair<double, double>, 8> kSpacingShotcreted = {
    {{0.01, 1.0}, {0.04, 1.3}, {0.1, 1.5}, {0.4, 1.7}, {1, 2.0}, {2, 2.1}, {4, 2.3}, {10, 2.5}}};
constexpr std::array<std::pair<double, double>, 3> kSpacingUnshotcreted = {
    {{1, 2.0}, {4, 2.5}, {10, 3.0}}};

template <std::size_t N>
double spacing_at(const std::array<std::pair<double, double>, N>& line, double q) {
  if (q <= line.front().first) return line.front().second;
  if (q >= line.back().first) return line.back().second;
  for (std::size_t i = 1; i < N; ++i)
    if (q <= line[i].first) {
      const double t = (std::log10(q) - std::log10(line[i - 1].first)) /
                       (std::log10(line[i].first) - std::log10(line[i - 1].first));
      return line[i - 1].second + t * (line[i].second - line[i - 1].second);
    }
  return line.back().second;
}

// log10 of the boundary's Q at De: the line De = a Q^0.4 solved for Q.
double boundary_log10_q(int k, double de) {
  if (k == 1) return (std::log10(de) - std::log10(2.0)) / kBoundarySlope;
  const double q10 = kBoundaryQAtDe10[static_cast<std::size_t>(k - 2)];
  return std::log10(q10) + (std::log10(de) - 1.0) / kBoundarySlope;
}

const std::array<QSupportCategory, 9>& categories() {
  // The legend of NGI 2015 (the header says each column's source): number,
  // name, words, shotcrete min and max, ribs, systematic bolting, special
  // evaluation, the Sfr's energy absorption class and its joules.
  static const std::array<QSupportCategory, 9> c = {{
      {1, "unsupported or spot bolting", "unsupported or spot bolting", 0, 0, "", "", 0, false,
       false},
      {2, "SB", "spot bolting", 0, 0, "", "", 0, false, false},
      {3, "B + Sfr 5-6 cm", "systematic bolting, fibre reinforced sprayed concrete 5-6 cm", 0.05,
       0.06, "", "", 0, true, false},
      {4, "Sfr 6-9 cm + B", "fibre reinforced sprayed concrete and bolting, 6-9 cm", 0.06, 0.09, "",
       "E500", 500, true, false},
      {5, "Sfr 9-12 cm + B", "fibre reinforced sprayed concrete and bolting, 9-12 cm", 0.09, 0.12,
       "", "E700", 700, true, false},
      {6, "Sfr 12-15 cm + RRS I + B",
       "fibre reinforced sprayed concrete and bolting, 12-15 cm, with reinforced ribs of sprayed "
       "concrete (RRS I)",
       0.12, 0.15, "RRS I", "E700", 700, true, false},
      {7, "Sfr > 15 cm + RRS II + B",
       "fibre reinforced sprayed concrete over 15 cm, reinforced ribs of sprayed concrete (RRS "
       "II) and bolting",
       0.15, 0.25, "RRS II", "E1000", 1000, true, false},
      {8, "CCA or Sfr > 25 cm + RRS III + B",
       "cast concrete lining, or fibre reinforced sprayed concrete over 25 cm with reinforced ribs "
       "of sprayed concrete (RRS III) and bolting",
       0.25, 0.25, "RRS III", "E1000", 1000, true, false},
      {9, "special evaluation", "special evaluation", 0, 0, "", "", 0, false, true},
  }};
  return c;
}

void require_positive(double v, const char* field) {
  if (!(v > 0) || !std::isfinite(v))
    throw InputError(field, format_significant(v, 6) + " is not a positive number");
}

}  // namespace

const std::vector<EsrUse>& esr_table() {
  // NGI 2015, the ESR table (by type of excavation). Temporary mine
  // openings: the table gives "about 3-5"; its middle here.
  static const std::vector<EsrUse> t = {
      {"temporary_mine", "temporary mine openings", 4.0},
      {"shaft_circular", "vertical shafts, circular section", 2.5},
      {"shaft_rectangular", "vertical shafts, rectangular or square section", 2.0},
      {"permanent_mine",
       "permanent mine openings, water tunnels for hydro power (excluding high pressure "
       "penstocks), water supply tunnels, pilot tunnels, drifts and headings for large openings",
       1.6},
      {"road_rail_minor",
       "minor road and railway tunnels, surge chambers, access tunnels, sewage tunnels", 1.3},
      {"road_rail_major",
       "power stations, storage rooms, water treatment plants, major road and railway tunnels, "
       "civil defence chambers, portals, intersections",
       1.0},
      {"public",
       "underground nuclear power stations, railway stations, sports and public facilities, "
       "factories, major gas pipeline tunnels",
       0.8},
      {"long_lifetime",
       "very important caverns and tunnels with a long lifetime (about 100 years) or without "
       "access for maintenance",
       0.5},
  };
  return t;
}

std::optional<EsrUse> esr_for(const std::string& key) {
  for (const auto& e : esr_table())
    if (key == e.key) return e;
  return std::nullopt;
}

const QSupportCategory& q_support_category(int number) {
  if (number < 1 || number > 9)
    throw InputError("category", std::to_string(number) + " is not a Q-chart category (1-9)");
  return categories()[static_cast<std::size_t>(number - 1)];
}

double q_chart_boundary_de(int k, double q) {
  if (k < 1 || k > 8) throw InputError("boundary", std::to_string(k) + " is not 1-8");
  if (k == 1) return 2.0 * std::pow(q, kBoundarySlope);
  const double q10 = kBoundaryQAtDe10[static_cast<std::size_t>(k - 2)];
  return 10.0 * std::pow(q / q10, kBoundarySlope);
}

QSupport q_support(const QChartPoint& p) {
  require_positive(p.q, "Q");
  require_positive(p.span_m, "span");
  require_positive(p.esr, "ESR");
  QSupport out;
  const double de = p.span_m / p.esr;
  out.equivalent_dimension = de;
  const double lq = std::log10(p.q);
  // The boundaries' Q at this De fall as k grows: category k lies between
  // boundary k (its lighter side, higher Q) and boundary k - 1. A point on
  // a line goes to the heavier category (>=).
  int cat = 9;
  for (int k = 1; k <= 8; ++k)
    if (lq > boundary_log10_q(k, de) + kQChartOnLineLog10) {
      cat = k;
      break;
    }
  out.category = q_support_category(cat);
  // Distance to the category's two boundaries (one at the ends).
  double margin = 1e300;
  if (cat >= 2) {  // its lighter neighbour across boundary cat - 1
    const double d = boundary_log10_q(cat - 1, de) - lq;
    if (d < margin) margin = d, out.nearest_other = cat - 1;
  }
  if (cat <= 8) {  // its heavier neighbour across boundary cat
    const double d = lq - boundary_log10_q(cat, de);
    if (d < margin) margin = d, out.nearest_other = cat + 1;
  }
  out.margin_log10 = margin <= kQChartOnLineLog10 ? 0.0 : margin;
  out.marginal = out.margin_log10 <= kQChartMarginalLog10;
  if (out.marginal) {
    const int lo = std::min(cat, out.nearest_other), hi = std::max(cat, out.nearest_other);
    out.marginal_note = "within 10 % of Q of the boundary " + std::to_string(lo) + "|" +
                        std::to_string(hi) + ": given " + std::to_string(cat) +
                        (out.margin_log10 == 0 ? " (on the line: the heavier side)" : "") + "; " +
                        std::to_string(out.nearest_other) + " across it";
  }
  out.bolt_length_m = 2.0 + 0.15 * p.span_m / p.esr;
  out.max_unsupported_span_m = 2.0 * p.esr * std::pow(p.q, 0.4);
  if (out.category.shotcrete_max_m > 0)
    out.bolt_spacing_shotcreted_m = spacing_at(kSpacingShotcreted, p.q);
  if (cat == 2 || cat == 3) out.bolt_spacing_unshotcreted_m = spacing_at(kSpacingUnshotcreted, p.q);
  out.source =
      "Q-system support chart (Grimstad & Barton 1993; NGI 2015); boundaries 2|3 to 8|9 as lines "
      "of slope 0.4 through the chart's limits at De = 10";
  if (p.q < 0.001 || p.q > 1000)
    out.notes.push_back("Q " + format_significant(p.q, 3) + " lies outside the chart (0.001-1000)");
  if (de < 1 || de > 100)
    out.notes.push_back("De " + format_significant(de, 3) + " lies outside the chart (1-100)");
  if (de < 3 || de > 40)
    out.notes.push_back(
        "De " + format_significant(de, 3) +
        " is far from 10, where the simplified boundaries match the printed chart best: read the "
        "chart itself before signing");
  return out;
}

}  // namespace rockface::rockmass
