// adversarial_polygons.h -- seeded polygons that are hard for segment Voronoi builders and
// for exact predicates (2.1.1; docs/design.md 4): the inputs of Boost.Polygon's known wrong
// outputs and their variants, near-collinear and near-cocircular vertices, tiny edges at
// coordinates near the int32 limit, spikes.
//
// Computes: polygon number `seed` of kind `kind`, a deterministic function of both (every
// random choice comes from a std::mt19937_64 seeded with them). Kinds:
//  - boost43:        the 6-vertex polygon of Boost.Polygon issue #43 ((0, 10^7), (7 10^5, t),
//                    (7 10^5, 9 10^6), (9.1 10^6, 9 10^6), (9.1 10^6, 0), (10^7, 10^7)) with a
//                    tiny coordinate t in [-4, 4], scaled by 10^s (s in [-7, 2], decimal
//                    coordinates when s < 0), mirrored, turned by quarter turns, translated;
//  - near-collinear: a thin band whose two long sides zigzag by 0 or 1 unit about a line;
//  - near-cocircular:vertices rounded to integers on a circle of radius up to 10^9 (every
//                    integer point there nearly on one circle), sometimes with a hole;
//  - int32-limit:    a rectangle with corners near +-(2^31 - 1) and notches of 1 to 3 units
//                    along its sides (edges of length 1 beside coordinates of 2^31);
//  - spikes:         a star with long thin spikes (tips 1 unit wide) between short teeth;
//  - random-star:    a star-shaped polygon with random angles and radii (integer vertices).
// The result may be invalid (two rounded vertices equal, edges crossing after rounding):
// callers validate it (shapes/validate_shape.h) and skip invalid ones, so every polygon
// they keep is a valid simple polygon (with holes).
// Complexity: O(n) for n vertices (n <= 200).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry2/shape2.h"

namespace grassfire {

const std::vector<std::string>& adversarial_polygon_kinds();
// Throws std::invalid_argument for an unknown kind. The shape's name is "kind:seed".
Shape2 adversarial_polygon(const std::string& kind, std::uint64_t seed);

}  // namespace grassfire
