#pragma once
// Barton's Q (Barton, Lien & Lunde 1974; tables as revised in Barton 2002,
// "Some new Q-value correlations to assist in site characterisation and
// tunnel design", IJRMMS 39):
//
//   Q = (RQD / Jn) (Jr / Ja) (Jw / SRF),   RQD below 10 taken as 10.
//
// RQD and Jn come from the visit (measured); Jr, Ja, Jw, SRF from the form.
// Classes (Barton 1974): exceptionally poor < 0.01 < extremely poor < 0.1 <
// very poor < 1 < poor < 4 < fair < 10 < good < 40 < very good < 100 <
// extremely good < 400 < exceptionally good. The support figures are
// Barton's formulas (1974, 2002), given where the span and ESR are known:
// the equivalent dimension De = span / ESR, the largest span left
// unsupported 2 ESR Q^0.4, the roof bolt length 2 + 0.15 span / ESR, and
// the roof support pressure (2 / Jr) Q^(-1/3) (x 98.1 kPa per kg/cm2).
#include <optional>
#include <string>

#include "core/rockmass/classification_form.h"
#include "core/rockmass/rating.h"

namespace rockface::rockmass {

struct MeasuredForQ {
  std::optional<double> rqd_percent;
  std::optional<int> sets;     // joint sets found on the face
  bool random_joints = false;  // traces belonging to no set
};

struct QSystem {
  Rating rqd, jn, jr, ja, jw, srf;
  std::optional<double> q;  // complete only
  // When open: the known factors' product and what the open ones could
  // still make of it (each open factor over its table's range).
  std::optional<double> q_lowest, q_highest;
  std::vector<std::string> missing;
  std::string class_words;  // "fair", "" when Q is not complete
  // Support figures (when Q, ESR and span are known).
  std::optional<double> equivalent_dimension, max_unsupported_span_m, bolt_length_m,
      roof_pressure_kpa;
  std::string support;  // in words
};

// Table Jn by the number of sets and random joints (Barton 2002, items A-H).
double jn_from_sets(int sets, bool random_joints);
std::string jn_words(int sets, bool random_joints);  // "three sets plus random"
const char* q_class_words(double q);

QSystem q_system(const MeasuredForQ& measured, const ClassificationForm& form);

}  // namespace rockface::rockmass
