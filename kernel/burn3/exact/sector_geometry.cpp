// sector_geometry.cpp -- see sector_geometry.h.
#include "burn3/exact/sector_geometry.h"

#include <algorithm>
#include <cmath>

#include "geometry3/exact_predicates3.h"
#include "number/ball_exact_sum.h"

namespace grassfire {

namespace {

using UV = std::array<mpq_class, 2>;

// The other end of edge e from vertex v.
std::uint32_t other_end(const MedialComplex& mc, std::uint32_t e, std::uint32_t v) {
  return mc.edge(e).v[0] == v ? mc.edge(e).v[1] : mc.edge(e).v[0];
}

// An open fan in a planar frame: its angle exceeds pi iff the turn from its first end edge
// to its last, in the fan's sense of rotation, is reflex (exactly pi: a straight border).
bool planar_open_fan_bends(const Unfolding& u, const Sector& s) {
  const MedialComplex& mc = u.complex();
  const std::uint32_t f = u.frame(s.triangles[0]), v = s.apex;
  const UV& o = u.vertex_uv(f, v);
  auto dir = [&](std::uint32_t e) {
    const UV& p = u.vertex_uv(f, other_end(mc, e, v));
    return UV{p[0] - o[0], p[1] - o[1]};
  };
  const auto first_edges = edges_at(mc.triangle(s.triangles[0]), v);
  const std::uint32_t next = first_edges[0] == s.ends[0] ? first_edges[1] : first_edges[0];
  const UV a = dir(s.ends[0]), b = dir(s.ends[1]), c = dir(next);
  const int sense = sgn(a[0] * c[1] - a[1] * c[0]);
  const int turn = sgn(a[0] * b[1] - a[1] * b[0]) * sense;
  if (turn != 0) return turn < 0;
  return sgn(a[0] * b[0] + a[1] * b[1]) > 0;  // the two ends coincide: a full turn (2 pi)
}

// The fan's angle against pi (open) or 2 pi (closed) in Arb: -1 below, +1 above, 0 undecided.
int arb_fan_angle(const MedialComplex& mc, const Sector& s) {
  for (long bits = 64; bits <= 256; bits *= 2) {
    BallPrecision guard(bits);
    Ball sum(0.0);
    for (std::uint32_t t : s.triangles) {
      const auto es = edges_at(mc.triangle(t), s.apex);
      const ExactPoint3& o = mc.vertex(s.apex).exact;
      const ExactPoint3 a = mc.vertex(other_end(mc, es[0], s.apex)).exact - o;
      const ExactPoint3 b = mc.vertex(other_end(mc, es[1], s.apex)).exact - o;
      const ExactPoint3 c = cross(a, b);
      const Ball y = sqrt(ball_of(dot(c, c))), x = ball_of(dot(a, b));
      Ball angle;
      arb_atan2(angle.get(), y.get(), x.get(), bits);
      sum += angle;
    }
    Ball limit;
    arb_const_pi(limit.get(), bits);
    if (s.closed) limit = limit + limit;
    const int sg = (sum - limit).sign();
    if (sg == 1 || sg == -1) return sg;
  }
  return 0;
}

// The corner vectors a = A - apex, b = B - apex of triangle t's corner at the apex.
void corner_vectors(const Unfolding& u, const Sector& s, std::uint32_t t, std::array<Interval, 3>* a,
                    std::array<Interval, 3>* b) {
  const MedialComplex& mc = u.complex();
  const auto es = edges_at(mc.triangle(t), s.apex);
  const auto& o = u.vertex_interval(s.apex);
  const auto& pa = u.vertex_interval(other_end(mc, es[0], s.apex));
  const auto& pb = u.vertex_interval(other_end(mc, es[1], s.apex));
  for (int k = 0; k < 3; ++k) (*a)[k] = pa[k] - o[k], (*b)[k] = pb[k] - o[k];
}

// The same, fast and rigorous: the product z = prod e^{i theta_j} of the corners' unit
// complex numbers (cos theta_j = a.b / |a||b|, sin theta_j = |a x b| / |a||b| >= 0) in
// Interval arithmetic, with Theta's quadrant tracked along the product: each corner adds
// theta_j in (0, pi), so the partial sum moves from quadrant n to one of n, n + 1, n + 2
// (three quadrants, distinct mod 4), which the certified signs of z's real and imaginary
// parts name. Theta's quadrant then places it against pi (quadrant index >= 2) or 2 pi
// (>= 4). 0 when a sign is not certified (z on an axis: Theta at a multiple of pi / 2, an
// exact pi among them; Arb and the caller decide).
int interval_fan_angle(const Unfolding& u, const Sector& s) {
  Interval re(1.0), im(0.0);
  int quadrant = 0;  // Theta in [quadrant pi / 2, (quadrant + 1) pi / 2)
  for (std::uint32_t t : s.triangles) {
    std::array<Interval, 3> a, b;
    corner_vectors(u, s, t, &a, &b);
    const Interval dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const Interval cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
    const Interval cr = sqrt(square(cx) + square(cy) + square(cz));
    const Interval n = sqrt((square(a[0]) + square(a[1]) + square(a[2])) * (square(b[0]) + square(b[1]) + square(b[2])));
    if (n.lo <= 0.0) return 0;
    const Interval c = dot / n, sn = cr / n;
    const Interval r2 = re * c - im * sn, i2 = re * sn + im * c;
    re = r2, im = i2;
    const int sr = certified_sign(re), si = certified_sign(im);
    if ((sr != 1 && sr != -1) || (si != 1 && si != -1)) return 0;
    const int q = si > 0 ? (sr > 0 ? 0 : 1) : (sr < 0 ? 2 : 3);  // quadrant mod 4
    int next = quadrant;
    while ((next & 3) != q) ++next;
    quadrant = next;  // within quadrant + 2: theta_j < pi
  }
  const int limit = s.closed ? 4 : 2;
  return quadrant >= limit ? 1 : -1;
}

// engine-double-bending (engine_mutant.h): the corner angles' sum in doubles against the
// limit, decided at a margin of 1e-6 (the rule before the certified one), else bends.
int double_fan_angle(const Unfolding& u, const Sector& s) {
  const double limit = s.closed ? 2 * M_PI : M_PI;
  double theta = 0.0;
  for (std::uint32_t t : s.triangles) {
    std::array<Interval, 3> a, b;
    corner_vectors(u, s, t, &a, &b);
    const double ax = a[0].mid(), ay = a[1].mid(), az = a[2].mid(), bx = b[0].mid(), by = b[1].mid(), bz = b[2].mid();
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    theta += std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz);
  }
  return std::fabs(theta - limit) > 1e-6 ? (theta > limit ? 1 : -1) : 1;
}

}  // namespace

