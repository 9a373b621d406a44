#include "storage/field_report/table_layout.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace rockface::storage {

namespace {

// The type shrinks in steps of this many points when the words do not fit.
constexpr double kSizeStep = 0.25;

std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace

std::vector<std::string> wrap_words(const std::string& text, double width,
                                    const std::function<double(const std::string&)>& measure) {
  std::vector<std::string> lines;
  std::string line;
  for (const auto& word : words_of(text)) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && measure(longer) > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = longer;
    }
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  return lines;
}

TableLayout lay_out_table(const std::vector<std::string>& header,
                          const std::vector<std::vector<std::string>>& rows, double available,
                          double size, double min_size, const TextWidth& measure) {
  const std::size_t n = header.size();
  auto cell = [&](std::size_t r, std::size_t c) -> const std::string& {
    static const std::string none;
    if (r == 0) return header[c];
    const auto& row = rows[r - 1];
    return c < row.size() ? row[c] : none;
  };
  const double gaps = n > 1 ? kColumnGap * static_cast<double>(n - 1) : 0;
  std::vector<double> widest_word(n), longest_cell(n);
  for (;;) {
    std::fill(widest_word.begin(), widest_word.end(), 0.0);
    std::fill(longest_cell.begin(), longest_cell.end(), 0.0);
    for (std::size_t r = 0; r <= rows.size(); ++r)
      for (std::size_t c = 0; c < n; ++c) {
        const bool bold = r == 0;
        longest_cell[c] = std::max(longest_cell[c], measure(cell(r, c), size, bold));
        for (const auto& w : words_of(cell(r, c)))
          widest_word[c] = std::max(widest_word[c], measure(w, size, bold));
      }
    const double least = std::accumulate(widest_word.begin(), widest_word.end(), 0.0) + gaps;
    if (least <= available || size - kSizeStep < min_size) break;
    size -= kSizeStep;
  }
  TableLayout t;
  t.size = size;
  t.width = longest_cell;
  const double natural = std::accumulate(longest_cell.begin(), longest_cell.end(), 0.0) + gaps;
  if (natural > available) {
    // Every column gets its widest word; what is left of the page goes to
    // the columns in proportion to how much more their longest cell needs.
    const double least = std::accumulate(widest_word.begin(), widest_word.end(), 0.0) + gaps;
    double wanted = 0;
    for (std::size_t c = 0; c < n; ++c) wanted += longest_cell[c] - widest_word[c];
    const double spare = std::max(0.0, available - least);
    for (std::size_t c = 0; c < n; ++c)
      t.width[c] =
          widest_word[c] + (wanted > 0 ? spare * (longest_cell[c] - widest_word[c]) / wanted : 0.0);
  }
  double x = 0;
  for (std::size_t c = 0; c < n; ++c) {
    t.left.push_back(x);
    x += t.width[c] + kColumnGap;
  }
  for (std::size_t r = 0; r <= rows.size(); ++r) {
    std::vector<std::vector<std::string>> row;
    for (std::size_t c = 0; c < n; ++c)
      row.push_back(wrap_words(cell(r, c), t.width[c],
                               [&](const std::string& s) { return measure(s, size, r == 0); }));
    t.cells.push_back(std::move(row));
  }
  return t;
}

}  // namespace rockface::storage
