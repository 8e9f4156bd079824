// The dissertation's thinning algorithm (3.3.2) against the definition (docs/design.md 4).
// It removes the leaf of smallest value and gives the exposed neighbour value + edge
// length, ordering by the leaf's value rather than by the arrival time at the neighbour.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "burn2/extended_grassfire.h"
#include "medial2/synthetic_graphs.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

TEST_CASE("thinning orders by leaf value: a star where it differs by one edge", "[dissertation]") {
  // centre 0 (R 1); leaves 1 (R 0, w 10), 2 (R 1, w 1), 3 (R 2, w 1). Thinning removes
  // leaf 1 first (value 0) although its front reaches the centre last (at 10).
  const MedialGraph g = integer_graph({1, 0, 1, 2}, {{0, 1, 10}, {0, 2, 1}, {0, 3, 1}});
  const GrassfireResult exact = extended_grassfire(g);
  const GrassfireResult thin = extended_grassfire(g, GrassfireVariant::Dissertation);
  CHECK(exact_value(exact, 0) == 3);
  CHECK(exact_value(thin, 0) == 2);
  // The thinning's EMA is the last node left, leaf 3; the definition's lies on edge 0.
  REQUIRE(thin.ema.at(0).point.at_node);
  CHECK(thin.ema[0].point.node == 3);
  CHECK_FALSE(exact.ema.at(0).point.at_node);
}

TEST_CASE("thinning can differ by more than one edge length", "[dissertation]") {
  // Found by the random search below (integer family); the difference at node 0 is
  // 6 = 1.5 x the longest edge (4), so "at most one edge length" is not a bound.
  const MedialGraph g = integer_graph({1, 1, 0, 0, 0, 0, 0, 1, 4, 0},
                                      {{0, 1, 2}, {1, 2, 4}, {0, 3, 4}, {3, 4, 4}, {3, 5, 1},
                                       {0, 6, 3}, {0, 7, 1}, {1, 8, 3}, {0, 9, 2}});
  const GrassfireResult exact = extended_grassfire(g);
  const GrassfireResult thin = extended_grassfire(g, GrassfireVariant::Dissertation);
  CHECK(exact_value(exact, 0) == 8);
  CHECK(exact_value(thin, 0) == 2);
  CHECK(exact_value(exact, 1) == 7);
  CHECK(exact_value(thin, 1) == 4);
}

TEST_CASE("thinning and definition on random graphs: same infinite set, bounded difference", "[dissertation]") {
  double worst_ratio = 0;
  int differ = 0;
  for (std::uint64_t seed = 0; seed < 3000; ++seed) {
    const SyntheticFamily family = seed % 2 ? SyntheticFamily::Geometric : SyntheticFamily::Integer;
    const MedialGraph g = random_medial_graph(seed, 2 + static_cast<std::uint32_t>(seed % 60), seed % 5 == 0 ? 2 : 0,
                                              family);
    const GrassfireResult exact = extended_grassfire(g);
    const GrassfireResult thin = extended_grassfire(g, GrassfireVariant::Dissertation);
    double longest = 0;
    for (const MedialEdge& e : g.edges()) longest = std::max(longest, e.length.hi);
    double worst = 0;
    for (std::uint32_t v = 0; v < g.node_count(); ++v) {
      INFO("seed " << seed << " node " << v);
      REQUIRE(exact.is_infinite(v) == thin.is_infinite(v));  // both leave exactly the 2-core
      if (exact.is_infinite(v)) continue;
      const Interval d = thin.edf(v) - exact.edf(v);
      worst = std::max({worst, std::fabs(d.lo), std::fabs(d.hi)});
    }
    differ += worst > 0;
    worst_ratio = std::max(worst_ratio, worst / longest);
  }
  // Measured on this corpus: 1.75. The thinning is not within one edge length of the
  // definition; within two edge lengths it stays on every graph we generated.
  CHECK(differ > 1000);
  CHECK(worst_ratio > 1.0);
  CHECK(worst_ratio < 2.0);
}
