// simplicial_homology.cpp -- see simplicial_homology.h.
#include "complex3/builders/simplicial_homology.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

namespace grassfire {

namespace {

template <std::size_t N>
std::array<std::uint32_t, N> sorted(std::array<std::uint32_t, N> s) {
  std::sort(s.begin(), s.end());
  return s;
}

// Ids of the distinct simplices of one dimension.
template <std::size_t N>
class SimplexIndex {
 public:
  std::uint32_t id(const std::array<std::uint32_t, N>& s) {
    return ids_.emplace(sorted(s), static_cast<std::uint32_t>(ids_.size())).first->second;
  }
  std::size_t size() const { return ids_.size(); }
  const std::map<std::array<std::uint32_t, N>, std::uint32_t>& all() const { return ids_; }

 private:
  std::map<std::array<std::uint32_t, N>, std::uint32_t> ids_;
};

// Rank over GF(2) of the matrix with these columns (sorted row ids each).
long gf2_rank(std::vector<std::vector<std::uint32_t>> columns) {
  return static_cast<long>(columns.size() - gf2_zero_columns(std::move(columns)).size());
}

long components(std::size_t n, const std::map<std::array<std::uint32_t, 2>, std::uint32_t>& edges) {
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  long count = static_cast<long>(n);
  for (const auto& [e, id] : edges) {
    const std::uint32_t a = find(e[0]), b = find(e[1]);
    if (a != b) {
      parent[a] = b;
      --count;
    }
  }
  return count;
}

}  // namespace

std::vector<std::size_t> gf2_zero_columns(std::vector<std::vector<std::uint32_t>> columns) {
  std::unordered_map<std::uint32_t, std::size_t> pivot_column;
  std::vector<std::size_t> zero;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    std::vector<std::uint32_t>& col = columns[c];
    while (!col.empty()) {
      auto it = pivot_column.find(col.back());
      if (it == pivot_column.end()) break;
      std::vector<std::uint32_t> sum;
      const std::vector<std::uint32_t>& other = columns[it->second];
      std::set_symmetric_difference(col.begin(), col.end(), other.begin(), other.end(), std::back_inserter(sum));
      col.swap(sum);
    }
    if (col.empty())
      zero.push_back(c);
    else
      pivot_column[col.back()] = c;
  }
  return zero;
}

BettiNumbers betti_numbers(std::size_t vertex_count, const std::vector<std::array<std::uint32_t, 2>>& edges,
                           const std::vector<std::array<std::uint32_t, 3>>& triangles,
                           const std::vector<std::array<std::uint32_t, 4>>& tetrahedra) {
  SimplexIndex<2> e;
  SimplexIndex<3> t;
  for (const auto& s : edges) e.id(s);
  for (const auto& s : triangles) t.id(s);
  std::vector<std::vector<std::uint32_t>> d3;
  for (const auto& s : tetrahedra) {
    std::vector<std::uint32_t> col;
    for (int k = 0; k < 4; ++k) {
      std::array<std::uint32_t, 3> f;
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != k) f[m++] = s[j];
      col.push_back(t.id(f));
    }
    std::sort(col.begin(), col.end());
    d3.push_back(std::move(col));
  }
  std::vector<std::vector<std::uint32_t>> d2(t.size());
  for (const auto& [s, id] : t.all()) {
    d2[id] = {e.id({s[0], s[1]}), e.id({s[0], s[2]}), e.id({s[1], s[2]})};
    std::sort(d2[id].begin(), d2[id].end());
  }
  const long rank3 = gf2_rank(std::move(d3));
  const long rank2 = gf2_rank(std::move(d2));
  BettiNumbers b;
  b.b0 = components(vertex_count, e.all());
  const long rank1 = static_cast<long>(vertex_count) - b.b0;
  b.b1 = static_cast<long>(e.size()) - rank1 - rank2;
  b.b2 = static_cast<long>(t.size()) - rank2 - rank3;
  return b;
}

std::map<std::size_t, std::size_t> edge_degree_histogram(const RawComplex& complex) {
  std::map<std::array<std::uint32_t, 2>, std::size_t> degree;
  for (const auto& t : complex.triangles)
    for (int k = 0; k < 3; ++k) ++degree[sorted<2>({t[k], t[(k + 1) % 3]})];
  std::map<std::size_t, std::size_t> h;
  for (const auto& [e, d] : degree) ++h[d];
  return h;
}

BettiNumbers betti_numbers(const RawComplex& complex) {
  return betti_numbers(complex.vertices.size(), complex.segments, complex.triangles, {});
}

}  // namespace grassfire
