// complex_checks.cpp -- the RawComplex contract (see header).
#include "complex3/complex_checks.h"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "geometry3/exact_predicates3.h"

namespace grassfire {
namespace {

std::string point_text(const ExactPoint3& p) {
  std::ostringstream os;
  os << "(" << p.x.get_d() << ", " << p.y.get_d() << ", " << p.z.get_d() << ")";
  return os.str();
}

template <std::size_t N>
std::optional<std::string> check_cells(const std::vector<std::array<std::uint32_t, N>>& cells, std::size_t n,
                                       const char* what) {
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t i = 0; i < N; ++i) {
      if (cells[c][i] >= n)
        return std::string(what) + " " + std::to_string(c) + " uses vertex " + std::to_string(cells[c][i]) +
               ", out of range (" + std::to_string(n) + " vertices)";
      for (std::size_t j = 0; j < i; ++j)
        if (cells[c][i] == cells[c][j])
          return std::string(what) + " " + std::to_string(c) + " repeats vertex " + std::to_string(cells[c][i]);
    }
  std::vector<std::pair<std::array<std::uint32_t, N>, std::size_t>> sorted;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    auto key = cells[c];
    std::sort(key.begin(), key.end());
    sorted.emplace_back(key, c);
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i)
    if (sorted[i].first == sorted[i + 1].first)
      return std::string(what) + "s " + std::to_string(sorted[i].second) + " and " +
             std::to_string(sorted[i + 1].second) + " are the same";
  return std::nullopt;
}

}  // namespace

std::optional<std::string> first_raw_violation(const FilteredPoints& points,
                                               const std::function<const mpq_class&(std::size_t)>& radius_squared,
                                               std::size_t radius_count,
                                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                               const std::vector<std::array<std::uint32_t, 2>>& segments) {
  const std::size_t n = points.size();
  if (n == 0) return std::string("empty complex (no vertices)");
  if (radius_count != n)
    return "radius_squared has " + std::to_string(radius_count) + " entries for " + std::to_string(n) + " vertices";
  for (std::size_t v = 0; v < n; ++v)
    if (sgn(radius_squared(v)) < 0) return "vertex " + std::to_string(v) + " has R^2 < 0";
  if (auto p = check_cells(triangles, n, "triangle")) return p;
  if (auto p = check_cells(segments, n, "segment")) return p;
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return points.compare_lex(a, b) < 0; });
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (points.compare_lex(order[i], order[i + 1]) == 0)
      return "vertices " + std::to_string(std::min(order[i], order[i + 1])) + " and " +
             std::to_string(std::max(order[i], order[i + 1])) + " coincide at " + point_text(points.exact(order[i]));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tv = triangles[t];
    if (points.collinear(tv[0], tv[1], tv[2]))
      return "triangle " + std::to_string(t) + " is degenerate (its vertices are collinear)";
  }
  return std::nullopt;
}

std::optional<std::string> first_raw_violation(const RawComplex& raw) {
  const FilteredPoints points(raw.vertices);
  return first_raw_violation(
      points, [&](std::size_t v) -> const mpq_class& { return raw.radius_squared[v]; }, raw.radius_squared.size(),
      raw.triangles, raw.segments);
}

}  // namespace grassfire
