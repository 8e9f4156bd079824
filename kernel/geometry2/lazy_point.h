// lazy_point.h -- rational points of the plane known by an interval and, on demand, exactly.
//
// Computes: the orientation predicate over points that are either input doubles or
// circumcentres of three input doubles (Voronoi vertices of boundary samples, 2.1.2).
// A circumcentre is rational; it is kept as its three defining points plus an interval
// enclosure, and its exact coordinates (GMP rationals) are computed only when the interval
// filter cannot decide a sign (docs/design.md 3: filter, then exact; fallbacks are counted).
// Contract: the three defining points of a circumcentre are not collinear.
// Complexity: O(1) per predicate; the exact fallback costs a few dozen GMP operations.
#pragma once

#include <gmpxx.h>

#include <cstdint>

#include "geometry2/point2.h"
#include "geometry2/predicates2.h"
#include "number/interval.h"
#include "number/long_interval.h"

namespace grassfire {

struct IntervalPoint2 {
  Interval x, y;
};

struct ExactPoint2 {
  mpq_class x, y;
};

class LazyPoint {
 public:
  LazyPoint() = default;
  static LazyPoint input(const Point2& p);
  static LazyPoint circumcenter(const Point2& a, const Point2& b, const Point2& c);
  // The same, with an enclosure already computed by interval_circumcenter(a, b, c).
  static LazyPoint circumcenter(const Point2& a, const Point2& b, const Point2& c, const IntervalPoint2& approx);

  bool is_input() const { return !is_circumcenter_; }
  const IntervalPoint2& approx() const { return approx_; }
  Point2 nearest() const { return {approx_.x.mid(), approx_.y.mid()}; }
  ExactPoint2 exact() const;
  // Exact squared distance to an input point.
  mpq_class squared_distance(const Point2& p) const;

 private:
  bool is_circumcenter_ = false;
  Point2 a_, b_, c_;  // a_ alone for an input point
  IntervalPoint2 approx_;
};

// Sign of the orientation of (p, q, r): +1 left turn, -1 right turn, 0 collinear. Exact.
int orientation(const LazyPoint& p, const LazyPoint& q, const LazyPoint& r, OrientationStats* counters = nullptr);

// Exact circumcentre and its interval enclosure.
ExactPoint2 exact_circumcenter(const Point2& a, const Point2& b, const Point2& c);
IntervalPoint2 interval_circumcenter(const Point2& a, const Point2& b, const Point2& c);

// Enclosures of the circumcircle: centre and radius, tight even for thin triangles.
struct Circle {
  IntervalPoint2 center;
  Interval radius;
};
Circle interval_circle(const Point2& a, const Point2& b, const Point2& c);
// The same in x87 extended precision (11 more bits); false for a nearly degenerate or
// extreme triangle, for which the caller must use the exact circumcentre.
bool long_circle(const Point2& a, const Point2& b, const Point2& c, LongInterval& x, LongInterval& y,
                 LongInterval& radius);

// Interval enclosure of an exact rational point.
IntervalPoint2 enclose(const ExactPoint2& p);

}  // namespace grassfire