SectorGeometry sector_geometry(const Unfolding& u, EngineMutant mutant) {
  const MedialComplex& mc = u.complex();
  SectorGeometry g;
  g.corner_sector.assign(3 * mc.triangle_count(), kNoIndex);
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = mc.triangle(t).v[i];
      g.corner_sector[3 * t + i] = mc.link_elements(v)[mc.corner_element(t, i)].id;
    }
  g.bends.assign(mc.sectors().size(), true);
  for (std::size_t k = 0; k < mc.sectors().size(); ++k) {
    const Sector& s = mc.sectors()[k];
    const std::uint32_t f0 = u.frame(s.triangles[0]);
    if (std::all_of(s.triangles.begin(), s.triangles.end(), [&](std::uint32_t t) { return u.frame(t) == f0; })) {
      g.bends[k] = !s.closed && planar_open_fan_bends(u, s);
      continue;
    }
    if (mutant == EngineMutant::double_bending) {
      g.bends[k] = double_fan_angle(u, s) >= 0;
      continue;
    }
    int c = interval_fan_angle(u, s);
    if (c == 0) c = arb_fan_angle(mc, s);
    if (c == 0) ++g.undecided_angles;
    g.bends[k] = c >= 0;
  }
  return g;
}

}  // namespace grassfire
