// union_find.h -- disjoint sets over 0..n-1 (path halving; the smaller id is the root).
//
// Used to merge coincident Voronoi vertices and to find components of medial graphs.
// Roots are always the smallest id of their set, so results do not depend on the order
// of unions. Complexity: near-constant amortised per operation.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace grassfire {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace grassfire
