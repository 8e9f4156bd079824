// window_exact.cpp -- stage 3 of the certified decisions (window_certify.h): a window's
// geometry and times in exact local coordinates of its frame (sums of square roots), where
// its pseudo-source is exact and its chain's unfoldings keep the coordinates small
// (docs/design.md 5a: rational inside one planar frame, one generator per irrational crossing).
#include <algorithm>

#include "burn3/exact/window_certify.h"
#include "burn3/exact/window_values.h"
#include "geometry3/exact_predicates3.h"
#include "number/sqrt_field.h"

namespace grassfire {
namespace {

using XV = Certifier::ExactVector;

// A coordinate that grows past this many terms is given up (then Arb decides).
constexpr std::size_t kMaxTerms = 32;
constexpr int kMaxIrrationalCrossings = 4;

ExactSum q(const mpq_class& x) { return ExactSum::rational(x); }
XV xv(const std::array<mpq_class, 2>& a) { return {q(a[0]), q(a[1])}; }
XV sub(const XV& a, const XV& b) { return {a[0] - b[0], a[1] - b[1]}; }
ExactSum mul(const ExactSum& a, const ExactSum& b) { return multiply_simplified(a, b); }
ExactSum cross_xv(const XV& a, const XV& b) { return mul(a[0], b[1]) - mul(a[1], b[0]); }
ExactSum metric_dot(const XV& a, const XV& b, const mpq_class& g1, const mpq_class& g2) {
  return scaled(mul(a[0], b[0]), g1) + scaled(mul(a[1], b[1]), g2);
}
bool small(const XV& a) { return a[0].term_count() <= kMaxTerms && a[1].term_count() <= kMaxTerms; }

// X' = P(X) + k beta(X) w (Unfolding::ExactCrossing); `affine` false for directions.
XV cross_over(const Unfolding::ExactCrossing& c, const ExactSum& k, const XV& x, bool affine) {
  ExactSum beta = scaled(x[0], c.b0) + scaled(x[1], c.b1);
  XV r{scaled(x[0], c.p00) + scaled(x[1], c.p01), scaled(x[0], c.p10) + scaled(x[1], c.p11)};
  if (affine) beta += q(c.bc), r[0] += q(c.p0), r[1] += q(c.p1);
  const ExactSum kb = mul(k, beta);
  r[0] += scaled(kb, c.w0), r[1] += scaled(kb, c.w1);
  r[0].simplify(), r[1].simplify();
  return r;
}

}  // namespace

std::optional<XV> Certifier::target_uv(std::uint32_t f, const Target& x) const {
  if (x.point) return xv(u_.point_uv(f, *x.point));
  if (!is_edge_point(x.vertex)) return xv(u_.vertex_uv(f, x.vertex));
  // (1 - lambda) a + lambda b with lambda exact.
  const EdgePoint& ep = s_.edge_points[x.vertex & ~kEdgePointBound];
  if (ep.exact < 0) return std::nullopt;
  const auto& ev = u_.complex().edge(ep.edge).v;
  const auto a = u_.vertex_uv(f, ev[0]), b = u_.vertex_uv(f, ev[1]);
  const ExactSum& l = s_.exact_times[ep.exact];
  XV r{q(a[0]) + scaled(l, mpq_class(b[0] - a[0])), q(a[1]) + scaled(l, mpq_class(b[1] - a[1]))};
  r[0].simplify(), r[1].simplify();
  return r;
}

// ---- stage 3: exact (rational frames and crossings) -------------------------------------

const ExactSum* Certifier::exact_sigma(std::uint32_t p) {
  const PseudoSource& ps = s_.pseudo[p];
  if (ps.time == kNoIndex) {
    static const ExactSum zero;
    return &zero;
  }
  return exact_expr(ps.time);
}

const ExactSum* Certifier::exact_expr(std::uint32_t i) {
  if (auto it = exact_time_memo_.find(i); it != exact_time_memo_.end()) return it->second.get();
  const TimeExpr& e = s_.times[i];
  std::optional<ExactSum> r;
  switch (e.kind) {
    case TimeExpr::Kind::Exact: r = s_.exact_times[e.a]; break;
    case TimeExpr::Kind::WindowAt: r = exact_time(e.a, Target{e.b, nullptr}); break;
    case TimeExpr::Kind::Plus:
      if (const ExactSum* x = exact_expr(e.a)) r = *x + ExactSum::sqrt_of(edge_length2(e.b));
      break;
    case TimeExpr::Kind::Enclosure: break;
    case TimeExpr::Kind::Min: {
      const ExactSum* x = exact_expr(e.a);
      const ExactSum* y = x ? exact_expr(e.b) : nullptr;
      if (x && y) r = exact_sign(*x - *y) <= 0 ? *x : *y;
      break;
    }
  }
  if (r) r->simplify();
  std::unique_ptr<ExactSum> owned = r ? std::make_unique<ExactSum>(std::move(*r)) : nullptr;
  return exact_time_memo_.emplace(i, std::move(owned)).first->second.get();
}

const Certifier::ExactWindow* Certifier::exact_window(std::uint32_t w) {
  if (auto it = exact_memo_.find(w); it != exact_memo_.end()) return it->second.get();
  auto r = build_exact_window(w);
  return exact_memo_.emplace(w, std::move(r)).first->second.get();
}

std::unique_ptr<Certifier::ExactWindow> Certifier::build_exact_window(std::uint32_t w, std::uint32_t source_vertex) {
  std::vector<std::uint32_t> chain;
  for (std::uint32_t x = w; x != kNoIndex; x = s_.windows[x].parent) chain.push_back(x);
  std::reverse(chain.begin(), chain.end());
  const Window& first = s_.windows[chain[0]];
  const Window& last = s_.windows[w];
  const PseudoSource& ps = s_.pseudo[first.pseudo];
  const MedialComplex& mc = u_.complex();
  auto e = std::make_unique<ExactWindow>();
  e->frame = u_.frame(first.triangle);
  if (source_vertex != kNoIndex) {
    e->s = xv(u_.vertex_uv(e->frame, source_vertex));
  } else if (ps.origin == SourceOrigin::BorderPoint) {
    // S = A + alpha E - sqrt(h^2 / |N|^2) N, N the part of C - A orthogonal to E (sources.h),
    // all rational in local coordinates but the one square root.
    const std::uint32_t edge = ps.data;
    const auto& ev = mc.edge(edge).v;
    const RotatedPoint rp = rotated_point(mc, edge);
    const auto a = u_.vertex_uv(e->frame, ev[0]), b = u_.vertex_uv(e->frame, ev[1]);
    const auto c = u_.vertex_uv(e->frame, third_vertex(mc.triangle(first.triangle), ev));
    const mpq_class g1 = u_.g1(e->frame), g2 = u_.g2(e->frame);
    const std::array<mpq_class, 2> E{b[0] - a[0], b[1] - a[1]}, AC{c[0] - a[0], c[1] - a[1]};
    const mpq_class e2 = g1 * E[0] * E[0] + g2 * E[1] * E[1];
    const mpq_class along = (g1 * AC[0] * E[0] + g2 * AC[1] * E[1]) / e2;
    const std::array<mpq_class, 2> N{AC[0] - along * E[0], AC[1] - along * E[1]};
    ExactSum k = ExactSum::sqrt_of(rp.h2 / (g1 * N[0] * N[0] + g2 * N[1] * N[1]));
    k.simplify();
    e->s = {q(a[0] + rp.alpha * E[0]) - scaled(k, N[0]), q(a[1] + rp.alpha * E[1]) - scaled(k, N[1])};
    e->s[0].simplify(), e->s[1].simplify();
  } else if (ps.origin == SourceOrigin::BorderPlane) {
    if (ps.exact < 0) return nullptr;
    const std::uint32_t edge = s_.exact[ps.exact].edge;
    const auto& ev = mc.edge(edge).v;
    e->line = true;
    e->p = xv(u_.vertex_uv(e->frame, ev[0]));
    e->d = sub(xv(u_.vertex_uv(e->frame, ev[1])), e->p);
    const XV c = xv(u_.vertex_uv(e->frame, third_vertex(mc.triangle(border_triangle(mc, edge)), ev)));
    e->inner = exact_sign(cross_xv(e->d, sub(c, e->p)));
  } else if (ps.origin == SourceOrigin::EdgePoint) {
    const std::optional<XV> p = target_uv(e->frame, Target{ps.data | kEdgePointBound, nullptr});
    if (!p) return nullptr;
    e->s = *p;
  } else {
    e->s = xv(ps.origin == SourceOrigin::Vertex ? u_.vertex_uv(e->frame, ps.vertex)
                                                 : u_.point_uv(e->frame, s_.given[ps.data].point));
  }
  std::array<bool, 2> taken{false, false};
  int generators = 0;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const Window& wi = s_.windows[chain[i]];
    const std::uint32_t prev = i > 0 ? s_.windows[chain[i - 1]].triangle : kNoIndex;
    if (i > 0 && !u_.same_frame(prev, wi.triangle)) {
      const Unfolding::ExactCrossing& c = u_.exact_crossing(wi.edge, prev, wi.triangle);
      ExactSum k = ExactSum::sqrt_of(c.kk);
      k.scale(-1);
      k.simplify();
      // Each irrational crossing may double the terms: past a few, give up (Arb decides).
      if (!k.sqrt_terms().empty() && ++generators > kMaxIrrationalCrossings) return nullptr;
      if (e->line) {
        e->p = cross_over(c, k, e->p, true), e->d = cross_over(c, k, e->d, false);
        if (u_.crossing(wi.edge, prev, wi.triangle).reflect) e->inner = -e->inner;
        if (!small(e->p) || !small(e->d)) return nullptr;
      } else {
        e->s = cross_over(c, k, e->s, true);
        if (!small(e->s)) return nullptr;
      }
      for (int j = 0; j < 2; ++j)
        if (taken[j]) e->image[j] = cross_over(c, k, e->image[j], true);
      e->frame = u_.frame(wi.triangle);
    }
    for (int j = 0; j < 2; ++j)
      if (!taken[j] && last.bound[j] != kNoIndex && last.bound_depth[j] == i) {
        const std::optional<XV> b = target_uv(e->frame, Target{last.bound[j], nullptr});
        if (!b) return nullptr;
        e->image[j] = *b;
        taken[j] = true;
      }
  }
  return e;
}

