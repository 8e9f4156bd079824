// unfolding.cpp -- see unfolding.h.
#include "burn3/exact/unfolding.h"

#include <cmath>
#include <stdexcept>

#include "geometry3/exact_predicates3.h"
#include "support/union_find.h"
#include "number/ball_exact_sum.h"
#include "number/exact_sum.h"
#include "number/sqrt_field.h"

namespace grassfire {

BallVec2 BallMotion::apply(const BallVec2& p) const {
  return {r00 * p.x + r01 * p.y + t0, r10 * p.x + r11 * p.y + t1};
}
BallVec2 BallMotion::apply_vector(const BallVec2& p) const { return {r00 * p.x + r01 * p.y, r10 * p.x + r11 * p.y}; }

namespace {

std::array<Interval, 3> enclose3(const ExactPoint3& p) { return {enclose(p.x), enclose(p.y), enclose(p.z)}; }

Interval dot3(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::array<Interval, 3> sub3(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

std::array<Interval, 3> cross3(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}


// The rigid motion that maps the directed segment A->B (frame of t) onto A2->B2 (frame of
// t2), proper or reflecting; N is Interval or Ball.
template <class N>
std::array<N, 6> motion_from_edges(const N& ax, const N& ay, const N& bx, const N& by, const N& a2x, const N& a2y,
                                   const N& b2x, const N& b2y, bool proper) {
  const N dx = bx - ax, dy = by - ay, d2x = b2x - a2x, d2y = b2y - a2y;
  const N l = sqrt(dx * dx + dy * dy), l2 = sqrt(d2x * d2x + d2y * d2y);
  const N ux = dx / l, uy = dy / l, vx = d2x / l2, vy = d2y / l2;
  N r00, r01, r10, r11;
  if (proper) {
    r00 = vx * ux + vy * uy, r01 = vx * uy - vy * ux;
    r10 = vy * ux - vx * uy, r11 = vy * uy + vx * ux;
  } else {
    r00 = vx * ux - vy * uy, r01 = vx * uy + vy * ux;
    r10 = vy * ux + vx * uy, r11 = vy * uy - vx * ux;
  }
  const N t0 = a2x - (r00 * ax + r01 * ay);
  const N t1 = a2y - (r10 * ax + r11 * ay);
  return {r00, r01, r10, r11, t0, t1};
}

// A length enclosure usable as a divisor in the double stage: positive, and known to 2^-40
// relative. Slivers (a 1e-17 edge of tripod-s2.ma's axis among coordinates near 0.1) give
// enclosures that hold 0; their frames and crossings then come from the exact data.
bool tight(const Interval& l) { return l.lo > 0.0 && l.hi - l.lo <= 0x1p-40 * l.lo; }

double norm_of_radii(std::initializer_list<double> radii) {
  double s = 0.0;
  for (double r : radii) s += r * r;
  return round_up(std::sqrt(round_up(s)));
}

}  // namespace

Unfolding::Unfolding(const MedialComplex& mc) : mc_(mc) {
  vertex_iv_.resize(mc.vertex_count());
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) vertex_iv_[v] = enclose3(mc.vertex(v).exact);
  build_patches();
  frame_iv_.resize(frames_.size());
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    if (!frames_[f]) {  // one triangle abc: origin a, e1 = b - a, e2 = ((b - a) x (c - a)) x (b - a)
      const auto& tv = mc_.triangle(frame_triangle_[f]).v;
      const auto a = vertex_iv_[tv[0]], e1 = sub3(vertex_iv_[tv[1]], a), ac = sub3(vertex_iv_[tv[2]], a);
      const auto e2 = cross3(cross3(e1, ac), e1);
      const Interval s1 = sqrt(dot3(e1, e1)), s2 = sqrt(dot3(e2, e2));
      if (tight(s1) && tight(s2)) {
        frame_iv_[f] = {a, {e1[0] / s1, e1[1] / s1, e1[2] / s1}, {e2[0] / s2, e2[1] / s2, e2[2] / s2}};
        continue;
      }
      planar_frame(static_cast<std::uint32_t>(f));  // a sliver: the exact frame, enclosed below
    }
    const PlanarFrame& fr = *frames_[f];
    const Interval s1 = sqrt(enclose(fr.e1_norm2)), s2 = sqrt(enclose(fr.e2_norm2));
    const auto e1 = enclose3(fr.e1), e2 = enclose3(fr.e2);
    frame_iv_[f] = {enclose3(fr.origin), {e1[0] / s1, e1[1] / s1, e1[2] / s1}, {e2[0] / s2, e2[1] / s2, e2[2] / s2}};
  }
  compute_corners();
  compute_crossings();
}

// Coplanar patches: triangles joined across a manifold edge when the fourth vertex lies in
// the first triangle's plane (an Interval filter on the orientation determinant, then exact).
void Unfolding::build_patches() {
  const std::size_t T = mc_.triangle_count();
  UnionFind uf(T);
  for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
    if (mc_.edge(e).stratum != EdgeStratum::Manifold) continue;
    const auto& ts = mc_.edge_triangles(e);
    const auto& tv = mc_.triangle(ts[0]).v;
    const std::uint32_t d = third_vertex(mc_.triangle(ts[1]), mc_.edge(e).v);
    const auto a = vertex_iv_[tv[0]];
    const auto u = sub3(vertex_iv_[tv[1]], a), v = sub3(vertex_iv_[tv[2]], a), w = sub3(vertex_iv_[d], a);
    const Interval det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (certified_sign(det) != kUndecided && certified_sign(det) != 0) continue;
    const ExactPoint3& pa = mc_.vertex(tv[0]).exact;
    if (grassfire::orientation(pa, mc_.vertex(tv[1]).exact, mc_.vertex(tv[2]).exact, mc_.vertex(d).exact) == 0) uf.unite(ts[0], ts[1]);
  }
  triangle_frame_.assign(T, kNoIndex);
  std::vector<std::uint32_t> size;
  for (std::uint32_t t = 0; t < T; ++t) {
    const std::uint32_t r = uf.find(t);
    if (triangle_frame_[r] == kNoIndex) {
      triangle_frame_[r] = static_cast<std::uint32_t>(frame_triangle_.size());
      frame_triangle_.push_back(r);
      size.push_back(0);
    }
    triangle_frame_[t] = triangle_frame_[r];
    ++size[triangle_frame_[t]];
  }
  frames_.resize(frame_triangle_.size());
  shared_.resize(frames_.size());
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    shared_[f] = size[f] > 1;
    if (shared_[f]) planar_frame(static_cast<std::uint32_t>(f));
  }
}

