// window_certify.cpp -- see window_certify.h.
#include "burn3/exact/window_certify.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "burn3/exact/window_values.h"
#include "geometry3/exact_predicates3.h"
#include "number/ball_exact_sum.h"
#include "number/sqrt_field.h"

namespace grassfire {

void CertificationCounts::merge(const CertificationCounts& o) {
  filter += o.filter, exact += o.exact, arb += o.arb, exact_equal += o.exact_equal;
  structural_equal += o.structural_equal, kept_undecided += o.kept_undecided, uncertified += o.uncertified;
  memo += o.memo, negligible_ties += o.negligible_ties;
  max_bits = std::max(max_bits, o.max_bits);
}

namespace {

Ball ball_cross(const BallVec2& a, const BallVec2& b) { return a.x * b.y - a.y * b.x; }
BallVec2 ball_sub(const BallVec2& a, const BallVec2& b) { return {a.x - b.x, a.y - b.y}; }

int ball_sign(const Ball& b) {
  const int s = b.sign();
  return s == kUndecided ? kUndecided : s;
}

}  // namespace

// A keyed point's images are cached per frame (and precision): the junction rule evaluates
// every record at one point (enclosing the rational point costs more than the comparison).
DiscPoint Certifier::target_disc(std::uint32_t t, const Target& x) const {
  if (x.point && x.key) {
    const MemoKey k{u_.frame(t), x.key, 0};
    if (const auto it = disc_cache_.find(k); it != disc_cache_.end()) return it->second;
    if (disc_cache_.size() > 1'000'000) disc_cache_.clear();
    return disc_cache_.emplace(k, u_.point_image(t, *x.point)).first->second;
  }
  if (x.point) return u_.point_image(t, *x.point);
  if (is_edge_point(x.vertex)) return edge_point_image(u_, s_, t, x.vertex & ~kEdgePointBound);
  return u_.vertex_image(t, x.vertex);
}

BallVec2 Certifier::target_ball(std::uint32_t t, const Target& x) const {
  if (x.point && x.key) {
    const MemoKey k{u_.frame(t), x.key, static_cast<std::uint64_t>(BallPrecision::bits())};
    if (const auto it = ball_cache_.find(k); it != ball_cache_.end()) return it->second;
    if (ball_cache_.size() > 1'000'000) ball_cache_.clear();
    return ball_cache_.emplace(k, x.lambda ? u_.edge_param_ball(t, x.edge, *x.lambda) : u_.point_ball(t, *x.point))
        .first->second;
  }
  if (x.lambda) return u_.edge_param_ball(t, x.edge, *x.lambda);
  if (x.point) return u_.point_ball(t, *x.point);
  if (is_edge_point(x.vertex)) return edge_point_ball(u_, s_, t, x.vertex & ~kEdgePointBound);
  return u_.vertex_ball(t, x.vertex);
}

Interval Certifier::time_interval(std::uint32_t w, const Target& x) const {
  const Window& win = s_.windows[w];
  const Approx a = approx_time(win, target_disc(win.triangle, x));
  return {round_down(a.v - a.e), round_up(a.v + a.e)};
}

// ---- stage 4: Arb re-evaluation of the chain -------------------------------------------

Ball Certifier::sigma_ball(std::uint32_t p) {
  const std::uint32_t t = s_.pseudo[p].time;
  return t == kNoIndex ? Ball(0.0) : expr_ball(t);
}

Ball Certifier::expr_ball(std::uint32_t i) {
  auto& memo = time_memo_[BallPrecision::bits()];
  if (auto it = memo.find(i); it != memo.end()) return it->second;
  const TimeExpr& e = s_.times[i];
  Ball r;
  switch (e.kind) {
    case TimeExpr::Kind::Exact: r = ball_of(s_.exact_times[e.a]); break;
    case TimeExpr::Kind::WindowAt: r = time_ball(e.a, Target{e.b, nullptr}); break;
    case TimeExpr::Kind::Plus: r = expr_ball(e.a) + sqrt(ball_of(edge_length2(e.b))); break;
    case TimeExpr::Kind::Enclosure: r = Ball::from_interval(e.value); break;
    case TimeExpr::Kind::Min: {
      const Ball x = expr_ball(e.a), y = expr_ball(e.b);
      arb_min(r.get(), x.get(), y.get(), BallPrecision::bits());
      break;
    }
  }
  time_memo_[BallPrecision::bits()].emplace(i, r);
  return r;
}

mpq_class Certifier::edge_length2(std::uint32_t e) const {
  const auto& ev = u_.complex().edge(e).v;
  return squared_distance(u_.complex().vertex(ev[0]).exact, u_.complex().vertex(ev[1]).exact);
}

// Memoised per (window, offset wanted, source vertex, precision): a window's chain never
// changes once made, and the bisections (junction_kinks.cpp) evaluate the same two chains
// at a hundred points.
WindowBall Certifier::evaluate(std::uint32_t w, bool with_offset, std::uint32_t source_vertex) {
  const MemoKey key{w, source_vertex, static_cast<std::uint64_t>(BallPrecision::bits()) * 2 + with_offset};
  if (const auto it = chain_memo_.find(key); it != chain_memo_.end()) return it->second;
  if (chain_memo_.size() > 200000) chain_memo_.clear();
  WindowBall b = evaluate_chain(w, with_offset, source_vertex);
  return chain_memo_.emplace(key, std::move(b)).first->second;
}

WindowBall Certifier::evaluate_chain(std::uint32_t w, bool with_offset, std::uint32_t source_vertex) {
  std::vector<std::uint32_t> chain;
  for (std::uint32_t x = w; x != kNoIndex; x = s_.windows[x].parent) chain.push_back(x);
  std::reverse(chain.begin(), chain.end());
  const Window& first = s_.windows[chain[0]];
  const Window& last = s_.windows[w];
  const SourceOrigin origin = s_.pseudo[first.pseudo].origin;
  const bool point_kind = origin != SourceOrigin::BorderPlane;
  const RootBall r =
      root_ball(u_, s_, first.pseudo, first.triangle, point_kind && with_offset ? sigma_ball(first.pseudo) : Ball(0.0));
  WindowBall b{r.source, r.offset, {}, r.plane};
  if (source_vertex != kNoIndex) b.source = u_.vertex_ball(first.triangle, source_vertex);
  std::array<bool, 2> taken{false, false};
  for (std::size_t i = 0; i < chain.size(); ++i) {
    const Window& wi = s_.windows[chain[i]];
    if (i > 0) {
      const Window& prev = s_.windows[chain[i - 1]];
      if (!u_.same_frame(prev.triangle, wi.triangle)) {
        const BallMotion m = u_.crossing_ball(wi.edge, prev.triangle, wi.triangle);
        if (b.plane) {
          b.source = m.apply_vector(b.source);
          b.offset = b.offset - (b.source.x * m.t0 + b.source.y * m.t1);
        } else {
          b.source = m.apply(b.source);
        }
        for (int j = 0; j < 2; ++j)
          if (taken[j]) b.image[j] = m.apply(b.image[j]);
      }
    }
    for (int j = 0; j < 2; ++j)
      if (!taken[j] && last.bound[j] != kNoIndex && last.bound_depth[j] == i) {
        b.image[j] = target_ball(wi.triangle, Target{last.bound[j], nullptr});
        taken[j] = true;
      }
  }
  return b;
}

namespace {
// The time of an evaluated window (with its offset) at the point p of its frame.
Ball time_at(const WindowBall& b, const BallVec2& p) {
  if (b.plane) return b.offset + b.source.x * p.x + b.source.y * p.y;
  const BallVec2 d = ball_sub(p, b.source);
  return b.offset + sqrt(d.x * d.x + d.y * d.y);
}
}  // namespace

Ball Certifier::time_ball(std::uint32_t w, const Target& x) {
  return time_at(evaluate(w, true), target_ball(s_.windows[w].triangle, x));
}

template <class F>
int Certifier::escalate(long cap, F&& sign_at_precision) {
  for (long bits = 128; bits <= cap; bits *= 2) {
    BallPrecision guard(bits);
    const int s = sign_at_precision();
    if (s != kUndecided) {
      ++counts.arb;
      counts.max_bits = std::max(counts.max_bits, bits);
      return s;
    }
  }
  return kUndecided;
}

// ---- stage 2: structural equality ------------------------------------------------------

// One point source, or the sources a vertex emits into its sectors at one time expression
// (the link rule and vertex burns give every sector the same expression).
bool Certifier::same_point_source(std::uint32_t pa, std::uint32_t pb) const {
  const PseudoSource &a = s_.pseudo[pa], &b = s_.pseudo[pb];
  if (pa == pb)
    return a.origin == SourceOrigin::Vertex || a.origin == SourceOrigin::GivenPoint || a.origin == SourceOrigin::EdgePoint;
  return a.origin == SourceOrigin::Vertex && b.origin == SourceOrigin::Vertex && a.vertex == b.vertex &&
         a.time == b.time && a.time != kNoIndex;
}

// `relay` a first window of an edge point p of x's edge E whose offset is the time at p of
// `src` (or of a window equal to it at p by p's defining equation), a first window of a point
// source S on E (a vertex of E, a caller's point on it, or another edge point of E),
// and `w` a first window of S too, all in triangles containing E: at x on E with p between S
// and x (decided on p's certified enclosure), time(w, x) = sigma + |x - S| = sigma + |p - S|
// + |x - p| = time(relay, x), each distance a straight segment of E (the relayed source of a
// kink or a stretch end, 4.2.1, beyond it along the edge).
bool Certifier::relayed_along_edge(std::uint32_t relay, std::uint32_t w, const Target& x) const {
  if (!x.point || x.edge == kNoIndex || !x.lambda) return false;
  const Window &b = s_.windows[relay], &a = s_.windows[w];
  if (!b.root() || !a.root()) return false;
  const PseudoSource& pb = s_.pseudo[b.pseudo];
  if (pb.origin != SourceOrigin::EdgePoint || pb.time == kNoIndex) return false;
  const EdgePoint& ep = s_.edge_points[pb.data];
  if (ep.edge != x.edge) return false;
  const TimeExpr& te = s_.times[pb.time];
  if (te.kind != TimeExpr::Kind::WindowAt || te.b != (pb.data | kEdgePointBound)) return false;
  // The window whose time at p is the offset, or the other window of p's defining equation
  // (a certified crossing: the two times are equal at p).
  auto of_s = [&](std::uint32_t v) {
    return v != kNoIndex && s_.windows[v].root() && same_point_source(s_.windows[v].pseudo, a.pseudo);
  };
  std::uint32_t from = kNoIndex;
  if (of_s(te.a)) from = te.a;
  for (int k = 0; k < 2 && from == kNoIndex; ++k)
    if (ep.equal_windows[k] == te.a && of_s(ep.equal_windows[1 - k])) from = ep.equal_windows[1 - k];
  if (from == kNoIndex) return false;
  const Window& src = s_.windows[from];
  const MedialComplex& mc = u_.complex();
  for (const Window* t : {&a, &b, &src}) {
    const auto& te3 = mc.triangle(t->triangle).e;
    if (std::find(te3.begin(), te3.end(), x.edge) == te3.end()) return false;
  }
  // S's parameter on E: a rational, or the certified enclosure of an edge point of E (a
  // kink or a stretch end relayed in turn).
  const PseudoSource& ps = s_.pseudo[a.pseudo];
  const auto& ev = mc.edge(x.edge).v;
  mpq_class sl, sh;
  if (ps.origin == SourceOrigin::Vertex && (ps.vertex == ev[0] || ps.vertex == ev[1])) {
    sl = sh = ps.vertex == ev[0] ? 0 : 1;
  } else if (ps.origin == SourceOrigin::GivenPoint) {
    const ExactPoint3 &va = mc.vertex(ev[0]).exact, &vb = mc.vertex(ev[1]).exact, &q = s_.given[ps.data].point;
    if (!(cross(vb - va, q - va) == ExactPoint3{})) return false;
    sl = sh = dot(q - va, vb - va) / dot(vb - va, vb - va);
    if (sl < 0 || sl > 1) return false;
  } else if (ps.origin == SourceOrigin::EdgePoint && s_.edge_points[ps.data].edge == x.edge) {
    if (!edge_point_bounds(s_.edge_points[ps.data], &sl, &sh)) return false;
  } else {
    return false;
  }
  // p's certified enclosure [pl, ph].
  mpq_class pl, ph;
  if (!edge_point_bounds(ep, &pl, &ph)) return false;
  const mpq_class& lx = *x.lambda;
  return (sl >= ph && lx <= pl) || (sh <= pl && lx >= ph);
}

bool Certifier::edge_point_bounds(const EdgePoint& ep, mpq_class* lo, mpq_class* hi) const {
  if (ep.exact >= 0 && s_.exact_times[ep.exact].sqrt_terms().empty() && s_.exact_times[ep.exact].constant_terms().empty()) {
    *lo = *hi = s_.exact_times[ep.exact].rational_part();
  } else if (ep.bracketed) {
    *lo = ep.lo, *hi = ep.hi;
  } else if (std::isfinite(ep.lambda.lo) && std::isfinite(ep.lambda.hi)) {
    *lo = ep.lambda.lo, *hi = ep.lambda.hi;
  } else {
    return false;
  }
  return true;
}

bool Certifier::same_expression(std::uint32_t w1, std::uint32_t w2, const Target& x) {
  const Window &a0 = s_.windows[w1], &b0 = s_.windows[w2];
  const auto pa = point_fronts_.find(front_id(w1)), pb = point_fronts_.find(front_id(w2));
  if (pa != point_fronts_.end() && pb != point_fronts_.end() && pa->second == pb->second) {
    // Two windows whose fronts are one point S at its own place in their frames, with offsets
    // proved equal (front_id; e.g. first windows of S, closed in both triangles): at a point x
    // of both closed triangles the time is sigma + |x - S| measured in 3D (a straight segment
    // inside each triangle): a vertex of both, or a point of an edge of both.
    const MedialComplex& mc = u_.complex();
    const ComplexTriangle &ta = mc.triangle(a0.triangle), &tb = mc.triangle(b0.triangle);
    if (!x.point) {
      if (corner_of(ta, x.vertex) >= 0 && corner_of(tb, x.vertex) >= 0) return true;
    } else {
      for (std::uint32_t e : ta.e) {
        if (std::find(tb.e.begin(), tb.e.end(), e) == tb.e.end()) continue;
        const ExactPoint3 &p = mc.vertex(mc.edge(e).v[0]).exact, &q = mc.vertex(mc.edge(e).v[1]).exact;
        if (cross(q - p, *x.point - p) == ExactPoint3{} && sgn(dot(*x.point - p, *x.point - q)) <= 0) return true;
      }
    }
  }
  if (a0.pseudo != b0.pseudo) return false;
  const SourceOrigin origin = s_.pseudo[a0.pseudo].origin;
  const bool point_kind =
      origin == SourceOrigin::Vertex || origin == SourceOrigin::GivenPoint || origin == SourceOrigin::EdgePoint;
  // Equal sequences of frame changes give the same source image.
  std::uint32_t p = a0.anchor, q = b0.anchor;
  for (;;) {
    if (p == q) return true;
    const Window &a = s_.windows[p], &b = s_.windows[q];
    if (u_.frame(a.triangle) != u_.frame(b.triangle)) return false;
    if (a.parent == kNoIndex || b.parent == kNoIndex) return a.parent == b.parent && point_kind;
    if (a.edge != b.edge || a.triangle != b.triangle || s_.windows[a.parent].triangle != s_.windows[b.parent].triangle)
      return false;
    p = s_.windows[a.parent].anchor, q = s_.windows[b.parent].anchor;
  }
}

bool Certifier::bound_fixed(std::uint32_t w, int j, std::uint32_t v) const {
  const Window& last = s_.windows[w];
  if (last.bound[j] != v) return false;
  const MedialComplex& mc = u_.complex();
  for (std::uint32_t x = w; x != kNoIndex; x = s_.windows[x].parent) {
    if (corner_of(mc.triangle(s_.windows[x].triangle), v) < 0) return false;
    if (s_.windows[x].depth == last.bound_depth[j]) return true;
  }
  return false;
}

// ---- identities and the memo of decisions -----------------------------------------------

namespace {
// Tags of the interned keys (top byte of MemoKey::a).
enum : std::uint64_t { kRootFront = 1, kPlaneRoot, kCrossed, kWindowAt, kPlus, kMin, kLeaf, kPoint, kExprs, kTimes };
constexpr std::uint64_t tag(std::uint64_t t, std::uint64_t payload) { return t << 56 | payload; }
// The precision cap as a small code (128 .. 2^k bits), kept under the tag.
std::uint64_t cap_code(long bits) { return static_cast<std::uint64_t>(bits / 128) << 40; }
}  // namespace

std::uint32_t Certifier::intern(const MemoKey& k) {
  return ids_.emplace(k, static_cast<std::uint32_t>(ids_.size())).first->second;
}

std::optional<int> Certifier::recall(const MemoKey& k) {
  const auto it = decided_.find(k);
  if (it == decided_.end()) return std::nullopt;
  ++counts.memo;
  return it->second;
}

int Certifier::remember(const MemoKey& k, int outcome) {
  if (decided_.size() > 4'000'000) decided_.clear();
  decided_.emplace(k, outcome);
  return outcome;
}

// Mirrors same_expression: a window has its anchor's front; an anchor without a parent is
// its pseudo-source (point kinds: one image per frame, named by the point and the offset's
// expression id, so that two sources at one point with offsets proved equal are one front;
// plane waves: itself); an anchor with one is the crossing (edge, triangle, parent's
// triangle) applied to its parent's front.
std::uint32_t Certifier::front_id(std::uint32_t w) {
  if (front_ids_.size() < s_.windows.size()) front_ids_.resize(s_.windows.size(), 0);
  std::vector<std::uint32_t> todo;  // anchors without an id, nearest first (iterative: long chains)
  for (std::uint32_t x = w; front_ids_[x] == 0;) {
    todo.push_back(x);
    const Window& W = s_.windows[x];
    if (W.anchor != x) x = W.anchor;
    else if (W.parent != kNoIndex) x = s_.windows[W.parent].anchor;
    else break;
  }
  for (auto it = todo.rbegin(); it != todo.rend(); ++it) {
    const std::uint32_t x = *it;
    const Window& W = s_.windows[x];
    std::uint32_t id;
    if (W.anchor != x) {
      id = front_ids_[W.anchor] - 1;
    } else if (W.parent == kNoIndex) {
      id = root_front(x);
    } else {
      const std::uint32_t parent = front_ids_[s_.windows[W.parent].anchor] - 1;
      const auto pf = point_fronts_.find(parent);
      if (pf != point_fronts_.end() && point_on_edge(pf->second[0], W.edge)) {
        // The crossing fixes its edge pointwise, so a point source on it keeps its place.
        id = point_front(pf->second[0], u_.frame(W.triangle), pf->second[1]);
      } else {
        id = intern({tag(kCrossed, W.edge), std::uint64_t(W.triangle) << 32 | s_.windows[W.parent].triangle, parent});
      }
    }
    front_ids_[x] = id + 1;
  }
  return front_ids_[w] - 1;
}

// A first window's front: sigma + |X - S| in its frame for a point S (a vertex, an edge
// point, a caller's point; S lies in the frame's plane, so its image is S's coordinates
// there), named by S (an edge point at an end of its edge is that vertex), the frame and
// the offset's expression id; a plane wave by its window.
std::uint32_t Certifier::root_front(std::uint32_t x) {
  const Window& W = s_.windows[x];
  const PseudoSource& ps = s_.pseudo[W.pseudo];
  std::uint64_t where;
  switch (ps.origin) {
    case SourceOrigin::Vertex: where = ps.vertex; break;
    case SourceOrigin::EdgePoint: where = canonical_point(ps.data | kEdgePointBound); break;
    case SourceOrigin::GivenPoint: where = std::uint64_t(1) << 40 | ps.data; break;
    default: return intern({tag(kPlaneRoot, x), 0, 0});
  }
  const std::uint64_t sigma = ps.time == kNoIndex ? 0 : std::uint64_t(expr_id(ps.time)) + 1;
  return point_front(where, u_.frame(W.triangle), sigma);
}

std::uint32_t Certifier::point_front(std::uint64_t where, std::uint32_t frame, std::uint64_t sigma) {
  const std::uint32_t id = intern({tag(kRootFront, where), frame, sigma});
  point_fronts_.emplace(id, std::array<std::uint64_t, 2>{where, sigma});
  return id;
}

// Whether the point p (a vertex, or an edge point with kEdgePointBound) lies on `edge`.
bool Certifier::point_on_edge(std::uint64_t p, std::uint32_t edge) const {
  if (p > 0xffffffffull) return false;  // a caller's point: not examined
  const auto q = static_cast<std::uint32_t>(p);
  if (is_edge_point(q)) return s_.edge_points[q & ~kEdgePointBound].edge == edge;
  const auto& ev = u_.complex().edge(edge).v;
  return ev[0] == q || ev[1] == q;
}

// An edge point whose parameter is exactly 0 or 1 is the edge's end vertex; any other
// target names itself.
std::uint32_t Certifier::canonical_point(std::uint32_t target) const {
  if (!is_edge_point(target)) return target;
  const EdgePoint& ep = s_.edge_points[target & ~kEdgePointBound];
  if (ep.exact < 0) return target;
  const ExactSum& l = s_.exact_times[ep.exact];
  if (!l.sqrt_terms().empty() || !l.constant_terms().empty()) return target;
  const auto& ev = u_.complex().edge(ep.edge).v;
  if (l.rational_part() == 0) return ev[0];
  if (l.rational_part() == 1) return ev[1];
  return target;
}

std::uint32_t Certifier::expr_id(std::uint32_t i) {
  if (expr_ids_.size() < s_.times.size()) expr_ids_.resize(s_.times.size(), 0);
  if (expr_ids_[i] != 0) return expr_ids_[i] - 1;
  const TimeExpr& e = s_.times[i];
  std::uint32_t id;
  switch (e.kind) {
    case TimeExpr::Kind::WindowAt: {
      const std::uint32_t p = canonical_point(e.b);
      id = intern({tag(kWindowAt, front_id(e.a)), p, 0});
      break;
    }
    case TimeExpr::Kind::Plus: id = intern({tag(kPlus, expr_id(e.a)), e.b, 0}); break;
    case TimeExpr::Kind::Min: {
      const std::uint32_t a = expr_id(e.a), b = expr_id(e.b);
      id = a == b ? a : intern({tag(kMin, std::min(a, b)), std::max(a, b), 0});  // min(x, x) = x
      break;
    }
    default: id = intern({tag(kLeaf, i), 0, 0}); break;
  }
  expr_ids_[i] = id + 1;
  return id;
}

std::uint64_t Certifier::point_key(std::uint32_t edge, double at) {
  std::uint64_t bits;
  std::memcpy(&bits, &at, sizeof bits);
  return (1ull << 63) | intern({tag(kPoint, edge), bits, 0});
}

int Certifier::compare_time_exprs(std::uint32_t a, std::uint32_t b, bool prune_only) {
  trim_memos();
  const int s = certified_sign(s_.times[a].value - s_.times[b].value);
  if (s != kUndecided) {
    ++counts.filter;
    return s;
  }
  const TimeExpr &ea = s_.times[a], &eb = s_.times[b];
  const std::uint32_t ia = expr_id(a), ib = expr_id(b);
  if (ia == ib || (ea.kind == TimeExpr::Kind::WindowAt && eb.kind == TimeExpr::Kind::WindowAt && ea.b == eb.b &&
                   same_expression(ea.a, eb.a, Target{ea.b, nullptr}))) {
    ++counts.structural_equal;
    return 0;
  }
  const long cap = prune_only ? prune_bits_ : max_bits_;
  const int flip = ia < ib ? 1 : -1;  // the key names the pair in one order
  const MemoKey key{tag(kExprs, std::min(ia, ib)) | cap_code(cap), std::max(ia, ib), 0};
  if (const std::optional<int> m = recall(key)) return *m == kUndecided ? *m : flip * *m;
  auto arb_level = [&] { return ball_sign(expr_ball(a) - expr_ball(b)); };
  // Arb's first level before the exact stage (as in side_if_certified).
  if (const int r = escalate(128, arb_level); r != kUndecided) return remember(key, flip * r) * flip;
  const ExactSum* x = exact_expr(a);
  const ExactSum* y = x ? exact_expr(b) : nullptr;
  if (x && y) {
    const int e = exact_sign(*x - *y);
    ++(e == 0 ? counts.exact_equal : counts.exact);
    return remember(key, flip * e) * flip;
  }
  const int r = escalate(cap, arb_level);
  if (r == kUndecided) ++counts.kept_undecided;
  return r == kUndecided ? remember(key, r) : remember(key, flip * r) * flip;
}

// ---- the staged decisions ---------------------------------------------------------------

void Certifier::trim_memos() {
  if (exact_memo_.size() > 200000) exact_memo_.clear();
}

int Certifier::side(std::uint32_t w, int j, const Target& x) {
  const int s = side_if_certified(w, j, x);
  if (s != kUndecided) return s;
  ++counts.uncertified;
  return 0;
}

// A window whose source S is a point inside edge E = (a, b) (a kink or stretch end located
// by an enclosure only) and whose bound j is b taken at depth 0: S, a and b are collinear
// in the first triangle's frame and stay so through the chain, S before b seen from a, so
// the ray from S through b and the ray from a through b have the same sides (cross(b - S,
// x - S) = cross(b - S, x - b) = |b - S| / |b - a| cross(b - a, x - b)), whatever S's place
// on E. Returns a (kNoIndex when w is not such a window); a is exact where S is not.
std::uint32_t Certifier::edge_ray_origin(std::uint32_t w, int j) const {
  const Window& win = s_.windows[w];
  const PseudoSource& ps = s_.pseudo[win.pseudo];
  if (ps.origin != SourceOrigin::EdgePoint || win.bound_depth[j] != 0) return kNoIndex;
  const EdgePoint& ep = s_.edge_points[ps.data];
  if (!(ep.lambda.lo > 0.0 && ep.lambda.hi < 1.0)) return kNoIndex;
  const auto& ev = u_.complex().edge(ep.edge).v;
  if (win.bound[j] == ev[0]) return ev[1];
  if (win.bound[j] == ev[1]) return ev[0];
  return kNoIndex;
}

namespace {
std::optional<Certifier::EdgeRoot> rational_root(const Ball& root, int slope, long bits) {
  mpfr_t lo, hi;
  mpfr_init2(lo, bits);
  mpfr_init2(hi, bits);
  root.to_mpfr(lo, hi);
  Certifier::EdgeRoot e;
  const bool finite = mpfr_number_p(lo) && mpfr_number_p(hi);
  if (finite) mpfr_get_q(e.lo.get_mpq_t(), lo), mpfr_get_q(e.hi.get_mpq_t(), hi);
  mpfr_clear(lo);
  mpfr_clear(hi);
  if (!finite) return std::nullopt;
  e.slope = slope;
  return e;
}
}  // namespace

std::optional<Certifier::EdgeRoot> Certifier::ray_root_on_edge(std::uint32_t w, int j, std::uint32_t edge, long bits) {
  BallPrecision guard(bits);
  const Window& win = s_.windows[w];
  const WindowBall b = evaluate(w, false, edge_ray_origin(w, j));
  const BallVec2 A = u_.edge_param_ball(win.triangle, edge, mpq_class(0));
  const BallVec2 D = ball_sub(u_.edge_param_ball(win.triangle, edge, mpq_class(1)), A);
  // The same cross products as side_if_certified's Arb stage, at A + l D.
  Ball g0, g1;
  if (b.plane) {
    g0 = ball_cross(b.source, ball_sub(A, b.image[j]));
    g1 = ball_cross(b.source, D);
  } else {
    const BallVec2 r = ball_sub(b.image[j], b.source);
    g0 = ball_cross(r, ball_sub(A, b.source));
    g1 = ball_cross(r, D);
  }
  const int slope = g1.sign();
  if (slope != 1 && slope != -1) return std::nullopt;
  return rational_root(-g0 / g1, slope, bits);
}


// Memoised per (frame, edge, precision): the edge's ends in a frame never change.
Certifier::Along Certifier::along_edge(std::uint32_t w, std::uint32_t edge) {
  const std::uint32_t t = s_.windows[w].triangle;
  const MemoKey key{u_.frame(t), edge, static_cast<std::uint64_t>(BallPrecision::bits())};
  auto it = edge_memo_.find(key);
  if (it == edge_memo_.end()) {
    if (edge_memo_.size() > 200000) edge_memo_.clear();
    const BallVec2 A = u_.edge_param_ball(t, edge, mpq_class(0));
    it = edge_memo_.emplace(key, std::array<BallVec2, 2>{A, ball_sub(u_.edge_param_ball(t, edge, mpq_class(1)), A)}).first;
  }
  return Along{evaluate(w, true), it->second[0], it->second[1]};
}

namespace {
using Along = Certifier::Along;
Ball time_along(const Along& a, const Ball& l) {  // time_ball at the edge point l
  return time_at(a.b, BallVec2{a.A.x + l * a.D.x, a.A.y + l * a.D.y});
}
Ball rate_along(const Along& a, const Ball& l) {  // its derivative in l
  if (a.b.plane) return a.b.source.x * a.D.x + a.b.source.y * a.D.y;
  const BallVec2 d{a.A.x + l * a.D.x - a.b.source.x, a.A.y + l * a.D.y - a.b.source.y};
  return (d.x * a.D.x + d.y * a.D.y) / sqrt(d.x * d.x + d.y * d.y);
}
}  // namespace

std::optional<Certifier::EdgeRoot> Certifier::crossing_root_on_edge(std::uint32_t w1, std::uint32_t w2,
                                                                    std::uint32_t edge, double lo, double hi,
                                                                    long bits) {
  BallPrecision guard(bits);
  const Along a = along_edge(w1, edge), b = along_edge(w2, edge);
  Ball X = Ball::from_interval(Interval{lo, hi});
  const Ball dX = rate_along(a, X) - rate_along(b, X);
  const int slope = dX.sign();
  if (slope != 1 && slope != -1) return std::nullopt;
  if ((time_along(a, Ball(lo)) - time_along(b, Ball(lo))).sign() != -slope ||
      (time_along(a, Ball(hi)) - time_along(b, Ball(hi))).sign() != slope)
    return std::nullopt;
  // f is monotone on X with a sign change: one root, which every Newton image contains.
  for (int i = 0; i < 8; ++i) {
    Ball m;
    arb_get_mid_arb(m.get(), X.get());
    const Ball n = m - (time_along(a, m) - time_along(b, m)) / (rate_along(a, X) - rate_along(b, X));
    Ball y;
    if (!arb_intersection(y.get(), X.get(), n.get(), bits)) return std::nullopt;
    X = y;
  }
  return rational_root(X, slope, bits);
}

std::array<int, 2> Certifier::edge_difference_signs(std::uint32_t w1, std::uint32_t w2, std::uint32_t edge,
                                                    const mpq_class& lo, const mpq_class& hi, long bits, double* bound) {
  BallPrecision guard(bits);
  const Along a = along_edge(w1, edge), b = along_edge(w2, edge);
  const Ball X = hull(ball_of(lo), ball_of(hi)), m = ball_of((lo + hi) / 2);
  const Ball slope = rate_along(a, X) - rate_along(b, X);
  const Ball naive = time_along(a, X) - time_along(b, X);
  int value = ball_sign(naive);
  const bool centred = value != 1 && value != -1;
  const Ball c = centred || bound ? time_along(a, m) - time_along(b, m) + slope * (X - m) : Ball(0.0);
  if (centred) value = ball_sign(c);
  if (bound) {
    auto mag = [](const Interval& d) { return std::max(-d.lo, d.hi); };
    const double r = std::min(mag(naive.to_interval()), mag(c.to_interval()));
    *bound = std::isnan(r) ? std::numeric_limits<double>::infinity() : r;
  }
  return {value, ball_sign(slope)};
}

double Certifier::edge_difference_bound(std::uint32_t w1, std::uint32_t w2, std::uint32_t edge, const mpq_class& lo,
                                        const mpq_class& hi, long bits) {
  double r = 0.0;
  edge_difference_signs(w1, w2, edge, lo, hi, bits, &r);
  return r;
}

int Certifier::side_if_certified(std::uint32_t w, int j, const Target& x, bool arb_first) {
  trim_memos();
  const Window& win = s_.windows[w];
  const int s = approx_side(win, win.image[j], target_disc(win.triangle, x)).sign();
  if (s != kUndecided) {
    ++counts.filter;
    return s;
  }
  if (!x.point && bound_fixed(w, j, x.vertex)) {
    ++counts.structural_equal;
    return 0;
  }
  const std::uint32_t along = edge_ray_origin(w, j);
  auto arb_level = [&] {
    const WindowBall b = evaluate(w, false, along);
    const std::uint32_t t = win.triangle;
    const BallVec2 p = target_ball(t, x);
    if (b.plane) return ball_sign(ball_cross(b.source, ball_sub(p, b.image[j])));
    return ball_sign(ball_cross(ball_sub(b.image[j], b.source), ball_sub(p, b.source)));
  };
  auto arb = [&] { return escalate(max_bits_, arb_level); };
  // Arb at its first level before the exact stage (thousands of rays against long rationals
  // that 128 bits separate at once); the exact stage then settles the ties Arb cannot.
  if (const int a = arb_first ? arb() : escalate(128, arb_level); a != kUndecided) return a;
  std::unique_ptr<ExactWindow> substitute = along == kNoIndex ? nullptr : build_exact_window(w, along);
  if (const ExactWindow* ew = substitute ? substitute.get() : exact_window(w)) {
    const int e = exact_side(*ew, j, x);
    if (e != kUndecided) {
      ++(e == 0 ? counts.exact_equal : counts.exact);
      return e;
    }
  }
  return arb_first ? kUndecided : arb();
}

int Certifier::compare_times(std::uint32_t w1, const Target& x1, std::uint32_t w2, const Target& x2, bool arb_first,
                             bool deciding) {
  trim_memos();
  const long cap = deciding ? max_bits_ : prune_bits_;
  const int s = certified_sign(time_interval(w1, x1) - time_interval(w2, x2));
  if (s != kUndecided) {
    ++counts.filter;
    return s;
  }
  const bool same_target = x1.point == x2.point && x1.vertex == x2.vertex;
  if (same_target && (same_expression(w1, w2, x1) || relayed_along_edge(w1, w2, x1) || relayed_along_edge(w2, w1, x1))) {
    ++counts.structural_equal;
    return 0;
  }
  // The memo, where both targets are one named point (a vertex, an edge point, a keyed point).
  const std::uint64_t where = x1.point ? x1.key : x1.vertex;
  const bool keyed = same_target && (x1.point ? x1.key != 0 : x1.vertex != kNoIndex);
  std::uint32_t fa = 0, fb = 0;
  if (same_target) {  // one front (front_id): one function of the frame's points, one value
    fa = front_id(w1), fb = front_id(w2);
    if (fa == fb) {
      ++counts.structural_equal;
      return 0;
    }
  }
  const int flip = fa < fb ? 1 : -1;
  const MemoKey key{tag(kTimes, std::min(fa, fb)) | cap_code(cap), std::max(fa, fb), where};
  if (keyed)
    if (const std::optional<int> m = recall(key)) return *m == kUndecided ? *m : flip * *m;
  auto done = [&](int r) {
    if (!keyed) return r;
    return r == kUndecided ? remember(key, r) : remember(key, flip * r) * flip;
  };
  auto arb_level = [&] { return ball_sign(time_ball(w1, x1) - time_ball(w2, x2)); };
  auto arb = [&] { return escalate(cap, arb_level); };
  // Arb's first level before the exact stage (as in side_if_certified).
  if (const int a = arb_first ? arb() : escalate(128, arb_level); a != kUndecided) return done(a);
  if (exact_window(w1) && exact_window(w2)) {
    const auto t1 = exact_time(w1, x1), t2 = exact_time(w2, x2);
    if (t1 && t2) {
      const int e = exact_sign(*t1 - *t2);
      ++(e == 0 ? counts.exact_equal : counts.exact);
      return done(e);
    }
  }
  const int r = arb_first ? kUndecided : arb();
  if (r == kUndecided && !deciding) ++counts.kept_undecided;
  return done(r);
}

int Certifier::compare_directions(std::uint32_t w1, std::uint32_t w2, std::uint32_t v) {
  trim_memos();
  const Window &a = s_.windows[w1], &b = s_.windows[w2];
  const IPoint x = ipoint(u_.vertex_image(a.triangle, v));
  const IPoint d1 = window_direction(a, x), d2 = window_direction(b, x);
  const int s = certified_sign(icross(d1.x, d1.y, d2.x, d2.y));
  if (s != kUndecided) {
    ++counts.filter;
    return s;
  }
  if (same_expression(w1, w2, Target{v, nullptr})) {
    ++counts.structural_equal;
    return 0;
  }
  const ExactWindow* ea = exact_window(w1);
  const ExactWindow* eb = ea ? exact_window(w2) : nullptr;
  if (ea && eb && ea->frame == eb->frame) {
    const int e = exact_direction_cross(*ea, *eb, v);
    ++(e == 0 ? counts.exact_equal : counts.exact);
    return e;
  }
  const int r = escalate(prune_bits_, [&] {
    const WindowBall ba = evaluate(w1, false), bb = evaluate(w2, false);
    const BallVec2 p = u_.vertex_ball(a.triangle, v);
    const BallVec2 da = ba.plane ? ba.source : ball_sub(p, ba.source);
    const BallVec2 db = bb.plane ? bb.source : ball_sub(p, bb.source);
    return ball_sign(ball_cross(da, db));
  });
  if (r == kUndecided) ++counts.kept_undecided;
  return r;
}

}  // namespace grassfire
