// window_values.h -- the double stage of the engine's predicates: enclosures of a window's
// wedge sides and times at points given as discs or interval boxes.
//
// Computes, two ways: Interval arithmetic on the bounding boxes of the discs (nothing is
// chained, so there is no wrapping), and, for the hot tests, plain doubles with an error
// bound from the disc radii (Approx: |exact - v| <= e; the bounds below say why):
//  - side(w, B, X) = cross(B - S, X - S) for a point source S, cross(u, X - B) for a plane
//    wave with direction u: > 0 when X lies counter-clockwise of the ray through B;
//  - the time of w at X: offset + |X - S|, or c + u . X;
//  - the parameter where the ray of w through B meets the line P -> Q;
//  - a certified lower bound of w's times over a segment (the queue key).
// Never NaN: where an input disc is unknown (DiscPoint::unknown(), infinite radius) or a
// value overflows, the Approx is {0, +infinity} (its sign undecided, its lower end -infinity)
// and a ray hit is not `ok`, so the filter fails and the next stage decides (a sliver with
// a 1e-17 edge on tripod-s2.ma made NaN here, which broke the queue's order).
// Contract: windows as windows.h defines them. Complexity: O(1).
#pragma once

#include <cmath>
#include <limits>

#include "burn3/exact/windows.h"

