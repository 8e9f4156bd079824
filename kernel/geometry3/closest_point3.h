// closest_point3.h -- the nearest point of a closed triangle to a point of R^3: exactly over
// Q, and as a certified interval enclosure of the squared distance.
//
// Computes: closest_weights(a, b, c, p), the barycentric weights of the point of triangle
// abc nearest to p, by the region tests of Ericson, Real-Time Collision Detection 5.1.5,
// in rationals (the nearest point of a closed triangle to a rational point is rational),
// evaluated on integers (the points times a common denominator, no gcd per operation);
// closest_weights_reference is the same in plain rationals, the reference tests compare with;
// and closest_squared_distance(a, b, c, p) on interval enclosures of the four points: the
// same region tests with certified interval signs, then |p - x|^2 for the point x of the
// region, an interval that contains the exact squared distance from p to the triangle.
// When a region test is not certified (p near a region boundary, or wide enclosures) the
// interval version returns nothing and the caller falls back to other bounds.
// Why the enclosure is valid: each test decided by the interval has the sign the exact
// test has, so the exact computation takes the same branch, and every interval operation
// encloses the exact operation on any points of its operands.
// Contract: abc not collinear. Complexity: O(1) rational or interval operations.
// Section: docs/design.md 3 (interval filter, then exact); point location of point_location.h.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>

#include "geometry3/exact_predicates3.h"
#include "number/interval.h"

namespace grassfire {

using IntervalPoint3 = std::array<Interval, 3>;

std::array<mpq_class, 3> closest_weights(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c,
                                         const ExactPoint3& p);

std::array<mpq_class, 3> closest_weights_reference(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c,
                                                   const ExactPoint3& p);

std::optional<Interval> closest_squared_distance(const IntervalPoint3& a, const IntervalPoint3& b,
                                                 const IntervalPoint3& c, const IntervalPoint3& p);

// Squared distance from p to the segment ab, enclosed (nothing when the clamp of the
// projection parameter is not certified).
std::optional<Interval> closest_squared_distance(const IntervalPoint3& a, const IntervalPoint3& b,
                                                 const IntervalPoint3& p);

}  // namespace grassfire
