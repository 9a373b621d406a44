#include "core/measure/proposals/line_chains.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace rockface::measure::proposals {

namespace {

constexpr int kDx[8] = {1, 0, -1, 0, 1, -1, -1, 1};  // 4-neighbours first
constexpr int kDy[8] = {0, 1, 0, -1, 1, 1, -1, -1};

// The direction out of a chain at one end, from the pixels kEndSkip to
// kEndReach steps in: a single pixel step only says one of eight directions,
// and the last pixels before a junction bend toward the other line (the
// skeletons of two crossing lines merge over a line width or two).
constexpr std::size_t kEndSkip = 6, kEndReach = 30;
cv::Point2f end_direction(const Chain& c, bool at_front) {
  const std::size_t n = c.size();
  const std::size_t reach = std::min<std::size_t>(kEndReach, n - 1);
  const std::size_t skip = std::min<std::size_t>(kEndSkip, reach / 3);
  const cv::Point2f outer = at_front ? c[skip] : c[n - 1 - skip];
  const cv::Point2f inner = at_front ? c[reach] : c[n - 1 - reach];
  cv::Point2f d = outer - inner;
  const float len = std::hypot(d.x, d.y);
  return len > 0 ? d / len : cv::Point2f(0, 0);
}

// Distance of `p` from the line through `q` along the unit direction `t`.
double off_line(cv::Point2f p, cv::Point2f q, cv::Point2f t) {
  const cv::Point2f d = p - q;
  return std::abs(d.x * t.y - d.y * t.x);
}

double angle_deg(cv::Point2f a, cv::Point2f b) {
  const double la = std::hypot(a.x, a.y), lb = std::hypot(b.x, b.y);
  if (la == 0 || lb == 0) return 180;
  return std::acos(std::clamp((a.x * b.x + a.y * b.y) / (la * lb), -1.0, 1.0)) * 180 / M_PI;
}

// The line image made 8-thin: Zhang-Suen thinning leaves a line that rises
// at a shallow angle as a 4-connected staircase, whose corner pixels have
// three neighbours and so read as junctions, cutting the line into pieces
// of one or two pixels that are dropped as speckle. A corner pixel whose
// removal keeps its neighbours connected (a simple point: Yokoi's 8-
// connectivity number 1) and that has at least three neighbours (not a
// line's end) is removed, in one raster pass on the image as it is thinned.
cv::Mat eight_thin(const cv::Mat& lines) {
  cv::Mat out;
  cv::compare(lines, 0, out, cv::CMP_NE);
  const int w = out.cols, h = out.rows;
  // Neighbours in the order E, NE, N, NW, W, SW, S, SE (y down).
  constexpr int kRingX[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  constexpr int kRingY[8] = {0, -1, -1, -1, 0, 1, 1, 1};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!out.at<std::uint8_t>(y, x)) continue;
      int on[8], count = 0;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kRingX[k], ny = y + kRingY[k];
        on[k] = nx >= 0 && ny >= 0 && nx < w && ny < h && out.at<std::uint8_t>(ny, nx) != 0;
        count += on[k];
      }
      if (count < 3) continue;
      int connectivity = 0;
      for (int k = 0; k < 8; k += 2)
        connectivity += (1 - on[k]) - (1 - on[k]) * (1 - on[k + 1]) * (1 - on[(k + 2) % 8]);
      if (connectivity == 1) out.at<std::uint8_t>(y, x) = 0;
    }
  return out;
}

// A chain cut where it turns by more than max_turn_deg over kCornerWindow
// pixels on either side (the sharpest pixel of each such turn): where two
// lines cross, the skeleton of one may run on into the other without a
// junction pixel, and the two arms have to be free to join their own lines.
constexpr std::size_t kCornerWindow = 12;
std::vector<Chain> cut_at_corners(const Chain& c, double max_turn_deg) {
  const std::size_t n = c.size();
  if (n < 2 * kCornerWindow + 1) return {c};
  std::vector<double> turn(n, 0.0);
  for (std::size_t k = kCornerWindow; k + kCornerWindow < n; ++k)
    turn[k] = angle_deg(c[k] - c[k - kCornerWindow], c[k + kCornerWindow] - c[k]);
  std::vector<std::size_t> corners;
  for (std::size_t k = 0; k < n; ++k) {
    if (turn[k] <= max_turn_deg) continue;
    std::size_t best = k;
    while (k + 1 < n && turn[k + 1] > max_turn_deg)
      if (turn[++k] > turn[best]) best = k;
    corners.push_back(best);
  }
  std::vector<Chain> out(1);
  std::size_t next_corner = 0;
  for (std::size_t k = 0; k < n; ++k) {
    out.back().push_back(c[k]);
    if (next_corner < corners.size() && corners[next_corner] == k) {
      out.push_back({c[k]});  // the corner pixel ends one piece and starts the next
      ++next_corner;
    }
  }
  return out;
}

}  // namespace

