// Issue 41: `measure --friction` (the stereonet's sliding overlay) took nan,
// inf, 0, 90 or 1e308; it is refused (exit 2) naming the option and its
// range, before any file is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/support/cli_run.h"

TEST(FrictionCli, OutsideZeroToNinetyOrNonFiniteIsRefusedByName) {
  for (const char* friction : {"nan", "inf", "0", "-5", "90", "1e308"}) {
    const auto r = rockface::test::run_rockface(
        std::string("measure /nonexistent/model.ply --traces /nonexistent/picks.json --out "
                    "/nonexistent/m.json --friction ") +
        friction);
    EXPECT_EQ(r.exit_code, 2) << friction << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--friction: "), std::string::npos) << friction << ": " << r.err;
    EXPECT_NE(r.err.find("is outside (0, 90) degrees"), std::string::npos)
        << friction << ": " << r.err;
  }
}
