// A face of many outlines on a printed page (issue 39): the outlines of one
// flat piece told in one line, the others as the Mapping screen tells them.
#include <gtest/gtest.h>

#include "storage/scene/face_outline_words.h"

namespace rockface::storage {
namespace {

Measurement area(const std::string& label, double dip, double dipdir, double rms_m) {
  Measurement m;
  m.kind = Measurement::Kind::area;
  m.label = label;
  m.dip_deg = dip;
  m.dipdir_deg = dipdir;
  m.fit_rms_m = rms_m;
  return m;
}

TEST(FaceOutlineSummary, OutlinesOfOneFlatPieceAreOneLineAndTheOthersTheirOwn) {
  const std::vector<Measurement> areas{area("FACE_W", 80, 90, 0.001),
                                       area("FACE_E", 80, 270, 0.004), area("F1a", 70, 180, 0.006),
                                       area("F1b", 82, 180, 0.007), area("FLOOR", 0, 0, 0.002)};
  const auto lines = face_outline_summary(areas, {});
  ASSERT_EQ(lines.size(), 2u);
  // The largest RMS of the three, 4 mm, rounded to the millimetre as printed.
  EXPECT_EQ(lines[0],
            "3 face outlines, each one flat piece (FACE_W, FACE_E, FLOOR), RMS at most 4 mm");
  // F1's pieces dip 70 and 82 towards 180: their normals 12.0° apart.
  EXPECT_EQ(lines[1], "face outline F1: 2 flat pieces, 12.0° apart, RMS 6 mm / 7 mm");
  // Every outline is still told one by one where a line each is wanted.
  EXPECT_EQ(face_outline_words(areas, {}).size(), 4u);
}

TEST(FaceOutlineSummary, OneOutlineOrANotedOneIsToldInFull) {
  const auto one = face_outline_summary({area("F1", 75, 180, 0.003)}, {});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], "face outline F1: one flat piece, RMS 3 mm");
  Measurement noted = area("F2", 75, 180, 0.003);
  noted.note = "fit of few points";
  const auto lines = face_outline_summary({area("F1", 75, 180, 0.003), noted}, {});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], "face outline F2: one flat piece, RMS 3 mm; fit of few points");
}

}  // namespace
}  // namespace rockface::storage
