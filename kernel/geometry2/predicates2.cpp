// predicates2.cpp -- see predicates2.h.
#include "geometry2/predicates2.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace grassfire {

namespace {

constexpr double kEps = 0x1p-53;
// 4 eps > (3 + 16 eps) eps, Shewchuk's bound, with room for underflow (see the header).
constexpr double kOrientationBound = 4.0 * kEps;
constexpr double kSmallestFilteredSum = 0x1p-900;

int exact_orientation(const Point2& a, const Point2& b, const Point2& c) {
  // mpq_class(double) is exact: every finite double is a dyadic rational.
  const mpq_class cx(c.x), cy(c.y);
  const mpq_class det = (mpq_class(a.x) - cx) * (mpq_class(b.y) - cy) - (mpq_class(a.y) - cy) * (mpq_class(b.x) - cx);
  return sgn(det);
}

bool is_integer(const Point2& p) { return p.x == std::floor(p.x) && p.y == std::floor(p.y); }

}  // namespace

int orientation(const Point2& a, const Point2& b, const Point2& c, OrientationStats* stats) {
  const double acx = a.x - c.x, bcy = b.y - c.y, acy = a.y - c.y, bcx = b.x - c.x;
  if ((acx == 0.0 || bcy == 0.0) && (acy == 0.0 || bcx == 0.0)) {
    if (stats) ++stats->filtered;
    return 0;
  }
  const double left = acx * bcy, right = acy * bcx;
  const double det = left - right;
  const double sum = std::fabs(left) + std::fabs(right);
  if (sum >= kSmallestFilteredSum && sum <= std::numeric_limits<double>::max()) {
    const double bound = kOrientationBound * sum;
    if (det > bound || -det > bound) {
      if (stats) ++stats->filtered;
      return det > 0 ? 1 : -1;
    }
  }
  // Integer inputs whose differences are below 2^26 (integer frames, e.g. three collinear
  // polygon vertices): the differences, the products (< 2^52) and det (< 2^53) were all
  // computed exactly, so det's sign is the exact one (a difference computed below 2^26 is
  // exact: a rounded one would be at least 2^53).
  if (is_integer(a) && is_integer(b) && is_integer(c) && std::fabs(acx) < 0x1p26 && std::fabs(bcy) < 0x1p26 &&
      std::fabs(acy) < 0x1p26 && std::fabs(bcx) < 0x1p26) {
    if (stats) ++stats->exact;  // an exact evaluation, counted as before
    return det > 0 ? 1 : det < 0 ? -1 : 0;
  }
  if (stats) ++stats->exact;
  return exact_orientation(a, b, c);
}

const char* to_string(SegmentIntersection kind) {
  switch (kind) {
    case SegmentIntersection::Disjoint: return "disjoint";
    case SegmentIntersection::Crossing: return "crossing";
    case SegmentIntersection::Touching: return "touching";
    case SegmentIntersection::Overlap: return "overlap";
  }
  return "?";
}

const char* to_string(BoundedSide side) {
  switch (side) {
    case BoundedSide::Inside: return "inside";
    case BoundedSide::Boundary: return "boundary";
    case BoundedSide::Outside: return "outside";
  }
  return "?";
}

namespace {

// Common points of two collinear segments (all four points on one line): project on x
// unless the line is vertical; the projection is injective on the line, so comparing the
// projected intervals exactly decides how the segments meet.
SegmentIntersection classify_collinear(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1) {
  const bool vertical = p0.x == p1.x && p1.x == q0.x && q0.x == q1.x;
  auto coord = [vertical](const Point2& p) { return vertical ? p.y : p.x; };
  const double lo = std::max(std::min(coord(p0), coord(p1)), std::min(coord(q0), coord(q1)));
  const double hi = std::min(std::max(coord(p0), coord(p1)), std::max(coord(q0), coord(q1)));
  if (lo > hi) return SegmentIntersection::Disjoint;
  return lo == hi ? SegmentIntersection::Touching : SegmentIntersection::Overlap;
}

bool boxes_disjoint(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1) {
  return std::max(p0.x, p1.x) < std::min(q0.x, q1.x) || std::max(q0.x, q1.x) < std::min(p0.x, p1.x) ||
         std::max(p0.y, p1.y) < std::min(q0.y, q1.y) || std::max(q0.y, q1.y) < std::min(p0.y, p1.y);
}

}  // namespace

SegmentIntersection classify_segments(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1,
                                      OrientationStats* stats) {
  if (boxes_disjoint(p0, p1, q0, q1)) return SegmentIntersection::Disjoint;
  const int q0_side = orientation(p0, p1, q0, stats), q1_side = orientation(p0, p1, q1, stats);
  if (q0_side == q1_side && q0_side != 0) return SegmentIntersection::Disjoint;
  const int p0_side = orientation(q0, q1, p0, stats), p1_side = orientation(q0, q1, p1, stats);
  if (p0_side == p1_side && p0_side != 0) return SegmentIntersection::Disjoint;
  if (q0_side == 0 && q1_side == 0 && p0_side == 0 && p1_side == 0) return classify_collinear(p0, p1, q0, q1);
  // Not all collinear and each segment meets the other's line: exactly one common point.
  if (q0_side * q1_side < 0 && p0_side * p1_side < 0) return SegmentIntersection::Crossing;
  return SegmentIntersection::Touching;
}

bool on_segment(const Point2& q, const Point2& a, const Point2& b, OrientationStats* stats) {
  if (q.x < std::min(a.x, b.x) || q.x > std::max(a.x, b.x) || q.y < std::min(a.y, b.y) || q.y > std::max(a.y, b.y))
    return false;
  return orientation(a, b, q, stats) == 0;
}

int winding_step(const Point2& q, const Point2& a, const Point2& b, OrientationStats* stats) {
  const bool a_below = a.y <= q.y, b_below = b.y <= q.y;
  if (a_below == b_below) return 0;
  // The edge crosses the line y = q.y; the crossing is right of q when q is left of an
  // upward edge or right of a downward one.
  const int side = orientation(a, b, q, stats);
  if (a_below) return side > 0 ? 1 : 0;
  return side < 0 ? -1 : 0;
}

BoundedSide locate_in_ring(const Point2& q, const std::vector<Point2>& ring, OrientationStats* stats) {
  long winding = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % n];
    if (on_segment(q, a, b, stats)) return BoundedSide::Boundary;
    winding += winding_step(q, a, b, stats);
  }
  return winding != 0 ? BoundedSide::Inside : BoundedSide::Outside;
}

BoundedSide locate_in_shape(const Point2& q, const Shape2& shape, OrientationStats* stats) {
  if (shape.rings.empty()) return BoundedSide::Outside;
  const BoundedSide outer = locate_in_ring(q, shape.rings[0].points, stats);
  if (outer != BoundedSide::Inside) return outer;
  for (std::size_t r = 1; r < shape.rings.size(); ++r) {
    const BoundedSide hole = locate_in_ring(q, shape.rings[r].points, stats);
    if (hole == BoundedSide::Boundary) return BoundedSide::Boundary;
    if (hole == BoundedSide::Inside) return BoundedSide::Outside;
  }
  return BoundedSide::Inside;
}

}  // namespace grassfire
