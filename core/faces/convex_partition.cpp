#include "core/faces/convex_partition.h"
#include "core/geometry/cross2.h"

#include <algorithm>
#include <cmath>

namespace rockface::faces {

using geometry::cross2;

namespace {

// Sine of the turn at b (a -> b -> c), positive to the left.
double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - b;
  const double n = u.norm() * v.norm();
  return n > 0 ? cross2(u, v) / n : 0.0;
}

bool convex_loop(const std::vector<Eigen::Vector2d>& p, const std::vector<int>& loop,
                 double straight_sine) {
  const size_t n = loop.size();
  for (size_t i = 0; i < n; ++i)
    if (turn(p[loop[(i + n - 1) % n]], p[loop[i]], p[loop[(i + 1) % n]]) < -straight_sine)
      return false;
  return true;
}

// Inside or on the triangle abc (counter-clockwise).
bool in_triangle(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 const Eigen::Vector2d& c) {
  return cross2(b - a, x - a) >= 0 && cross2(c - b, x - b) >= 0 && cross2(a - c, x - c) >= 0;
}

}  // namespace

std::vector<std::vector<int>> convex_partition(const std::vector<Eigen::Vector2d>& p,
                                               double straight_sine) {
  const int n = static_cast<int>(p.size());
  std::vector<int> all(n);
  for (int i = 0; i < n; ++i) all[i] = i;
  if (convex_loop(p, all, straight_sine)) return {all};

  // Ear clipping: a corner turning left whose triangle holds no other corner.
  std::vector<std::vector<int>> pieces;
  std::vector<int> rest = all;
  while (rest.size() > 3) {
    const int m = static_cast<int>(rest.size());
    bool cut = false;
    for (int i = 0; i < m && !cut; ++i) {
      const int a = rest[(i + m - 1) % m], b = rest[i], c = rest[(i + 1) % m];
      if (cross2(p[b] - p[a], p[c] - p[b]) <= 0) continue;  // reflex or straight: no ear
      bool empty = true;
      for (int k : rest)
        if (k != a && k != b && k != c && in_triangle(p[k], p[a], p[b], p[c])) empty = false;
      if (!empty) continue;
      pieces.push_back({a, b, c});
      rest.erase(rest.begin() + i);
      cut = true;
    }
    if (!cut) return {};  // the outline crosses itself
  }
  pieces.push_back(rest);

  // Hertel-Mehlhorn: drop a diagonal where the two pieces it separates make
  // one convex piece.
  for (bool merged = true; merged;) {
    merged = false;
    for (size_t i = 0; i < pieces.size() && !merged; ++i)
      for (size_t j = 0; j < pieces.size() && !merged; ++j) {
        if (i == j) continue;
        const auto& P = pieces[i];
        const auto& Q = pieces[j];
        for (size_t s = 0; s < P.size() && !merged; ++s) {
          const int a = P[s], b = P[(s + 1) % P.size()];
          // Q runs the shared diagonal the other way: b -> a.
          const auto qb = std::find(Q.begin(), Q.end(), b);
          if (qb == Q.end() || Q[(qb - Q.begin() + 1) % Q.size()] != a) continue;
          // P from b round to a, then Q's corners between a and b.
          std::vector<int> u;
          for (size_t k = 0; k < P.size(); ++k) u.push_back(P[(s + 1 + k) % P.size()]);
          const size_t qa = (qb - Q.begin() + 1) % Q.size();
          for (size_t k = 1; k + 1 < Q.size(); ++k) u.push_back(Q[(qa + k) % Q.size()]);
          if (!convex_loop(p, u, straight_sine)) continue;
          pieces[i] = std::move(u);
          pieces.erase(pieces.begin() + static_cast<long>(j));
          merged = true;
        }
      }
  }
  return pieces;
}

}  // namespace rockface::faces
