// Issue 41: `measure --point-sigma` nan, inf, 0 or -1 was taken and stored
// every joint as "orientation unknown"; it is refused (exit 2) naming the
// option and its range, before any file is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/support/cli_run.h"

TEST(PointSigmaCli, NonPositiveOrNonFiniteIsRefusedByName) {
  for (const char* sigma : {"nan", "inf", "0", "-1", "11"}) {
    const auto r = rockface::test::run_rockface(
        std::string("measure /nonexistent/model.ply --traces /nonexistent/picks.json --out "
                    "/nonexistent/m.json --point-sigma ") +
        sigma);
    EXPECT_EQ(r.exit_code, 2) << sigma << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--point-sigma: "), std::string::npos) << sigma << ": " << r.err;
    EXPECT_NE(r.err.find("is outside (0, 10] m"), std::string::npos) << sigma << ": " << r.err;
  }
}
