// predicates2.h -- exact planar predicates on double points: orientation, segment-segment
// intersection classification, and the location of a point relative to a ring or a shape.
//
// Computes: the exact sign of orient(a, b, c) = det[b - a, c - a] for double points, and
// every decision built on it (which segments meet and how; inside / boundary / outside).
// Method (docs/design.md 3): a double filter with Shewchuk's static error bound, then an exact
// GMP fallback. The filter evaluates det = (a.x - c.x)(b.y - c.y) - (a.y - c.y)(b.x - c.x)
// in round-to-nearest; Shewchuk (1997, "ccwerrboundA") proves |det - exact| <= (3 + 16 eps)
// eps * (|l| + |r|), eps = 2^-53, l and r the two rounded products, when nothing underflows.
// We accept the sign when |det| > 4 eps (|l| + |r|) and |l| + |r| >= 2^-900: underflow can
// add at most 2^-1074 in absolute terms, far below the slack eps * 2^-900 between the two
// bounds. A sum |l| + |r| that is infinite or NaN (overflow) also goes to the fallback. A
// zero factor on each side makes det exactly zero (a rounded difference of doubles is zero
// only when the exact one is), which decides axis-parallel collinear triples without GMP.
// All other predicates here use orientation signs and exact comparisons of coordinates.
// Contract: finite coordinates (readers and validate_shape reject NaN and infinity).
// Complexity: O(1) per orientation (the fallback costs a few GMP rational operations);
// locate_in_ring O(n) for n vertices.
// Section: docs/design.md 3; the input side of the 2D pipeline (dissertation 2.1.2, 3.3.2).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry2/point2.h"
#include "geometry2/shape2.h"

namespace grassfire {

// How often each stage of the orientation predicate decided.
struct OrientationStats {
  std::uint64_t filtered = 0;  // decided by the double filter (or the exact-zero shortcut)
  std::uint64_t exact = 0;     // decided exactly (GMP, or doubles on small integers)
  void merge(const OrientationStats& o) {
    filtered += o.filtered;
    exact += o.exact;
  }
};

// Sign of det[b - a, c - a]: +1 when a, b, c turn left (counter-clockwise), -1 right, 0 collinear.
int orientation(const Point2& a, const Point2& b, const Point2& c, OrientationStats* stats = nullptr);

// How two closed segments p0p1 and q0q1 meet. Zero-length segments are allowed.
enum class SegmentIntersection {
  Disjoint,  // no common point
  Crossing,  // one common point, interior to both segments
  Touching,  // one common point, an endpoint of at least one segment
  Overlap,   // collinear with infinitely many common points
};
const char* to_string(SegmentIntersection kind);

SegmentIntersection classify_segments(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1,
                                      OrientationStats* stats = nullptr);

// True when q lies on the closed segment ab (exact).
bool on_segment(const Point2& q, const Point2& a, const Point2& b, OrientationStats* stats = nullptr);

// Contribution of the edge a -> b to the winding number of q, by the crossing rule on the
// ray from q towards +x with half-open vertical ranges (a vertex on the ray's line counts
// as lying below it): +1 for an upward edge crossing the ray, -1 downward, 0 otherwise.
// Contract: q is not on the closed segment ab.
int winding_step(const Point2& q, const Point2& a, const Point2& b, OrientationStats* stats = nullptr);

// Where a point lies relative to a closed curve or a region (CGAL's name for the concept).
enum class BoundedSide { Inside, Boundary, Outside };
const char* to_string(BoundedSide side);

// Location of q relative to the closed polygonal curve `ring` (the closing edge is implicit).
// Inside means a non-zero winding number; for a simple ring that is the bounded component.
BoundedSide locate_in_ring(const Point2& q, const std::vector<Point2>& ring, OrientationStats* stats = nullptr);

// Location of q relative to a validated shape: inside the outer ring and outside every hole.
BoundedSide locate_in_shape(const Point2& q, const Shape2& shape, OrientationStats* stats = nullptr);

}  // namespace grassfire