const PlanarFrame& Unfolding::planar_frame(std::uint32_t f) const {
  if (!frames_[f]) {
    const auto& tv = mc_.triangle(frame_triangle_[f]).v;
    frames_[f] = std::make_unique<PlanarFrame>(
        frame_of_triangle(mc_.vertex(tv[0]).exact, mc_.vertex(tv[1]).exact, mc_.vertex(tv[2]).exact));
  }
  return *frames_[f];
}

void Unfolding::compute_corners() {
  const std::size_t T = mc_.triangle_count();
  corners_.resize(3 * T);
  orientation_.resize(T);
  for (std::uint32_t t = 0; t < T; ++t) {
    const FrameIv& f = frame_iv_[triangle_frame_[t]];
    std::array<Interval, 2> c[3];
    for (int i = 0; i < 3; ++i) {
      const auto d = sub3(vertex_iv_[mc_.triangle(t).v[i]], f.origin);
      c[i] = {dot3(d, f.a1), dot3(d, f.a2)};
      corners_[3 * t + i] = DiscPoint::from_intervals(c[i][0], c[i][1]);
    }
    const Interval cr = (c[1][0] - c[0][0]) * (c[2][1] - c[0][1]) - (c[1][1] - c[0][1]) * (c[2][0] - c[0][0]);
    const int s = certified_sign(cr);
    orientation_[t] = (s == 1 || s == -1) ? s : exact_orientation(t);
  }
}

