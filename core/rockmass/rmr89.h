#pragma once
// Bieniawski's Rock Mass Rating, 1989 version (Bieniawski 1989, Engineering
// Rock Mass Classifications, Table 4.1: A parameters and ratings, B rating
// adjustment for discontinuity orientations, C classes, E guidelines for
// the condition of discontinuities; Table 4.6 guidelines for excavation
// and support of 10 m span rock tunnels). The tables' class ratings are
// used as printed (steps), not the continuous charts: the sheet the
// geologist fills is the table.
//
// RMR89 = A1 strength + A2 RQD + A3 spacing + A4 condition + A5 groundwater
//         + B orientation adjustment (tunnels).
#include <optional>
#include <string>

#include "core/rockmass/classification_form.h"
#include "core/rockmass/rating.h"

namespace rockface::rockmass {

// What the visit's figures give the sheet (each nullopt when not measured).
struct MeasuredForRmr {
  std::optional<double> rqd_percent;
  std::optional<double> spacing_m;      // the set with the smallest spacing (the sheet's rule)
  std::string spacing_set;              // its label
  std::optional<double> persistence_m;  // longest set persistence estimable
  // The least favourable set against the drive (core/tunnel/strike_vs_drive.h)
  // and what decided it ("S2: strike parallel to the axis, dip 45-90").
  std::optional<OrientationClass> orientation;
  std::string orientation_words;
};

struct Rmr89 {
  Rating strength, rqd, spacing, condition, groundwater, orientation;
  Total basic;     // A1..A5 (RMR basic, without the adjustment)
  Total adjusted;  // with B: the tunnel's RMR89
  // Class of the adjusted total when complete, else of the basic when
  // complete (said so in class_words), else none.
  std::optional<int> rock_class;  // 1..5 (I..V)
  std::string class_words;        // "II good rock"
  std::string support;            // Table 4.6 for the class (10 m span, horseshoe, drill and blast)
};

// The table functions, one per line of the sheet (exposed for the tests and
// the form's live preview).
double rmr_strength_ucs(double ucs_mpa);  // A.1
// A.1 by point-load index; nullopt below 1 MPa (the table asks for UCS there).
std::optional<double> rmr_strength_is50(double is50_mpa);
double rmr_rqd(double rqd_percent);           // A.2
double rmr_spacing(double spacing_m);         // A.3
double rmr_persistence(double length_m);      // E
double rmr_aperture(double aperture_mm);      // E
double rmr_roughness(Roughness r);            // E
double rmr_infilling(Infilling i);            // E
double rmr_weathering(Weathering w);          // E
double rmr_groundwater(Groundwater g);        // A.5 general conditions
double rmr_inflow(double l_per_min_per_10m);  // A.5 inflow
double rmr_orientation(OrientationClass c);   // B, tunnels
int rmr_class(double rmr);                    // C: 1..5
const char* rmr_class_words(int rock_class);  // "very good rock", ...
const char* rmr_support(int rock_class);      // Table 4.6

// Throws InputError (via validate) for an entered value out of range.
Rmr89 rmr89(const MeasuredForRmr& measured, const ClassificationForm& form);

}  // namespace rockface::rockmass
