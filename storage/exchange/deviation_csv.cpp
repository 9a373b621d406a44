#include "storage/exchange/deviation_csv.h"

#include "core/common/number_format.h"

namespace rockface::storage {

std::size_t write_deviation_csv(std::ostream& out, const tunnel::ProfileDeviation& deviation) {
  out << "chainage,overbreak_m2,underbreak_m2,max_overbreak_m,max_underbreak_m,seen_fraction,"
         "roof_seen,walls_seen,floor_seen\n";
  for (const auto& s : deviation.sections) {
    // Chainage to 1 mm, areas to 1 cm², depths to 1 mm: the 3D image's own
    // precision is millimetres at best.
    out << format_fixed(s.chainage, 3) << ',';
    if (s.seen_fraction > 0)
      out << format_fixed(s.overbreak_area_m2, 4) << ',' << format_fixed(s.underbreak_area_m2, 4)
          << ',' << format_fixed(s.max_overbreak_m, 3) << ','
          << format_fixed(s.max_underbreak_m, 3);
    else
      out << ",,,";
    out << ',' << format_fixed(s.seen_fraction, 3) << ',' << format_fixed(s.roof_seen, 3) << ','
        << format_fixed(s.walls_seen, 3) << ',' << format_fixed(s.floor_seen, 3) << '\n';
  }
  return deviation.sections.size();
}

}  // namespace rockface::storage