double chain_length(const Chain& chain) {
  double s = 0;
  for (std::size_t i = 1; i < chain.size(); ++i)
    s += std::hypot(chain[i].x - chain[i - 1].x, chain[i].y - chain[i - 1].y);
  return s;
}

std::vector<Chain> trace_chains(const cv::Mat& line_image, int min_pixels) {
  const cv::Mat lines = eight_thin(line_image);
  const int w = lines.cols, h = lines.rows;
  auto on = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && lines.at<std::uint8_t>(y, x) != 0;
  };
  cv::Mat count(lines.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (on(x, y))
        for (int k = 0; k < 8; ++k) count.at<std::uint8_t>(y, x) += on(x + kDx[k], y + kDy[k]);
  auto is_node = [&](int x, int y) { return count.at<std::uint8_t>(y, x) != 2; };
  cv::Mat visited(lines.size(), CV_8U, cv::Scalar(0));
  std::vector<Chain> chains;

  // Walks from `start` through `next` until a node, a dead end or a pixel
  // already walked.
  auto walk = [&](cv::Point start, cv::Point next) {
    Chain c{cv::Point2f(start)};
    cv::Point prev = start, cur = next;
    while (true) {
      c.emplace_back(cur);
      if (is_node(cur.x, cur.y)) break;
      visited.at<std::uint8_t>(cur.y, cur.x) = 1;
      bool moved = false;
      for (int k = 0; k < 8 && !moved; ++k) {
        const cv::Point n(cur.x + kDx[k], cur.y + kDy[k]);
        if (n == prev || !on(n.x, n.y)) continue;
        if (!is_node(n.x, n.y) && visited.at<std::uint8_t>(n.y, n.x)) continue;
        if (n == start && c.size() < 3) continue;
        prev = cur;
        cur = n;
        moved = true;
      }
      if (!moved) break;
    }
    if (static_cast<int>(c.size()) >= min_pixels) chains.push_back(std::move(c));
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!on(x, y) || !is_node(x, y)) continue;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (!on(nx, ny) || is_node(nx, ny) || visited.at<std::uint8_t>(ny, nx)) continue;
        walk(cv::Point(x, y), cv::Point(nx, ny));
      }
    }
  // Closed loops (every pixel with two neighbours): start anywhere.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!on(x, y) || is_node(x, y) || visited.at<std::uint8_t>(y, x)) continue;
      visited.at<std::uint8_t>(y, x) = 1;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (on(nx, ny) && !visited.at<std::uint8_t>(ny, nx)) {
          walk(cv::Point(x, y), cv::Point(nx, ny));
          break;
        }
      }
    }
  return chains;
}

