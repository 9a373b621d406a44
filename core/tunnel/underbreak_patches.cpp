#include "core/tunnel/underbreak_patches.h"

#include <algorithm>
#include <limits>

#include "core/tunnel/developed_cells.h"

namespace rockface::tunnel {

namespace {

constexpr std::uint8_t kMeasuredViewCell =
    0;  // the developed view's measured cells (profile_deviation.h)

}  // namespace

std::vector<UnderbreakPatch> underbreak_patches(
    const ProfileDeviation& d, double tolerance, double cell_s, double cell_c,
    const std::vector<ProfilePosition>& position_of_cell) {
  const auto& v = d.view;
  const std::size_t rows = v.chainage.size(), cols = v.s.size();
  auto beyond = [&](std::size_t k) {
    return v.state[k] == kMeasuredViewCell && -v.deviation_m[k] > tolerance;
  };
  std::vector<char> done(rows * cols, 0);
  std::vector<UnderbreakPatch> out;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < rows * cols; ++start) {
    if (done[start] || !beyond(start)) continue;
    UnderbreakPatch p;
    p.chainage_from = std::numeric_limits<double>::infinity();
    p.chainage_to = -p.chainage_from;
    std::vector<std::size_t> col_list;
    stack.assign(1, start);
    done[start] = 1;
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      const std::size_t r = k / cols, c = k % cols;
      ++p.cells;
      p.chainage_from = std::min(p.chainage_from, v.chainage[r]);
      p.chainage_to = std::max(p.chainage_to, v.chainage[r]);
      col_list.push_back(c);
      const double depth = -v.deviation_m[k];
      if (depth > p.max_depth_m) {
        p.max_depth_m = depth;
        p.deepest = position_of_cell[k];
      }
      for (std::size_t n : developed_neighbours(k, rows, cols))
        if (!done[n] && beyond(n)) {
          done[n] = 1;
          stack.push_back(n);
        }
    }
    p.area_m2 = static_cast<double>(p.cells) * cell_s * cell_c;
    // Its arc-length span; a patch across s = 0 is unwrapped there, so
    // s_from > s_to says it wraps.
    std::sort(col_list.begin(), col_list.end());
    col_list.erase(std::unique(col_list.begin(), col_list.end()), col_list.end());
    std::size_t gap_at = 0, gap = 0;
    for (std::size_t i = 0; i < col_list.size(); ++i) {
      const std::size_t next = i + 1 < col_list.size() ? col_list[i + 1] : col_list[0] + cols;
      if (next - col_list[i] > gap) {
        gap = next - col_list[i];
        gap_at = i;
      }
    }
    const std::size_t first = col_list[(gap_at + 1) % col_list.size()], last = col_list[gap_at];
    p.s_from = v.s[first] - cell_s / 2;
    p.s_to = v.s[last] + cell_s / 2;
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const UnderbreakPatch& a, const UnderbreakPatch& b) {
    return a.max_depth_m > b.max_depth_m;
  });
  return out;
}

}  // namespace rockface::tunnel