int Unfolding::exact_orientation(std::uint32_t t) const {
  const std::uint32_t f = triangle_frame_[t];
  const auto& tv = mc_.triangle(t).v;
  const auto& a = vertex_uv(f, tv[0]);
  const auto& b = vertex_uv(f, tv[1]);
  const auto& c = vertex_uv(f, tv[2]);
  const mpq_class cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (sgn(cr) == 0) throw std::logic_error("Unfolding: degenerate triangle " + std::to_string(t));
  return sgn(cr);
}

DiscPoint Unfolding::vertex_image(std::uint32_t t, std::uint32_t v) const {
  const int i = corner_of(mc_.triangle(t), v);
  if (i < 0) throw std::logic_error("Unfolding::vertex_image: vertex not on the triangle");
  return corners_[3 * t + i];
}

DiscPoint Unfolding::point_image(std::uint32_t t, const ExactPoint3& p) const {
  const FrameIv& f = frame_iv_[triangle_frame_[t]];
  const auto d = sub3(enclose3(p), f.origin);
  return DiscPoint::from_intervals(dot3(d, f.a1), dot3(d, f.a2));
}

void Unfolding::compute_crossings() {
  const std::size_t T = mc_.triangle_count();
  crossing_.assign(3 * T, RigidMotion2{});
  has_crossing_.assign(3 * T, false);
  for (std::uint32_t t = 0; t < T; ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t e = mc_.triangle(t).e[i];
      if (mc_.edge(e).stratum != EdgeStratum::Manifold) continue;
      const auto& ts = mc_.edge_triangles(e);
      const std::uint32_t t2 = ts[0] == t ? ts[1] : ts[0];
      if (same_frame(t, t2)) continue;
      crossing_[3 * t + i] = compute_crossing(e, t, t2);
      has_crossing_[3 * t + i] = true;
    }
}

int Unfolding::edge_side(std::uint32_t e, std::uint32_t t) const {
  const ComplexTriangle& tr = mc_.triangle(t);
  const int i = corner_of(tr, third_vertex(tr, mc_.edge(e).v));
  return mc_.edge(e).v[0] == tr.v[(i + 1) % 3] ? orientation(t) : -orientation(t);
}

RigidMotion2 Unfolding::compute_crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const {
  const auto& ev = mc_.edge(e).v;
  const DiscPoint A = vertex_image(t, ev[0]), B = vertex_image(t, ev[1]);
  const DiscPoint A2 = vertex_image(t2, ev[0]), B2 = vertex_image(t2, ev[1]);
  const bool proper = edge_side(e, t) == -edge_side(e, t2);
  std::array<Interval, 6> m;
  const Interval l = sqrt(square(B.ix() - A.ix()) + square(B.iy() - A.iy()));
  const Interval l2 = sqrt(square(B2.ix() - A2.ix()) + square(B2.iy() - A2.iy()));
  if (tight(l) && tight(l2)) {
    m = motion_from_edges<Interval>(A.ix(), A.iy(), B.ix(), B.iy(), A2.ix(), A2.iy(), B2.ix(), B2.iy(), proper);
  } else {  // a short edge: the images' discs do not give its direction; Arb from the exact data
    BallPrecision guard(256);
    const BallMotion b = crossing_ball(e, t, t2);
    m = {b.r00.to_interval(), b.r01.to_interval(), b.r10.to_interval(),
         b.r11.to_interval(), b.t0.to_interval(),  b.t1.to_interval()};
  }
  RigidMotion2 r;
  r.reflect = !proper;
  r.r00 = m[0].mid(), r.r01 = m[1].mid(), r.r10 = m[2].mid(), r.r11 = m[3].mid();
  r.t0 = m[4].mid(), r.t1 = m[5].mid();
  r.rot_error = norm_of_radii({m[0].radius(), m[1].radius(), m[2].radius(), m[3].radius()});
  r.trans_error = norm_of_radii({m[4].radius(), m[5].radius()});
  return r;
}