std::vector<Chain> join_chains(std::vector<Chain> traced, double max_gap_px, double max_turn_deg) {
  std::vector<Chain> chains;
  for (const Chain& c : traced)
    for (Chain& piece : cut_at_corners(c, max_turn_deg)) chains.push_back(std::move(piece));
  struct Link {
    double score;
    int a, b;  // end ids: 2 * chain + (0 front, 1 back)
  };
  const int n = static_cast<int>(chains.size());
  // Where two lines cross at a small angle their skeletons merge into one
  // short piece between two junctions: that piece is both lines', so it
  // links to neither, and each line's arms are joined across it (up to
  // kAcrossJunction gaps, when they run on in one straight line).
  const double bridge_px = max_gap_px;
  constexpr double kAcrossJunction = 3.0;
  constexpr double kStraightTurnDeg = 10.0;
  constexpr double kStraightOffsetPx = 2.0;
  std::vector<bool> linkable(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    linkable[i] = chains[i].size() >= 2 && chain_length(chains[i]) > bridge_px;
  // The chains with an end near one of a chain's ends, from a grid of the
  // ends whose cells are as wide as the farthest link: the pairs every
  // pair of chains would give, in the same order (a scan of every pair was
  // quadratic in the thousands of chains of a 24 Mpx photograph). Two
  // cells either way: an end exactly the farthest link away may round
  // into the cell beyond.
  const double cell = std::max(1.0, kAcrossJunction * max_gap_px);
  const auto cell_of = [cell](cv::Point2f p) {
    return std::make_pair(static_cast<long>(std::floor(p.x / cell)),
                          static_cast<long>(std::floor(p.y / cell)));
  };
  std::map<std::pair<long, long>, std::vector<int>> ends_in;
  for (int i = 0; i < n; ++i)
    if (linkable[i])
      for (const cv::Point2f p : {chains[i].front(), chains[i].back()})
        ends_in[cell_of(p)].push_back(i);
  std::vector<Link> links;
  std::vector<int> near;
  for (int i = 0; i < n; ++i) {
    if (!linkable[i]) continue;
    near.clear();
    for (const cv::Point2f p : {chains[i].front(), chains[i].back()}) {
      const auto [cx, cy] = cell_of(p);
      for (long dy = -2; dy <= 2; ++dy)
        for (long dx = -2; dx <= 2; ++dx) {
          const auto found = ends_in.find({cx + dx, cy + dy});
          if (found == ends_in.end()) continue;
          for (const int j : found->second)
            if (j > i) near.push_back(j);
        }
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const int j : near) {
      for (int ei = 0; ei < 2; ++ei)
        for (int ej = 0; ej < 2; ++ej) {
          const cv::Point2f pi = ei == 0 ? chains[i].front() : chains[i].back();
          const cv::Point2f pj = ej == 0 ? chains[j].front() : chains[j].back();
          const cv::Point2f gap = pj - pi;
          const double len = std::hypot(gap.x, gap.y);
          if (len > kAcrossJunction * max_gap_px) continue;
          const cv::Point2f ti = end_direction(chains[i], ei == 0);
          const cv::Point2f tj = end_direction(chains[j], ej == 0);
          const double turn = angle_deg(ti, -tj);
          if (turn > max_turn_deg) continue;
          // How far each end lies off the other's line: a line that runs on
          // through a junction is one straight line on both sides.
          const double offset = std::max(off_line(pj, pi, ti), off_line(pi, pj, tj));
          const bool straight =
              turn <= kStraightTurnDeg && offset <= std::max(kStraightOffsetPx, 0.1 * len);
          if (len > max_gap_px && !straight) continue;
          // Across a real gap the bridge itself must run on the same way:
          // each end within the turn of the other's line.
          if (offset > std::max(kStraightOffsetPx, len * std::tan(max_turn_deg * M_PI / 180)))
            continue;
          // Straightest first: a degree of turn weighs as a pixel off line
          // and as two pixels of gap.
          links.push_back({turn + offset + 0.5 * len, 2 * i + ei, 2 * j + ej});
        }
    }
  }
  std::sort(links.begin(), links.end(),
            [](const Link& x, const Link& y) { return x.score < y.score; });
  std::vector<int> partner(static_cast<std::size_t>(2 * n), -1);
  std::vector<int> root(static_cast<std::size_t>(n));
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  for (const Link& l : links) {
    if (partner[l.a] >= 0 || partner[l.b] >= 0) continue;
    const int ra = find(l.a / 2), rb = find(l.b / 2);
    if (ra == rb) continue;  // would close a loop
    root[ra] = rb;
    partner[l.a] = l.b;
    partner[l.b] = l.a;
  }
  // Follow the links from each free end.
  std::vector<Chain> out;
  std::vector<bool> used(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (used[i] || chains[i].size() < 2) continue;
    int start_end = -1;
    for (int e = 0; e < 2; ++e)
      if (partner[2 * i + e] < 0) start_end = 2 * i + e;
    if (start_end < 0) continue;  // inside a sequence: reached from its free end
    Chain joined;
    int end = start_end;
    while (true) {
      const int c = end / 2;
      used[c] = true;
      Chain piece = chains[c];
      if (end % 2 == 1) std::reverse(piece.begin(), piece.end());  // enter at `end`
      joined.insert(joined.end(), piece.begin(), piece.end());
      const int exit = end ^ 1;
      if (partner[exit] < 0) break;
      end = partner[exit];
    }
    out.push_back(std::move(joined));
  }
  return out;
}

}  // namespace rockface::measure::proposals
