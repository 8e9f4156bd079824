// disc_point.h -- 2D points known to lie in a Euclidean disc (midpoint + radius), moved by
// rigid motions whose double matrices carry a certified error bound.
//
// Computes: enclosures of points (and unit directions) that are unfolded through long
// chains of rigid motions, as the exact burning engine does when a window crosses the
// edges of a curved sheet (kernel/burn3/exact/, docs/design.md 5a).
// Why discs and not boxes: a rotation maps a disc onto a disc of the same radius, whereas
// it maps an axis-aligned box onto a box up to sqrt(2) times wider (the wrapping effect);
// after k unfoldings boxes grow like 2^(k/2), discs grow by the rounding errors only, i.e.
// linearly in k. The predicates that use a DiscPoint evaluate once in Interval arithmetic
// on its bounding box, which costs no wrapping because nothing is chained there.
// Error model: apply() returns the double result of R~ p~ + T~ and the radius
//   r' = r + eR |p~| + eT + rounding,
// valid because the exact motion R p + T has |R| = 1 (R orthogonal): |R~ p~ - R p| <=
// |R~ - R| |p~| + |p~ - p|. eR bounds the spectral norm of R~ - R (by its Frobenius norm),
// eT the length of T~ - T; rounding of the two 3-term dot products is at most
// gamma_3 (|r00 x| + |r01 y| + |t0|) per coordinate (Higham, gamma_n = n u / (1 - n u)).
// Contract: the RigidMotion's bounds enclose an exact orthogonal motion. A point whose
// midpoint or radius is not finite (an enclosure that overflowed, a division by an interval
// holding 0, a motion with unbounded error) is `unknown()`: midpoint 0, radius +infinity,
// so that every filter built on it fails and the caller's next stage decides (never NaN).
// Complexity: O(1).
#pragma once

#include <cmath>
#include <limits>

#include "number/interval.h"

namespace grassfire {

struct DiscPoint {
  double x = 0.0, y = 0.0;
  double r = 0.0;  // |exact - (x, y)| <= r

  static DiscPoint unknown() { return {0.0, 0.0, std::numeric_limits<double>::infinity()}; }
  // (x, y, r) when all three are finite, else unknown().
  static DiscPoint checked(double x, double y, double r) {
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(r) ? DiscPoint{x, y, r} : unknown();
  }
  static DiscPoint from_intervals(const Interval& ix, const Interval& iy) {
    const double rx = ix.radius(), ry = iy.radius();
    return checked(ix.mid(), iy.mid(), round_up(std::sqrt(round_up(rx * rx + ry * ry))));
  }
  bool known() const { return std::isfinite(r); }
  Interval ix() const { return {round_down(x - r), round_up(x + r)}; }
  Interval iy() const { return {round_down(y - r), round_up(y + r)}; }
  double norm() const { return std::sqrt(x * x + y * y); }
};

// p -> R p + T with R orthogonal (a rotation, or a reflection when a sheet is not
// oriented consistently), stored as doubles with error bounds.
struct RigidMotion2 {
  double r00 = 1, r01 = 0, r10 = 0, r11 = 1;
  double t0 = 0, t1 = 0;
  double rot_error = 0.0;    // >= |R~ - R|_2
  double trans_error = 0.0;  // >= |T~ - T|
  bool reflect = false;      // det R = -1: clockwise and counter-clockwise swap

  DiscPoint apply(const DiscPoint& p) const {
    constexpr double gamma3 = 3.0 * 0x1p-53 / (1.0 - 3.0 * 0x1p-53);
    DiscPoint q;
    q.x = r00 * p.x + r01 * p.y + t0;
    q.y = r10 * p.x + r11 * p.y + t1;
    const double ex = gamma3 * (std::fabs(r00 * p.x) + std::fabs(r01 * p.y) + std::fabs(t0));
    const double ey = gamma3 * (std::fabs(r10 * p.x) + std::fabs(r11 * p.y) + std::fabs(t1));
    return DiscPoint::checked(q.x, q.y, grow(p.r + rot_error * p.norm() + trans_error + ex + ey));
  }
  // A direction (no translation), for plane waves.
  DiscPoint apply_vector(const DiscPoint& p) const {
    constexpr double gamma2 = 2.0 * 0x1p-53 / (1.0 - 2.0 * 0x1p-53);
    DiscPoint q;
    q.x = r00 * p.x + r01 * p.y;
    q.y = r10 * p.x + r11 * p.y;
    const double ex = gamma2 * (std::fabs(r00 * p.x) + std::fabs(r01 * p.y));
    const double ey = gamma2 * (std::fabs(r10 * p.x) + std::fabs(r11 * p.y));
    return DiscPoint::checked(q.x, q.y, grow(p.r + rot_error * p.norm() + ex + ey));
  }

 private:
  // The radius sum above is evaluated in doubles; inflate it by more than its own rounding
  // (a few ulps relative, and the norm's) so that it stays an upper bound.
  static double grow(double r) { return r * (1.0 + 0x1p-48) + 0x1p-1000; }
};

}  // namespace grassfire
