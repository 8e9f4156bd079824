// perturbation.h -- seeded boundary perturbations of a planar shape, uniform or on one
// side only, with a guaranteed amplitude bound (3.4, Fig. 3.5; 5.1.3 stability).
//
// Computes: a new shape whose boundary is the old one with noise added along the normal:
//  1. every ring is densified: its vertices are kept and each edge of length L gets
//     ceil(L / spacing) - 1 evenly spaced interior points, so the densified ring is the
//     old ring as a point set;
//  2. each point p gets the displacement u * (amplitude - rounding) along its unit normal
//     (the edge's normal inside an edge, the normalised sum of the two edge normals at a
//     vertex), u uniform in [-1, 1] from a SplitMix64 stream of (seed, attempt, point);
//     OneSided perturbs only the points with (p - c) . direction > 0, c the bounding-box
//     centre, and leaves the others where they are;
//  3. coordinates are rounded to `decimal_digits` decimals (so the exact polygon axis runs
//     on integers, medial2/polygon/polygon_axis.h), rounding = 10^-digits bounds that move;
//  4. the result is validated (shapes/validate_shape.h); if the noise made it
//     self-intersecting, steps 2-4 are redone with attempt + 1, up to `max_attempts`.
// Guarantee: every point of the new boundary is within `amplitude` of the old boundary and
// vice versa (Hausdorff distance <= amplitude): densified points correspond one to one, each
// moved by at most amplitude, and points along edges are convex combinations of them.
// Deterministic: the same shape, options and seed give the same result bit for bit.
// Contract: a validated shape; amplitude > 2 * 10^-digits; spacing > 0; at most 10^7
// densified points. Errors: std::invalid_argument for bad options; std::runtime_error
// naming the shape, amplitude and seed when no attempt gave a valid shape.
// Complexity: O(n) per attempt for n densified points, plus validation.
#pragma once

#include <cstdint>

#include "geometry2/shape2.h"

namespace grassfire {

enum class PerturbationKind { Uniform, OneSided };
const char* to_string(PerturbationKind k);

struct PerturbationOptions {
  PerturbationKind kind = PerturbationKind::Uniform;
  double amplitude = 0;        // largest displacement of a boundary point (absolute units)
  double spacing = 0;          // arc-length spacing of the densified points (absolute units)
  std::uint64_t seed = 1;
  Point2 direction{1, 0};      // OneSided: the perturbed side
  int decimal_digits = 6;
  int max_attempts = 16;
};

struct PerturbedShape {
  Shape2 shape;
  int attempts = 0;                 // 1 when the first draw was valid
  std::size_t points = 0;           // densified points
  std::size_t perturbed_points = 0; // of which were displaced (all for Uniform)
};

PerturbedShape perturb_boundary(const Shape2& shape, const PerturbationOptions& options);

}  // namespace grassfire
