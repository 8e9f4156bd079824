// sources.cpp -- see sources.h.
#include "burn3/exact/sources.h"

#include <stdexcept>

#include "geometry3/exact_predicates3.h"
#include "number/ball_exact_sum.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

Interval as_number(const mpq_class& q, const Interval&) { return enclose(q); }
Ball as_number(const mpq_class& q, const Ball&) { return ball_of(q); }

template <class N>
struct P2 {
  N x, y;
};

// The unit normal of the edge A -> B pointing to the side `side` (+1: left).
template <class N>
P2<N> unit_normal(const P2<N>& a, const P2<N>& b, int side, N* length) {
  const N ex = b.x - a.x, ey = b.y - a.y;
  *length = sqrt(ex * ex + ey * ey);
  if (side > 0) return {N(0.0) - ey / *length, ex / *length};
  return {ey / *length, N(0.0) - ex / *length};
}

template <class N>
P2<N> rotated_point_in_frame(const P2<N>& a, const P2<N>& b, int side, const RotatedPoint& rp) {
  N len;
  const P2<N> n = unit_normal(a, b, side, &len);
  const N alpha = as_number(rp.alpha, len), h = sqrt(as_number(rp.h2, len));
  return {a.x + alpha * (b.x - a.x) - h * n.x, a.y + alpha * (b.y - a.y) - h * n.y};
}

// u and c of the plane wave of a Linear edge a -> b with R^2 values r2a, r2b.
template <class N>
std::pair<P2<N>, N> plane_wave_in_frame(const P2<N>& a, const P2<N>& b, int side, const mpq_class& r2a,
                                         const mpq_class& r2b) {
  N len;
  const P2<N> n = unit_normal(a, b, side, &len);
  const N f0 = sqrt(as_number(r2a, len)), f1 = sqrt(as_number(r2b, len));
  const N s = (f1 - f0) / len;
  const N c = sqrt(N(1.0) - s * s);
  const P2<N> u{s * (b.x - a.x) / len + c * n.x, s * (b.y - a.y) / len + c * n.y};
  return {u, f0 - (u.x * a.x + u.y * a.y)};
}

}  // namespace

std::uint32_t border_triangle(const MedialComplex& mc, std::uint32_t e) {
  const auto& ts = mc.edge_triangles(e);
  if (ts.size() != 1) throw std::logic_error("border_triangle: edge " + std::to_string(e) + " is not a border edge");
  return ts[0];
}

bool linear_plane_wave(const MedialComplex& mc, std::uint32_t e) {
  const ComplexEdge& ed = mc.edge(e);
  const mpq_class& a = mc.vertex(ed.v[0]).radius_squared;
  const mpq_class& b = mc.vertex(ed.v[1]).radius_squared;
  const mpq_class l2 = squared_distance(mc.vertex(ed.v[0]).exact, mc.vertex(ed.v[1]).exact);
  // (sqrt a - sqrt b)^2 < l2  <=>  a + b - l2 < 2 sqrt(ab)
  ExactSum d = ExactSum::rational(a + b - l2);
  d -= ExactSum::sqrt_of(4 * a * b);
  return exact_sign(d) < 0;
}

RotatedPoint rotated_point(const MedialComplex& mc, std::uint32_t e) {
  const ComplexEdge& ed = mc.edge(e);
  const ExactPoint3& a = mc.vertex(ed.v[0]).exact;
  const ExactPoint3 ab = mc.vertex(ed.v[1]).exact - a, ap = ed.rule_point - a;
  const mpq_class l2 = dot(ab, ab), t = dot(ap, ab);
  RotatedPoint r;
  r.alpha = t / l2;
  r.h2 = dot(ap, ap) - t * t / l2;
  return r;
}

std::optional<ExactSum> exact_vertex_ignition(const MedialComplex& mc, std::uint32_t v) {
  if (!mc.is_border_point(v)) return std::nullopt;
  std::optional<ExactSum> best;
  bool has_border_edge = false;
  for (std::uint32_t e : mc.vertex_edges(v)) {
    const ComplexEdge& ed = mc.edge(e);
    if (ed.stratum != EdgeStratum::Border) continue;
    has_border_edge = true;
    if (ed.rule == IgnitionRule::Never) continue;
    ExactSum f = ed.rule == IgnitionRule::Linear ? ExactSum::sqrt_of(mc.vertex(v).radius_squared)
                                                 : ExactSum::sqrt_of(squared_distance(mc.vertex(v).exact, ed.rule_point));
    f.simplify();
    if (!best || exact_sign(f - *best) < 0) best = f;
  }
  if (!has_border_edge) {
    ExactSum f = ExactSum::sqrt_of(mc.vertex(v).radius_squared);
    f.simplify();
    return f;
  }
  return best;
}