const RigidMotion2& Unfolding::crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const {
  static const RigidMotion2 identity{};
  if (same_frame(t, t2)) return identity;
  const ComplexTriangle& tr = mc_.triangle(t);
  for (int i = 0; i < 3; ++i)
    if (tr.e[i] == e && has_crossing_[3 * t + i]) return crossing_[3 * t + i];
  const std::uint64_t key = (static_cast<std::uint64_t>(t) << 32) | t2;
  auto it = other_crossings_.find(key);
  if (it == other_crossings_.end()) it = other_crossings_.emplace(key, compute_crossing(e, t, t2)).first;
  return it->second;
}

std::array<Ball, 2> Unfolding::frame_scale_ball(std::uint32_t t) const {
  auto& cache = ball_scales_[BallPrecision::bits()];
  const std::uint32_t frame = triangle_frame_[t];
  if (auto it = cache.find(frame); it != cache.end()) return it->second;
  const PlanarFrame& f = planar_frame(frame);
  return cache.emplace(frame, std::array<Ball, 2>{sqrt(ball_of(f.e1_norm2)), sqrt(ball_of(f.e2_norm2))}).first->second;
}

BallVec2 Unfolding::point_ball(std::uint32_t t, const ExactPoint3& p) const {
  const PlanarFrame& f = planar_frame(triangle_frame_[t]);
  const ExactPoint3 d = p - f.origin;
  const auto s = frame_scale_ball(t);
  return {ball_of(dot(d, f.e1)) / s[0], ball_of(dot(d, f.e2)) / s[1]};
}

BallVec2 Unfolding::edge_param_ball(std::uint32_t t, std::uint32_t edge, const mpq_class& l) const {
  const std::uint32_t frame = triangle_frame_[t];
  const std::uint64_t key = (static_cast<std::uint64_t>(frame) << 32) | edge;
  auto it = edge_dots_.find(key);
  if (it == edge_dots_.end()) {
    const PlanarFrame& f = planar_frame(frame);
    const ExactPoint3& a = mc_.vertex(mc_.edge(edge).v[0]).exact;
    const ExactPoint3 d = a - f.origin, ab = mc_.vertex(mc_.edge(edge).v[1]).exact - a;
    it = edge_dots_.emplace(key, std::array<mpq_class, 4>{dot(d, f.e1), dot(ab, f.e1), dot(d, f.e2), dot(ab, f.e2)}).first;
  }
  const auto& c = it->second;
  const auto s = frame_scale_ball(t);
  // c0 + l c1 as one fraction, not reduced (no gcd: its value is all ball_of reads).
  auto affine = [&l](const mpq_class& c0, const mpq_class& c1) {
    mpq_class q;
    mpz_class num = c0.get_num() * c1.get_den() * l.get_den() + l.get_num() * c1.get_num() * c0.get_den();
    mpz_class den = c0.get_den() * c1.get_den() * l.get_den();
    mpz_swap(mpq_numref(q.get_mpq_t()), num.get_mpz_t());
    mpz_swap(mpq_denref(q.get_mpq_t()), den.get_mpz_t());
    return ball_of(q);
  };
  return {affine(c[0], c[1]) / s[0], affine(c[2], c[3]) / s[1]};
}

BallVec2 Unfolding::vertex_ball(std::uint32_t t, std::uint32_t v) const {
  const std::uint32_t f = triangle_frame_[t];
  auto& cache = ball_vertices_[BallPrecision::bits()];
  const std::uint64_t key = (static_cast<std::uint64_t>(f) << 32) | v;
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const auto& uv = vertex_uv(f, v);
  const auto s = frame_scale_ball(t);
  return cache.emplace(key, BallVec2{ball_of(uv[0]) * s[0], ball_of(uv[1]) * s[1]}).first->second;
}

