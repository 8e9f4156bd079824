// Helpers shared by the [complex3] and [burn3] tests.
#pragma once

#include <catch2/catch.hpp>

#include <functional>

#include "burn3/burn3_reference.h"
#include "burn3/discrete/steiner_graph.h"
#include "complex3/medial_complex.h"

namespace grassfire::testing {

// Every test validates every complex it builds.
inline MedialComplex built(const RawComplex& raw) {
  MedialComplex mc(raw);
  mc.validate();
  return mc;
}

inline std::uint32_t vertex_at(const MedialComplex& mc, const ExactPoint3& p) {
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex(v).exact == p) return v;
  FAIL("no vertex at (" << p.x.get_d() << ", " << p.y.get_d() << ", " << p.z.get_d() << ")");
  return kNoIndex;
}

// The graph points of the baseline at spacing h (vertices and Steiner points) for which
// `inside` holds, counted from the Steiner graph's positions: how many points a
// summarize_error over the same region must compare.
inline std::uint64_t graph_points_inside(const MedialComplex& mc, double h, const std::function<bool(const Vec3d&)>& inside) {
  const SteinerGraph g(mc, h, 50'000'000);
  std::uint64_t n = 0;
  for (std::uint32_t node = 0; node < g.node_count(); ++node) n += inside(g.position(node)) ? 1 : 0;
  return n;
}

// The comparison looked at exactly `expected` points (> 0) and compared every one of them:
// none skipped because one side is infinite.
inline void require_compared(const ErrorSummary& err, std::uint64_t expected) {
  CAPTURE(err.considered, err.points, err.both_infinite, err.one_sided_infinite);
  REQUIRE(expected > 0);
  REQUIRE(err.considered == expected);
  REQUIRE(err.one_sided_infinite == 0);
  REQUIRE(err.points == expected);
}

}  // namespace grassfire::testing