Ball edge_point_lambda_ball(const WindowStore& s, std::uint32_t id) {
  const EdgePoint& ep = s.edge_points[id];
  if (ep.exact >= 0) return ball_of(s.exact_times[ep.exact]);
  return ep.bracketed ? hull(ball_of(ep.lo), ball_of(ep.hi)) : Ball::from_interval(ep.lambda);
}

DiscPoint edge_point_image(const Unfolding& u, const WindowStore& s, std::uint32_t t, std::uint32_t id) {
  const EdgePoint& ep = s.edge_points[id];
  const auto& ev = u.complex().edge(ep.edge).v;
  const DiscPoint a = u.vertex_image(t, ev[0]), b = u.vertex_image(t, ev[1]);
  return DiscPoint::from_intervals(a.ix() + ep.lambda * (b.ix() - a.ix()), a.iy() + ep.lambda * (b.iy() - a.iy()));
}

BallVec2 edge_point_ball(const Unfolding& u, const WindowStore& s, std::uint32_t t, std::uint32_t id) {
  const auto& ev = u.complex().edge(s.edge_points[id].edge).v;
  const BallVec2 a = u.vertex_ball(t, ev[0]), b = u.vertex_ball(t, ev[1]);
  const Ball l = edge_point_lambda_ball(s, id);
  return {a.x + l * (b.x - a.x), a.y + l * (b.y - a.y)};
}

RootDisc root_disc(const Unfolding& u, const WindowStore& s, std::uint32_t p, std::uint32_t t) {
  const PseudoSource& ps = s.pseudo[p];
  const MedialComplex& mc = u.complex();
  RootDisc r;
  switch (ps.origin) {
    case SourceOrigin::GivenPoint:
      r.source = u.point_image(t, s.given[ps.data].point);
      r.offset = ps.sigma;
      return r;
    case SourceOrigin::Vertex:
      r.source = u.vertex_image(t, ps.vertex);
      r.offset = ps.sigma;
      return r;
    case SourceOrigin::EdgePoint:
      r.source = edge_point_image(u, s, t, ps.data);
      r.offset = ps.sigma;
      return r;
    case SourceOrigin::BorderPoint:
    case SourceOrigin::BorderPlane: {
      const std::uint32_t e = ps.data;
      const DiscPoint da = u.vertex_image(t, mc.edge(e).v[0]), db = u.vertex_image(t, mc.edge(e).v[1]);
      const P2<Interval> a{da.ix(), da.iy()}, b{db.ix(), db.iy()};
      const int side = u.edge_side(e, t);
      if (ps.origin == SourceOrigin::BorderPoint) {
        const P2<Interval> q = rotated_point_in_frame(a, b, side, rotated_point(mc, e));
        r.source = DiscPoint::from_intervals(q.x, q.y);
        r.offset = ps.sigma;
        return r;
      }
      const auto [w, c] = plane_wave_in_frame(a, b, side, mc.vertex(mc.edge(e).v[0]).radius_squared,
                                              mc.vertex(mc.edge(e).v[1]).radius_squared);
      r.source = DiscPoint::from_intervals(w.x, w.y);
      r.offset = c;
      r.plane = true;
      return r;
    }
  }
  return r;
}

RootBall root_ball(const Unfolding& u, const WindowStore& s, std::uint32_t p, std::uint32_t t, const Ball& sigma) {
  const PseudoSource& ps = s.pseudo[p];
  const MedialComplex& mc = u.complex();
  RootBall r;
  switch (ps.origin) {
    case SourceOrigin::GivenPoint:
      r.source = u.point_ball(t, s.given[ps.data].point);
      r.offset = sigma;
      return r;
    case SourceOrigin::Vertex:
      r.source = u.vertex_ball(t, ps.vertex);
      r.offset = sigma;
      return r;
    case SourceOrigin::EdgePoint:
      r.source = edge_point_ball(u, s, t, ps.data);
      r.offset = sigma;
      return r;
    case SourceOrigin::BorderPoint:
    case SourceOrigin::BorderPlane: {
      const std::uint32_t e = ps.data;
      const BallVec2 ba = u.vertex_ball(t, mc.edge(e).v[0]), bb = u.vertex_ball(t, mc.edge(e).v[1]);
      const P2<Ball> a{ba.x, ba.y}, b{bb.x, bb.y};
      const int side = u.edge_side(e, t);
      if (ps.origin == SourceOrigin::BorderPoint) {
        const P2<Ball> q = rotated_point_in_frame(a, b, side, rotated_point(mc, e));
        r.source = {q.x, q.y};
        r.offset = sigma;
        return r;
      }
      const auto [w, c] = plane_wave_in_frame(a, b, side, mc.vertex(mc.edge(e).v[0]).radius_squared,
                                              mc.vertex(mc.edge(e).v[1]).radius_squared);
      r.source = {w.x, w.y};
      r.offset = c;
      r.plane = true;
      return r;
    }
  }
  return r;
}

}  // namespace grassfire