BallMotion Unfolding::crossing_ball(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const {
  if (same_frame(t, t2)) return {Ball(1.0), Ball(0.0), Ball(0.0), Ball(1.0), Ball(0.0), Ball(0.0)};
  auto& cache = ball_crossings_[BallPrecision::bits()];
  const std::uint64_t key = (static_cast<std::uint64_t>(t) << 32) | t2;
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const auto& ev = mc_.edge(e).v;
  const BallVec2 A = vertex_ball(t, ev[0]), B = vertex_ball(t, ev[1]);
  const BallVec2 A2 = vertex_ball(t2, ev[0]), B2 = vertex_ball(t2, ev[1]);
  const bool proper = edge_side(e, t) == -edge_side(e, t2);
  const auto m = motion_from_edges<Ball>(A.x, A.y, B.x, B.y, A2.x, A2.y, B2.x, B2.y, proper);
  return cache.emplace(key, BallMotion{m[0], m[1], m[2], m[3], m[4], m[5]}).first->second;
}

const std::array<mpq_class, 2>& Unfolding::vertex_uv(std::uint32_t f, std::uint32_t v) const {
  const std::uint64_t key = (static_cast<std::uint64_t>(f) << 32) | v;
  auto it = uv_cache_.find(key);
  if (it == uv_cache_.end()) it = uv_cache_.emplace(key, planar_frame(f).local(mc_.vertex(v).exact)).first;
  return it->second;
}

std::array<mpq_class, 2> Unfolding::point_uv(std::uint32_t f, const ExactPoint3& p) const { return planar_frame(f).local(p); }

// X (in t's plane) = A + alpha E + beta N with N the part of C - A orthogonal to E; the
// unfolding sends it to A + alpha E + k beta N2, k = -|N| / |N2| (t onto the side opposite
// t2's third vertex D). alpha and beta are affine in X's local coordinates.
const Unfolding::ExactCrossing& Unfolding::exact_crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const {
  const std::uint64_t key = (static_cast<std::uint64_t>(t) << 32) | t2;
  auto it = exact_crossings_.find(key);
  if (it != exact_crossings_.end()) return *it->second;
  const auto& ev = mc_.edge(e).v;
  const ExactPoint3& A = mc_.vertex(ev[0]).exact;
  const ExactPoint3 E = mc_.vertex(ev[1]).exact - A;
  const mpq_class e2 = dot(E, E);
  auto perpendicular = [&](std::uint32_t tri) {
    const ExactPoint3 c = mc_.vertex(third_vertex(mc_.triangle(tri), ev)).exact - A;
    return c - mpq_class(dot(c, E) / e2) * E;
  };
  const ExactPoint3 N = perpendicular(t), N2 = perpendicular(t2);
  const mpq_class n2 = dot(N, N);
  const PlanarFrame &f = planar_frame(triangle_frame_[t]), &f2 = planar_frame(triangle_frame_[t2]);
  auto localvec = [&](const ExactPoint3& v) { return std::array<mpq_class, 2>{dot(v, f2.e1) / f2.e1_norm2, dot(v, f2.e2) / f2.e2_norm2}; };
  const ExactPoint3 oa = f.origin - A;
  auto r = std::make_unique<ExactCrossing>();
  // alpha(X) = a0 + ax x + ay y; P(X) = local(A) + alpha(X) localvec(E)
  const mpq_class a0 = dot(oa, E) / e2, ax = dot(f.e1, E) / e2, ay = dot(f.e2, E) / e2;
  const auto la = f2.local(A), le = localvec(E), w = localvec(N2);
  r->p00 = ax * le[0], r->p01 = ay * le[0], r->p0 = la[0] + a0 * le[0];
  r->p10 = ax * le[1], r->p11 = ay * le[1], r->p1 = la[1] + a0 * le[1];
  r->bc = dot(oa, N) / n2, r->b0 = dot(f.e1, N) / n2, r->b1 = dot(f.e2, N) / n2;
  r->w0 = w[0], r->w1 = w[1];
  r->kk = n2 / dot(N2, N2);
  return *exact_crossings_.emplace(key, std::move(r)).first->second;
}

}  // namespace grassfire
