// Over- and underbreak per section as CSV (storage/exchange/deviation_csv.h):
// a section the 3D image did not see has its figures empty (unknown), not 0.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "storage/exchange/deviation_csv.h"

namespace {

TEST(DeviationCsv, UnseenSectionsHaveUnknownFiguresNotZero) {
  rockface::tunnel::ProfileDeviation d;
  rockface::tunnel::SectionDeviation seen;
  seen.chainage = 111.25;
  seen.overbreak_area_m2 = 0.4321;
  seen.max_overbreak_m = 0.351;
  seen.seen_fraction = 0.8;
  rockface::tunnel::SectionDeviation unseen;
  unseen.chainage = 111.5;
  d.sections = {seen, unseen};
  std::ostringstream out;
  EXPECT_EQ(rockface::storage::write_deviation_csv(out, d), 2u);
  std::istringstream in(out.str());
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_EQ(header.rfind("chainage,overbreak_m2,underbreak_m2,max_overbreak_m,", 0), 0u);
  EXPECT_EQ(row1.rfind("111.250,0.4321,0.0000,0.351,0.000,0.800,", 0), 0u) << row1;
  EXPECT_EQ(row2.rfind("111.500,,,,,0.000,", 0), 0u) << row2;
}

}  // namespace
