// Traces as CSV for Dips (storage/exchange/traces_csv.h): one row per trace,
// its set through its joint, its middle halfway along it (not the mean of
// its points), absolute coordinates, unknown orientation left empty.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "storage/exchange/traces_csv.h"

namespace {

using rockface::storage::Joint;
using rockface::storage::Measurement;

TEST(TracesCsv, RowPerTraceWithItsSetMiddleAndEnds) {
  Measurement t;
  t.label = "T1";
  t.joint_label = "J3";
  t.visit_id = 2;
  // Densely picked near its start: the mean of the points would lie at
  // x = 0.3, the middle along it at x = 1.
  t.points = {{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {2, 0, 0}};
  t.dip_deg = 62.5;
  t.dipdir_deg = 201.25;
  t.trace_length_m = 2;
  Measurement unfitted = t;
  unfitted.label = "T2, east";  // a comma: quoted
  unfitted.joint_label.clear();
  unfitted.dip_deg.reset();
  unfitted.dipdir_deg.reset();
  unfitted.censored = true;
  Measurement area = t;
  area.kind = Measurement::Kind::area;
  Joint j;
  j.label = "J3";
  j.set_label = "S1";
  std::ostringstream out;
  const Eigen::Vector3d datum{512340, 5211870, 410};
  EXPECT_EQ(rockface::storage::write_traces_csv(out, {t, unfitted, area}, {j}, datum), 2u);
  std::istringstream in(out.str());
  std::string header, row1, row2, extra;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(row1,
            "T1,62.500,201.250,S1,J3,2.000,no,512341.0000,5211870.0000,410.0000,"
            "512340.0000,5211870.0000,410.0000,512342.0000,5211870.0000,410.0000,hand,2");
  EXPECT_EQ(row2.rfind("\"T2, east\",,,,,2.000,yes,", 0), 0u) << row2;
}

}  // namespace
