// Planar sheets made of grid cells, for the burning tests: squares, an L, a square with a
// square hole; each cell of side 1/g split into two triangles, all in the plane z = 0
// (or mapped by a rational affine map into another plane).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geometry3/exact_predicates3.h"
#include "complex3/raw_complex.h"

namespace grassfire::testing {

// mask[r][c] == '#' keeps the unit cell [c, c+1] x [r, r+1] (row 0 at the bottom); each is
// split into g x g squares of side 1/g. rule(a, b) gives the rule of the border edge ab
// (Linear when it returns nothing); `place` maps the (x, y) plane into R^3.
struct GridSheet {
  std::vector<std::string> mask;
  int g = 1;
  std::function<BorderIgnition(const ExactPoint3&, const ExactPoint3&)> rule{};
  std::function<ExactPoint3(const mpq_class&, const mpq_class&)> place{};
};

inline RawComplex grid_sheet(const GridSheet& s) {
  RawComplex raw;
  raw.source = "grid sheet";
  std::map<std::pair<long, long>, std::uint32_t> ids;
  std::vector<std::pair<long, long>> lattice;
  auto vertex = [&](long i, long j) {
    auto [it, fresh] = ids.emplace(std::make_pair(i, j), static_cast<std::uint32_t>(lattice.size()));
    if (fresh) lattice.emplace_back(i, j);
    return it->second;
  };
  for (std::size_t r = 0; r < s.mask.size(); ++r)
    for (std::size_t c = 0; c < s.mask[r].size(); ++c) {
      if (s.mask[r][c] != '#') continue;
      for (int a = 0; a < s.g; ++a)
        for (int b = 0; b < s.g; ++b) {
          const long i = static_cast<long>(c) * s.g + a, j = static_cast<long>(r) * s.g + b;
          const std::uint32_t v00 = vertex(i, j), v10 = vertex(i + 1, j), v11 = vertex(i + 1, j + 1),
                              v01 = vertex(i, j + 1);
          raw.triangles.push_back({v00, v10, v11});
          raw.triangles.push_back({v00, v11, v01});
        }
    }
  for (const auto& [i, j] : lattice) {
    mpq_class x(i, s.g), y(j, s.g);
    x.canonicalize();
    y.canonicalize();
    raw.vertices.push_back(s.place ? s.place(x, y) : ExactPoint3{x, y, 0});
  }
  raw.radius_squared.assign(raw.vertices.size(), 0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const auto& t : raw.triangles)
    for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
  if (s.rule)
    for (const auto& [e, n] : count)
      if (n == 1) {
        BorderIgnition b = s.rule(raw.vertices[e.first], raw.vertices[e.second]);
        if (b.rule == IgnitionRule::Linear) continue;
        b.edge = {e.first, e.second};
        raw.border_rules.push_back(b);
      }
  return raw;
}

}  // namespace grassfire::testing
