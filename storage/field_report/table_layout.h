#pragma once
// A table of the printed report laid out from measured text widths: each
// column as wide as its widest word at least and its longest cell at most,
// the page's width shared by what the cells need, a cell wrapped at spaces
// inside its column, and a gap between columns, so that no two cells meet
// (issue 39: "volume m3mass kg"). The type shrinks, down to `min_size`, only
// when the widest words alone do not fit. The measure is given (cairo's text
// extents in the PDF), so the layout is a function a test can call.
#include <functional>
#include <string>
#include <vector>

namespace rockface::storage {

// Advance width in points of `text` at `size` points, bold or not.
using TextWidth = std::function<double(const std::string& text, double size, bool bold)>;

// The gap between two columns, in points: about a space and a half at the
// report's type sizes, so a reader sees where one cell ends.
inline constexpr double kColumnGap = 6;

struct TableLayout {
  double size = 0;                  // the type size chosen
  std::vector<double> left, width;  // per column, points from the table's left edge
  // Per row (the header first), per column: the cell's lines.
  std::vector<std::vector<std::vector<std::string>>> cells;
};

// The header is set bold. A row shorter than the header leaves its last
// cells empty; cells beyond the header's count are not shown.
TableLayout lay_out_table(const std::vector<std::string>& header,
                          const std::vector<std::vector<std::string>>& rows, double available,
                          double size, double min_size, const TextWidth& measure);

// `text` broken at spaces into lines no wider than `width` (a word wider
// than that stands alone on its line).
std::vector<std::string> wrap_words(const std::string& text, double width,
                                    const std::function<double(const std::string&)>& measure);

}  // namespace rockface::storage
