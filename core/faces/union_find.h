#pragma once
// Disjoint sets over 0..n-1 (path halving; the smaller index is the root),
// used to merge snapped trace vertices and faces joined across patch edges.
#include <algorithm>
#include <numeric>
#include <vector>

namespace rockface::faces {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace rockface::faces
