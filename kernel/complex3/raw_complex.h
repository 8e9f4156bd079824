// raw_complex.h -- a piecewise-linear 2-complex in R^3 as builders produce it.
//
// The hand-over format between the medial-axis builders (convex polyhedron, union of
// balls, mesh approximation, synthetic complexes, .ma files) and the MedialComplex,
// which derives strata, sheets, sectors and links from it (ch. 4, docs/design.md 5).
// Coordinates are exact rationals; the medial ball at a vertex has squared radius
// `radius_squared` (rational for every builder we have: Voronoi/power vertices of
// rational input). Ignition along each border edge follows `border_rule`:
//  - Linear: f interpolates the vertex values R linearly along the edge;
//  - DistanceToPoint: f(x) = |x - p| for the given rational point p (the medial ball of a
//    Voronoi-based axis touches the sample p; docs/design.md 5);
//  - Never: a truncation border that never ignites (f = infinity).
// Edges not listed in border_rules are Linear.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry3/exact_point3.h"

namespace grassfire {

enum class IgnitionRule : std::uint8_t { Linear, DistanceToPoint, Never };

struct BorderIgnition {
  std::array<std::uint32_t, 2> edge;  // vertex ids, either order
  IgnitionRule rule = IgnitionRule::Linear;
  ExactPoint3 point;                  // for DistanceToPoint
};

struct RawComplex {
  std::string source;                                // file or builder name, for messages
  std::vector<ExactPoint3> vertices;
  std::vector<mpq_class> radius_squared;             // per vertex, R^2 >= 0
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 2>> segments;  // 1-dimensional parts (no triangle)
  std::vector<BorderIgnition> border_rules;
};

}  // namespace grassfire
