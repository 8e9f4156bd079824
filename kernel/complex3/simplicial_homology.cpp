// simplicial_homology.cpp -- see simplicial_homology.h.
#include "complex3/simplicial_homology.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>

#include "support/union_find.h"

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

// The distinct simplices of one dimension as sorted keys; id = position.
template <std::size_t N>
class SortedIndex {
 public:
  void add(std::array<std::uint32_t, N> s) { keys_.push_back(sorted(s)); }
  void finish() {
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
  }
  std::uint32_t id(const std::array<std::uint32_t, N>& s) const {
    return static_cast<std::uint32_t>(std::lower_bound(keys_.begin(), keys_.end(), sorted(s)) - keys_.begin());
  }
  std::size_t size() const { return keys_.size(); }
  const std::vector<std::array<std::uint32_t, N>>& keys() const { return keys_; }

 private:
  std::vector<std::array<std::uint32_t, N>> keys_;
};

// Rank over GF(2) of the matrix with these columns (row ids each, distinct): columns with
// a row of their own are peeled first, the rest reduced.
long peeled_rank(std::size_t rows, std::vector<std::vector<std::uint32_t>> columns) {
  std::vector<std::uint32_t> count(rows, 0), start(rows + 1, 0), column_of;
  for (const auto& c : columns)
    for (std::uint32_t r : c) ++count[r];
  for (std::size_t r = 0; r < rows; ++r) start[r + 1] = start[r] + count[r];
  column_of.resize(start[rows]);
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t c = 0; c < columns.size(); ++c)
    for (std::uint32_t r : columns[c]) column_of[fill[r]++] = c;
  std::vector<bool> alive(columns.size(), true);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t r = 0; r < rows; ++r)
    if (count[r] == 1) queue.push_back(r);
  long rank = 0;
  while (!queue.empty()) {
    const std::uint32_t r = queue.back();
    queue.pop_back();
    if (count[r] != 1) continue;
    std::uint32_t c = 0;
    for (std::uint32_t i = start[r]; i < start[r + 1]; ++i)
      if (alive[column_of[i]]) c = column_of[i];
    alive[c] = false;
    ++rank;
    for (std::uint32_t x : columns[c])
      if (--count[x] == 1) queue.push_back(x);
  }
  std::vector<std::vector<std::uint32_t>> rest;
  for (std::uint32_t c = 0; c < columns.size(); ++c)
    if (alive[c]) {
      std::sort(columns[c].begin(), columns[c].end());
      rest.push_back(std::move(columns[c]));
    }
  return rank + gf2_rank(std::move(rest));
}

std::array<std::array<std::uint32_t, 3>, 4> tetrahedron_faces(const std::array<std::uint32_t, 4>& s) {
  return {{{s[1], s[2], s[3]}, {s[0], s[2], s[3]}, {s[0], s[1], s[3]}, {s[0], s[1], s[2]}}};
}

long components(std::size_t n, const std::vector<std::array<std::uint32_t, 2>>& edges) {
  UnionFind sets(n);
  long count = static_cast<long>(n);
  for (const auto& e : edges)
    if (sets.find(e[0]) != sets.find(e[1])) {
      sets.unite(e[0], e[1]);
      --count;
    }
  return count;
}

}  // namespace

std::string betti_text(const BettiNumbers& b) {
  return std::to_string(b.b0) + ":" + std::to_string(b.b1) + ":" + std::to_string(b.b2);
}

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
  SortedIndex<2> e;
  SortedIndex<3> t;
  for (const auto& s : triangles) t.add(s);
  for (const auto& s : tetrahedra)
    for (const auto& f : tetrahedron_faces(s)) t.add(f);
  t.finish();
  for (const auto& s : edges) e.add(s);
  for (const auto& s : t.keys()) {
    e.add({s[0], s[1]});
    e.add({s[0], s[2]});
    e.add({s[1], s[2]});
  }
  e.finish();
  std::vector<std::vector<std::uint32_t>> d2, d3;
  for (const auto& s : t.keys()) d2.push_back({e.id({s[0], s[1]}), e.id({s[0], s[2]}), e.id({s[1], s[2]})});
  std::vector<std::array<std::uint32_t, 4>> tets;
  for (auto s : tetrahedra) tets.push_back(sorted(s));
  std::sort(tets.begin(), tets.end());
  tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
  for (const auto& s : tets) {
    d3.emplace_back();
    for (const auto& f : tetrahedron_faces(s)) d3.back().push_back(t.id(f));
  }
  const long rank3 = peeled_rank(t.size(), std::move(d3));
  const long rank2 = peeled_rank(e.size(), std::move(d2));
  BettiNumbers b;
  b.b0 = components(vertex_count, e.keys());
  const long rank1 = static_cast<long>(vertex_count) - b.b0;
  b.b1 = static_cast<long>(e.size()) - rank1 - rank2;
  b.b2 = static_cast<long>(t.size()) - rank2 - rank3;
  return b;
}

BettiNumbers polygonal_betti_numbers(std::size_t vertex_count, const std::vector<std::array<std::uint32_t, 2>>& segments,
                                     const PolygonRings& polygons) {
  SortedIndex<2> e;
  for (const auto& s : segments) e.add(s);
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::uint32_t k = 0; k < polygons.ring_size(i); ++k) e.add(polygons.side(i, k));
  e.finish();
  std::vector<std::vector<std::uint32_t>> d2(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::uint32_t k = 0; k < polygons.ring_size(i); ++k) d2[i].push_back(e.id(polygons.side(i, k)));
  const long rank2 = peeled_rank(e.size(), std::move(d2));
  BettiNumbers b;
  b.b0 = components(vertex_count, e.keys());
  b.b1 = static_cast<long>(e.size()) - (static_cast<long>(vertex_count) - b.b0) - rank2;
  b.b2 = static_cast<long>(polygons.size()) - rank2;
  return b;
}

BettiNumbers betti_numbers_reference(std::size_t vertex_count, const std::vector<std::array<std::uint32_t, 2>>& edges,
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
  std::vector<std::array<std::uint32_t, 2>> edge_list;
  for (const auto& [key, id] : e.all()) edge_list.push_back(key);
  b.b0 = components(vertex_count, edge_list);
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