namespace grassfire {

struct IPoint {
  Interval x, y;
};

// A double v with |exact - v| <= e.
struct Approx {
  double v = 0.0, e = 0.0;
  int sign() const { return v > e ? 1 : v < -e ? -1 : (v == 0.0 && e == 0.0) ? 0 : kUndecided; }
};
constexpr double kUnit = 0x1p-53;  // unit roundoff

// v within e (e inflated for its own rounding), or {0, inf} when either is not finite.
inline Approx bounded(double v, double e) {
  const double eb = e * (1 + 8 * kUnit) + 0x1p-1000;
  if (!std::isfinite(v) || !std::isfinite(eb)) return {0.0, std::numeric_limits<double>::infinity()};
  return {v, eb};
}

// side(B, X) = cross(a, b), a = B - S, b = X - S: moving the points within their discs
// moves a by da <= rB + rS and b by db <= rX + rS, so the cross product by at most
// |da||b| + |a||db| + |da||db|; the three roundings of the subtractions and the two
// products and the difference add at most 6 u |a|_1 |b|_1. For a plane wave a = u (|u| = 1
// within rS) and b = X - B.
inline Approx approx_side(const Window& w, const DiscPoint& b, const DiscPoint& x) {
  const DiscPoint& s = w.source;
  const bool plane = w.plane();
  const double ax = plane ? s.x : b.x - s.x, ay = plane ? s.y : b.y - s.y;
  const double bx = plane ? x.x - b.x : x.x - s.x, by = plane ? x.y - b.y : x.y - s.y;
  const double da = plane ? s.r : b.r + s.r, db = plane ? x.r + b.r : x.r + s.r;
  const double na = std::fabs(ax) + std::fabs(ay), nb = std::fabs(bx) + std::fabs(by);
  const double v = ax * by - ay * bx;
  const double e = da * nb + na * db + da * db + 6 * kUnit * na * nb;
  return bounded(v, e);
}

// cross(a, b) for vectors known within da and db (|a~ - a| <= da, |b~ - b| <= db).
inline Approx approx_cross(double ax, double ay, double da, double bx, double by, double db) {
  const double na = std::fabs(ax) + std::fabs(ay), nb = std::fabs(bx) + std::fabs(by);
  const double e = da * nb + na * db + da * db + 6 * kUnit * na * nb;
  return bounded(ax * by - ay * bx, e);
}

// The point where the ray of w through the bound image b meets the line p -> q, as a disc:
// mu = N / D with N = cross(d, S - p) (or cross(u, b - p)), D = cross(d, q - p); then
// |mu~ - mu| <= (eN + |mu~| eD) / (|D~| - eD) + 2 u |mu~|, and X = p + mu (q - p) within
// rp + |mu - mu~| |q - p| + |mu~| (rp + rq) + 3 u (|p| + |mu~ (q - p)|), |q - p| <=
// |q~ - p~| + rp + rq. `ok` is false when
// the ray may be parallel to the line (|D~| <= eD).
struct RayHit {
  bool ok = false;
  DiscPoint point;
};
inline RayHit approx_ray_hit(const Window& w, const DiscPoint& b, const DiscPoint& p, const DiscPoint& q) {
  const DiscPoint& s = w.source;
  const bool plane = w.plane();
  const double dx = plane ? s.x : b.x - s.x, dy = plane ? s.y : b.y - s.y, dd = plane ? s.r : b.r + s.r;
  const double qx = q.x - p.x, qy = q.y - p.y, dq = q.r + p.r;
  const Approx den = approx_cross(dx, dy, dd, qx, qy, dq);
  const Approx num = plane ? approx_cross(dx, dy, dd, b.x - p.x, b.y - p.y, b.r + p.r)
                           : approx_cross(dx, dy, dd, s.x - p.x, s.y - p.y, s.r + p.r);
  const double ad = std::fabs(den.v);
  if (!(ad > den.e)) return {};
  const double mu = num.v / den.v;
  const double emu = (num.e + std::fabs(mu) * den.e) / (ad - den.e) + 2 * kUnit * std::fabs(mu);
  const double x = p.x + mu * qx, y = p.y + mu * qy;
  const double nq = std::fabs(qx) + std::fabs(qy);
  const double r = p.r + emu * (nq + dq) + std::fabs(mu) * dq +
                   3 * kUnit * (std::fabs(p.x) + std::fabs(p.y) + std::fabs(mu) * nq);
  const DiscPoint hit = DiscPoint::checked(x, y, r * (1 + 8 * kUnit) + 0x1p-1000);
  if (!hit.known()) return {};
  return {true, hit};
}

// time(X) = sigma + |X - S|: |X - S| moves by at most rX + rS; its double evaluation errs by
// at most 4 u |X - S| (two products, a sum, a square root), the final sum by u |v|. For a
// plane wave c + u . X: |u . X - u~ . X~| <= rS |X| + rX (1 + rS), roundings 4 u (|c| + |u.X|).
inline Approx approx_time(const Window& w, const DiscPoint& x) {
  const DiscPoint& s = w.source;
  const double c = w.offset.mid(), cr = w.offset.radius();
  if (w.plane()) {
    const double p = s.x * x.x + s.y * x.y;
    const double v = c + p;
    const double e = cr + s.r * (std::fabs(x.x) + std::fabs(x.y)) + x.r * (1 + s.r) +
                     4 * kUnit * (std::fabs(c) + std::fabs(s.x * x.x) + std::fabs(s.y * x.y));
    return bounded(v, e);
  }
  const double dx = x.x - s.x, dy = x.y - s.y;
  const double d = std::sqrt(dx * dx + dy * dy);
  const double v = c + d;
  const double e = cr + s.r + x.r + 4 * kUnit * d + kUnit * std::fabs(v);
  return bounded(v, e);
}
inline IPoint ipoint(const DiscPoint& p) { return {p.ix(), p.iy()}; }
inline Interval icross(const Interval& ax, const Interval& ay, const Interval& bx, const Interval& by) {
  return ax * by - ay * bx;
}

inline Interval window_side(const Window& w, const IPoint& b, const IPoint& x) {
  const IPoint s = ipoint(w.source);
  if (w.plane()) return icross(s.x, s.y, x.x - b.x, x.y - b.y);
  return icross(b.x - s.x, b.y - s.y, x.x - s.x, x.y - s.y);
}

inline Interval window_time(const Window& w, const IPoint& x) {
  const IPoint s = ipoint(w.source);
  if (w.plane()) return w.offset + s.x * x.x + s.y * x.y;
  return w.offset + sqrt(square(x.x - s.x) + square(x.y - s.y));
}

// The direction in which w's front reaches x (x - S, or u).
inline IPoint window_direction(const Window& w, const IPoint& x) {
  const IPoint s = ipoint(w.source);
  if (w.plane()) return s;
  return {x.x - s.x, x.y - s.y};
}

// The point where the ray of w through b (a bound image) meets the line p -> q, as
// p + mu (q - p); nullopt-like: `ok` false when the ray may be parallel to the line.
struct IRayHit {
  bool ok = false;
  IPoint point;
};
inline IRayHit window_ray_hit(const Window& w, const IPoint& b, const IPoint& p, const IPoint& q) {
  const IPoint s = ipoint(w.source);
  const Interval dx = w.plane() ? s.x : b.x - s.x, dy = w.plane() ? s.y : b.y - s.y;
  const Interval den = icross(dx, dy, q.x - p.x, q.y - p.y);
  if (certified_sign(den) == kUndecided || certified_sign(den) == 0) return {};
  const Interval mu = icross(dx, dy, b.x - p.x, b.y - p.y) / den;
  return {true, {p.x + mu * (q.x - p.x), p.y + mu * (q.y - p.y)}};
}

// A certified lower bound of w's times on the segment [a, b] (both enclosed by boxes).
inline double window_lower_bound(const Window& w, const IPoint& a, const IPoint& b) {
  if (w.plane()) {
    const Interval ta = window_time(w, a), tb = window_time(w, b);
    return std::min(ta.lo, tb.lo);
  }
  const IPoint s = ipoint(w.source);
  const Interval abx = b.x - a.x, aby = b.y - a.y;
  const Interval len2 = square(abx) + square(aby);
  const Interval ta = window_time(w, a), tb = window_time(w, b);
  const double ends = std::min(ta.lo, tb.lo);
  if (len2.lo <= 0.0) return ends;
  // Foot of S on the line: mu = (S - a).(b - a) / |b - a|^2. If certainly outside [0, 1]
  // the nearest point is an endpoint; else the distance to the line is a lower bound.
  const Interval mu = ((s.x - a.x) * abx + (s.y - a.y) * aby) / len2;
  if (mu.hi < 0.0 || mu.lo > 1.0) return ends;
  const Interval line = sqrt(square(icross(abx, aby, s.x - a.x, s.y - a.y)) / len2);
  return std::min(ends, (w.offset + line).lo);
}

// dot(a, b) for vectors known within da and db (the same bound as approx_cross).
inline Approx approx_dot(double ax, double ay, double da, double bx, double by, double db) {
  const Approx c = approx_cross(ax, ay, da, bx, by, db);
  return {ax * bx + ay * by, c.e};
}

// A certified lower bound of w's times on the segment [a, b] (discs). Point source: the
// nearest end when the foot of S certainly lies beyond it ((S - a).(b - a) < 0, or the
// same at b), else the distance to the line (a lower bound of the distance to the
// segment), perturbed by the radii (the line moves by at most max(ra, rb), S by rS) and
// the roundings.
inline double approx_lower_bound(const Window& w, const DiscPoint& a, const DiscPoint& b) {
  const Approx ta = approx_time(w, a), tb = approx_time(w, b);
  const double ends = std::min(ta.v - ta.e, tb.v - tb.e);
  if (w.plane()) return ends;
  const DiscPoint& s = w.source;
  const double abx = b.x - a.x, aby = b.y - a.y, len2 = abx * abx + aby * aby;
  if (!(len2 > 0)) return ends;
  const Approx da = approx_dot(s.x - a.x, s.y - a.y, s.r + a.r, abx, aby, a.r + b.r);
  const Approx db = approx_dot(s.x - b.x, s.y - b.y, s.r + b.r, -abx, -aby, a.r + b.r);
  if (da.sign() == -1 || db.sign() == -1) return ends;
  const double len = std::sqrt(len2);
  const double cr = std::fabs(abx * (s.y - a.y) - aby * (s.x - a.x));
  const double line = cr / len;
  const double err = s.r + std::max(a.r, b.r) + 8 * kUnit * (line + std::fabs(s.x - a.x) + std::fabs(s.y - a.y));
  const double lo = w.offset.lo + line - err * (1 + 8 * kUnit) - 0x1p-1000;
  if (std::isnan(lo)) return -std::numeric_limits<double>::infinity();
  return std::min(ends, lo);
}

}  // namespace grassfire
