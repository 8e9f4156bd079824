// edge_fronts.cpp -- see edge_fronts.h.
#include "burn3/exact/edge_fronts.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grassfire {

namespace {

Interval sq(const Interval& x) { return square(x); }
Ball sq(const Ball& x) { return x * x; }

template <class T>
T time_of(const FrontCoefficients<T>& c, const T& l) {
  if (c.plane) return c.c0 + c.c1 * l;
  return c.sigma + sqrt(c.delta * sq(l - c.l0) + c.h2);
}

FrontCoefficients<Ball> coefficients(Certifier& cert, std::uint32_t w, std::uint32_t edge, bool on_line,
                                     const Interval& corner) {
  const Certifier::Along a = cert.along_edge(w, edge);
  FrontCoefficients<Ball> c;
  c.plane = a.b.plane;
  if (c.plane) {
    c.c0 = a.b.offset + a.b.source.x * a.A.x + a.b.source.y * a.A.y;
    c.c1 = a.b.source.x * a.D.x + a.b.source.y * a.D.y;
    return c;
  }
  const Ball x = a.A.x - a.b.source.x, y = a.A.y - a.b.source.y;
  c.sigma = a.b.offset;
  c.delta = a.D.x * a.D.x + a.D.y * a.D.y;
  c.l0 = Ball(0.0) - (x * a.D.x + y * a.D.y) / c.delta;
  const Ball cross = x * a.D.y - y * a.D.x;
  c.h2 = cross * cross / c.delta;
  if (on_line) {
    c.on_line = true, c.h2 = Ball(0.0);
    c.l0 = intersect(c.l0, corner.is_point() ? Ball(corner.lo) : Ball::from_interval(corner));
  }
  return c;
}

}  // namespace

Interval front_time(const FrontCoefficients<Interval>& c, const Interval& l) { return time_of(c, l); }
Ball front_time(const FrontCoefficients<Ball>& c, const Ball& l) { return time_of(c, l); }

Interval front_rate(const FrontCoefficients<Interval>& c, const Interval& l) {
  if (c.plane) return c.c1;
  // delta u / sqrt(delta u^2 + h2), of modulus at most sqrt(delta)
  const Interval len = sqrt(c.delta), u = l - c.l0;
  if (c.on_line && l.lo >= c.l0.hi) return len;  // after the corner
  if (c.on_line && l.hi <= c.l0.lo) return -len;
  const Interval n = sqrt(c.delta * square(u) + c.h2);
  if (!(n.lo > 0.0)) return {-len.hi, len.hi};
  const Interval r = c.delta * u / n;
  return {std::max(r.lo, -len.hi), std::min(r.hi, len.hi)};
}

Ball front_rate(const FrontCoefficients<Ball>& c, const Ball& l) {
  if (c.plane) return c.c1;
  const Ball u = l - c.l0;
  if (c.on_line) {
    const Interval i = l.to_interval(), at = c.l0.to_interval();
    if (i.lo >= at.hi) return sqrt(c.delta);
    if (i.hi <= at.lo) return Ball(0.0) - sqrt(c.delta);
  }
  return c.delta * u / sqrt(c.delta * sq(u) + c.h2);  // an infinite ball where the norm may vanish
}

double front_difference_bound(const FrontCoefficients<Ball>& a, const FrontCoefficients<Ball>& b, double lo, double hi) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (a.plane != b.plane) return kInf;
  const Ball L = hull(Ball(lo), Ball(hi));
  auto mag = [](const Ball& x) {
    const Interval i = x.to_interval();
    return std::max(-i.lo, i.hi);
  };
  if (a.plane) return mag(a.c0 - b.c0 + (a.c1 - b.c1) * L);
  // P_a - P_b = (delta_a - delta_b)(l - l0_a)^2 + delta_b (l0_b - l0_a)(2 l - l0_a - l0_b) + h2_a - h2_b,
  // small where the coefficients agree, on any range.
  const Ball dp = (a.delta - b.delta) * sq(L - a.l0) + b.delta * (b.l0 - a.l0) * (L + L - a.l0 - b.l0) + a.h2 - b.h2;
  const double s = mag(a.sigma - b.sigma), p = mag(dp);
  if (!std::isfinite(s) || !std::isfinite(p)) return kInf;
  const Interval r = Interval(s) + sqrt(Interval(p));  // outward rounded
  return r.hi;
}

EdgeFront& EdgeFronts::front(Certifier& cert, std::uint32_t w, std::uint32_t edge, bool on_line,
                             const Interval& corner) {
  const std::uint64_t key = (std::uint64_t(w) << 32) | edge;
  auto it = fronts_.find(key);
  if (it != fronts_.end()) return it->second;
  EdgeFront& f = fronts_[key];
  f.corner = corner;
  BallPrecision guard(128);
  f.balls[0] = std::make_unique<FrontCoefficients<Ball>>(coefficients(cert, w, edge, on_line, corner));
  const FrontCoefficients<Ball>& b = *f.balls[0];
  f.d.plane = b.plane, f.d.on_line = b.on_line;
  f.d.c0 = b.c0.to_interval(), f.d.c1 = b.c1.to_interval();
  f.d.sigma = b.sigma.to_interval(), f.d.delta = b.delta.to_interval();
  f.d.l0 = b.l0.to_interval(), f.d.h2 = b.h2.to_interval();
  if (!b.plane) f.d.h2.lo = std::max(f.d.h2.lo, 0.0);  // a squared distance
  if (b.on_line) f.d.l0 = intersect(f.d.l0, corner);
  return f;
}

const FrontCoefficients<Ball>& EdgeFronts::ball(Certifier& cert, std::uint32_t w, std::uint32_t edge, int level) {
  const std::uint64_t key = (std::uint64_t(w) << 32) | edge;
  EdgeFront& f = fronts_.at(key);
  if (!f.balls[level]) {
    BallPrecision guard(cert.max_bits());
    f.balls[level] = std::make_unique<FrontCoefficients<Ball>>(coefficients(cert, w, edge, f.d.on_line, f.corner));
  }
  return *f.balls[level];
}

}  // namespace grassfire
