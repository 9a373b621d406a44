// The report's tables laid out from measured widths (issue 39): cells wrap
// inside their column, columns never meet, the table stays within the
// page, and the type shrinks only when the widest words do not fit. The
// measure here is a monospace stand-in (every character the same advance),
// so every width below is counted by hand.
#include <gtest/gtest.h>

#include "storage/field_report/table_layout.h"

namespace rockface::storage {
namespace {

// Half the type size per character, a tenth more when bold: the proportions
// of a sans-serif, exact here so the layout's sums can be checked exactly.
double monospace(const std::string& text, double size, bool bold) {
  return static_cast<double>(text.size()) * size * (bold ? 0.55 : 0.5);
}

// Every line of every cell fits its column, or is one word alone; every
// column ends a gap before the next begins; the table fits `available`.
// 1e-9 pt: the widths are sums of a few dozen doubles; only their rounding
// (1e-13 pt at these sizes) separates a line that fits exactly.
void expect_laid_out(const TableLayout& t, double available) {
  ASSERT_EQ(t.left.size(), t.width.size());
  for (std::size_t c = 0; c + 1 < t.left.size(); ++c)
    EXPECT_LE(t.left[c] + t.width[c] + kColumnGap, t.left[c + 1] + 1e-9) << "column " << c;
  EXPECT_LE(t.left.back() + t.width.back(), available + 1e-9);
  for (std::size_t r = 0; r < t.cells.size(); ++r)
    for (std::size_t c = 0; c < t.cells[r].size(); ++c)
      for (const auto& line : t.cells[r][c]) {
        if (line.find(' ') == std::string::npos) continue;  // one word: may be wider
        EXPECT_LE(monospace(line, t.size, r == 0), t.width[c] + 1e-9)
            << "row " << r << " column " << c << ": " << line;
      }
}

TEST(TableLayout, ATableThatFitsKeepsEachCellOnOneLine) {
  const TableLayout t =
      lay_out_table({"volume m3", "mass kg"}, {{"0.721", "1946"}}, 500, 9, 6, monospace);
  EXPECT_EQ(t.size, 9);
  // "volume m3" bold: 9 characters of 4.95 pt; "mass kg": 7 of 4.95 pt.
  EXPECT_DOUBLE_EQ(t.width[0], 9 * 4.95);
  EXPECT_DOUBLE_EQ(t.width[1], 7 * 4.95);
  EXPECT_DOUBLE_EQ(t.left[1], 9 * 4.95 + kColumnGap);
  for (const auto& row : t.cells)
    for (const auto& cell : row) EXPECT_EQ(cell.size(), 1u);
  expect_laid_out(t, 500);
}

TEST(TableLayout, ALongCellWrapsInsideItsColumn) {
  const std::vector<std::vector<std::string>> rows{
      {"J1", "strike perpendicular to the axis, drive against dip, dip 45-90: fair", "-5"},
      {"J2", "strike parallel to the axis, dip 45-90: very unfavourable", "-12"}};
  const double available = 200;
  const TableLayout t = lay_out_table({"plane", "against the drive (RMR89)", "RMR adj"}, rows,
                                      available, 8, 6, monospace);
  EXPECT_EQ(t.size, 8);  // the widest words fit at 8 pt: no need to shrink
  EXPECT_GT(t.cells[1][1].size(), 1u);
  expect_laid_out(t, available);
  // Nothing lost in the wrapping: the lines joined are the cell.
  std::string joined;
  for (const auto& line : t.cells[1][1]) joined += (joined.empty() ? "" : " ") + line;
  EXPECT_EQ(joined, rows[0][1]);
}

TEST(TableLayout, TheTypeShrinksOnlyUntilTheWidestWordsFit) {
  // Ten columns of one bold 10-character word: 100 characters, and 9 gaps
  // of 6 pt. At size s the words need 100 * 0.55 s + 54 pt; 300 pt are
  // given, so s <= 4.47: below the smallest type allowed (6 pt), which is taken.
  std::vector<std::string> header(10, "abcdefghij");
  const TableLayout small = lay_out_table(header, {}, 300, 9, 6, monospace);
  EXPECT_EQ(small.size, 6);
  // 450 pt: s <= (450 - 54) / 55 = 7.2 (bold header) -> 7.0 in quarter-point steps.
  const TableLayout shrunk = lay_out_table(header, {}, 450, 9, 6, monospace);
  EXPECT_DOUBLE_EQ(shrunk.size, 7.0);
  expect_laid_out(shrunk, 450);
}

TEST(TableLayout, AShortRowLeavesItsLastCellsEmpty) {
  const TableLayout t = lay_out_table({"a", "b", "c"}, {{"x"}}, 100, 9, 6, monospace);
  ASSERT_EQ(t.cells.size(), 2u);
  EXPECT_EQ(t.cells[1][2], std::vector<std::string>{""});
}

}  // namespace
}  // namespace rockface::storage