int Certifier::exact_side(const ExactWindow& e, int j, const Target& x) const {
  const std::optional<XV> px = target_uv(e.frame, x);
  if (!px) return kUndecided;
  const XV& p = *px;
  if (!e.line) return exact_sign(cross_xv(sub(e.image[j], e.s), sub(p, e.s)));
  // side = cross(u, X - B) with u the inner unit normal: sign = -inner * sign(E . (X - B)),
  // the dot product in the frame's metric.
  return -e.inner * exact_sign(metric_dot(e.d, sub(p, e.image[j]), u_.g1(e.frame), u_.g2(e.frame)));
}

std::optional<mpq_class> Certifier::line_length2(std::uint32_t w) {
  const ExactWindow* e = exact_window(w);
  if (!e || !e->line) return std::nullopt;
  ExactSum n2 = metric_dot(e->d, e->d, u_.g1(e->frame), u_.g2(e->frame));
  n2.simplify();
  if (n2.sqrt_terms().empty() && n2.constant_terms().empty()) return n2.rational_part();
  // Irrational crossings leave sums of square roots that the simplification does not fold:
  // d is the border edge's vector carried by isometries, so |d|^2 is its squared length,
  // proved here by exact comparison (not assumed).
  const PseudoSource& ps = s_.pseudo[s_.windows[w].pseudo];
  if (ps.origin != SourceOrigin::BorderPlane || ps.exact < 0 || !n2.constant_terms().empty()) return std::nullopt;
  const mpq_class len2 = edge_length2(s_.exact[ps.exact].edge);
  if (exact_sign(n2 - ExactSum::rational(len2)) != 0) return std::nullopt;
  return len2;
}

