// synthetic_graphs.cpp -- see synthetic_graphs.h.
#include "medial2/synthetic_graphs.h"

#include <algorithm>
#include <random>
#include <set>

namespace grassfire {

namespace {

struct IntPoint {
  long x, y;
};

long squared_distance(const IntPoint& a, const IntPoint& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> random_ends(std::mt19937_64& rng, std::uint32_t n,
                                                                 std::uint32_t extra) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  std::set<std::pair<std::uint32_t, std::uint32_t>> used;
  for (std::uint32_t v = 1; v < n; ++v) {
    const std::uint32_t parent = std::uniform_int_distribution<std::uint32_t>(0, v - 1)(rng);
    ends.emplace_back(parent, v);
    used.insert({parent, v});
  }
  for (std::uint32_t k = 0; k < extra && n >= 3; ++k) {
    std::uint32_t a = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
    std::uint32_t b = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (!used.insert({a, b}).second) continue;
    ends.emplace_back(a, b);
  }
  return ends;
}

MedialGraph integer_graph(std::mt19937_64& rng, std::uint32_t n, std::uint32_t extra) {
  auto ends = random_ends(rng, n, extra);
  // Lengths first, then R by a walk that keeps every edge strictly 1-Lipschitz, as R is
  // on a medial axis: R(v) within [R(parent) - w + 1, R(parent) + w - 1] for tree edges;
  // chords get length > |R(a) - R(b)|.
  std::vector<long> radius(n, 0);
  std::vector<long> length(ends.size(), 0);
  radius[0] = std::uniform_int_distribution<long>(0, 6)(rng);
  for (std::size_t e = 0; e < n - 1; ++e) {
    const auto [p, v] = ends[e];
    length[e] = std::uniform_int_distribution<long>(1, 4)(rng);
    radius[v] = std::max(0L, radius[p] + std::uniform_int_distribution<long>(1 - length[e], length[e] - 1)(rng));
  }
  for (std::size_t e = n - 1; e < ends.size(); ++e) {
    const long gap = std::abs(radius[ends[e].first] - radius[ends[e].second]);
    length[e] = gap + std::uniform_int_distribution<long>(1, 3)(rng);
  }
  std::vector<Point2> positions(n);
  std::vector<ExactSum> radii, lengths;
  for (std::uint32_t v = 0; v < n; ++v) {
    positions[v] = {static_cast<double>(v), static_cast<double>(radius[v])};
    radii.push_back(ExactSum::rational(radius[v]));
  }
  for (long w : length) lengths.push_back(ExactSum::rational(w));
  return MedialGraph::from_exact(std::move(positions), std::move(radii), std::move(ends), std::move(lengths));
}

MedialGraph geometric_graph(std::mt19937_64& rng, std::uint32_t n, std::uint32_t extra) {
  std::uniform_int_distribution<long> coord(0, 24);
  std::vector<IntPoint> points;
  std::set<std::pair<long, long>> taken;
  while (points.size() < n) {
    IntPoint p{coord(rng), coord(rng)};
    if (taken.insert({p.x, p.y}).second) points.push_back(p);
  }
  std::vector<IntPoint> sites(3);
  for (IntPoint& s : sites) s = {coord(rng) - 4, coord(rng) - 4};
  auto ends = random_ends(rng, n, extra);
  std::vector<Point2> positions;
  std::vector<ExactSum> radii, lengths;
  for (const IntPoint& p : points) {
    long best = squared_distance(p, sites[0]);
    for (const IntPoint& s : sites) best = std::min(best, squared_distance(p, s));
    positions.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
    // 9/10 of the distance to the nearest site: strictly 1-Lipschitz along every edge.
    radii.push_back(ExactSum::sqrt_of(make_rational(81 * best, 100)));
  }
  for (const auto& [a, b] : ends) lengths.push_back(ExactSum::sqrt_of(squared_distance(points[a], points[b])));
  return MedialGraph::from_exact(std::move(positions), std::move(radii), std::move(ends), std::move(lengths));
}

}  // namespace

MedialGraph random_medial_graph(std::uint64_t seed, std::uint32_t nodes, std::uint32_t extra_edges,
                                SyntheticFamily family) {
  std::mt19937_64 rng(seed);
  return family == SyntheticFamily::Integer ? integer_graph(rng, nodes, extra_edges)
                                            : geometric_graph(rng, nodes, extra_edges);
}

}  // namespace grassfire
