#pragma once
// The classification form the support suites fill on their visit (the
// command line's `rockface support` and the tablet's Support view): RMR89's
// lines and Q's, a damp rock of 80 MPa with RQD 70 and joints 0.5 m apart,
// Jr 1.5, Ja 2, Jw 1, SRF 1, ESR 1.3. A suite takes from it or adds to it.
#include "core/rockmass/classification_form.h"

namespace rockface::test {

inline rockmass::ClassificationForm sample_support_form() {
  rockmass::ClassificationForm f;
  f.ucs_mpa = 80;
  f.condition_rating = 15;
  f.groundwater = rockmass::Groundwater::damp;
  f.rqd_percent = 70;
  f.spacing_m = 0.5;
  f.jr = 1.5;
  f.ja = 2;
  f.jw = 1;
  f.srf = 1;
  f.esr = 1.3;
  return f;
}

}  // namespace rockface::test
