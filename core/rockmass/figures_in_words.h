#pragma once
// The rock-mass figures as the lines a geologist reads: on the command
// line, the tablet's Rock mass view and the field report. Units always
// written; every rating with its source and table.
#include <string>
#include <vector>

#include "core/rockmass/rock_mass_figures.h"

namespace rockface::rockmass {

// "RQD: 72 % -> 13 (measured; Bieniawski 1989, Table 4.1 A.2)", or
// "groundwater: not entered (Bieniawski 1989, Table 4.1 A.5)".
std::string rating_line(const Rating& r);
// "RMR89 62 (II good rock)" or "RMR89 incomplete: 32 so far, 32-92 with
// strength, condition, groundwater not entered".
std::string rmr_line(const Rmr89& r);
std::string q_line(const QSystem& q);

// The figures: sets and spacing, RQD, Jv, block sizes, persistence.
std::vector<std::string> figures_lines(const RockMassFigures& f);
// Both classifications line by line.
std::vector<std::string> classification_lines(const RockMassFigures& f);

}  // namespace rockface::rockmass