std::optional<ExactSum> Certifier::exact_time(std::uint32_t w, const Target& x) {
  const ExactWindow* e = exact_window(w);
  if (!e) return std::nullopt;
  const ExactSum* sigma = exact_sigma(s_.windows[w].pseudo);
  if (!sigma) return std::nullopt;
  const std::optional<XV> px = target_uv(e->frame, x);
  if (!px) return std::nullopt;
  const XV& p = *px;
  const mpq_class &g1 = u_.g1(e->frame), &g2 = u_.g2(e->frame);
  ExactSum r = *sigma;
  if (!e->line) {
    const XV d = sub(p, e->s);
    ExactSum d2 = metric_dot(d, d, g1, g2);
    d2.simplify();
    if (d2.sqrt_terms().empty()) {
      r += ExactSum::sqrt_of(d2.rational_part());
    } else if (auto root = sqrt_of_sum(d2)) {
      r += *root;
    } else {
      return std::nullopt;
    }
  } else {
    // distance to the line = inner * cross(d, X - p) * sqrt(g1 g2 / |d|^2)
    const std::optional<mpq_class> n2 = line_length2(w);
    if (!n2) return std::nullopt;
    const ExactSum dist = mul(ExactSum::sqrt_of(g1 * g2 / *n2), cross_xv(e->d, sub(p, e->p)));
    r += e->inner > 0 ? dist : q(0) - dist;
  }
  r.simplify();
  return r;
}

// Directions at v in local coordinates: a point source's v - S (cross products scale by
// sqrt(g1 g2) > 0), a line's inner normal u, for which cross(u, Y) = -inner (E . Y) / |E|.
int Certifier::exact_direction_cross(const ExactWindow& a, const ExactWindow& b, std::uint32_t v) const {
  const mpq_class &g1 = u_.g1(a.frame), &g2 = u_.g2(a.frame);
  const XV x = xv(u_.vertex_uv(a.frame, v));
  if (!a.line && !b.line) return exact_sign(cross_xv(sub(x, a.s), sub(x, b.s)));
  if (a.line && !b.line) return -a.inner * exact_sign(metric_dot(a.d, sub(x, b.s), g1, g2));
  if (!a.line && b.line) return b.inner * exact_sign(metric_dot(b.d, sub(x, a.s), g1, g2));
  return a.inner * b.inner * exact_sign(cross_xv(a.d, b.d));
}

}  // namespace grassfire
