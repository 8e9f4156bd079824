// window_values.h -- the double stage of the engine's predicates: enclosures of a window's
// wedge sides and times at points given as discs or interval boxes.
//
// Computes (Interval arithmetic on the bounding boxes of the discs; nothing is chained, so
// there is no wrapping):
//  - side(w, B, X) = cross(B - S, X - S) for a point source S, cross(u, X - B) for a plane
//    wave with direction u: > 0 when X lies counter-clockwise of the ray through B;
//  - the time of w at X: offset + |X - S|, or c + u . X;
//  - the parameter where the ray of w through B meets the line P -> Q;
//  - a certified lower bound of w's times over a segment (the queue key).
// Contract: windows as windows.h defines them. Complexity: O(1).
#pragma once

#include "burn3/exact/windows.h"

namespace grassfire {

struct IPoint {
  Interval x, y;
};
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

}  // namespace grassfire
