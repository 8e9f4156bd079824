// edge_crossings.cpp -- see edge_crossings.h.
#include "burn3/exact/edge_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "burn3/exact/junction_kinks.h"
#include "burn3/exact/junction_tangents.h"
#include "geometry3/exact_predicates3.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

constexpr int kMaxDepth = 48;            // boxes down to 2^-48 of the range
constexpr std::uint32_t kNodeBudget = 256;  // boxes per pair before Arb decides the rest
constexpr std::size_t kEqualPoints = 5;  // zeros that prove f = 0 (degree <= 4 after squaring)
constexpr int kNarrowSteps = 44;
constexpr double kNegligible = 0x1p-64;  // a tie's width below every reported error (see negligible())

// Where a window's source lies on the edge's line (a root window of a point source on E:
// an edge point of E, a vertex of E, a caller's point on E), its time along E is exactly
// sigma + |E| |l - corner|: a corner at `corner`, slope -|E| before and +|E| after it.
struct OnLine {
  bool on = false;
  Interval corner;               // the source's parameter
  std::uint32_t point = kNoIndex;  // an edge point of E (kEdgePointBound target), else none
  mpq_class exact;               // its rational value, when it has one (vertices, given points)
  bool rational = false;
};

OnLine on_line(const Unfolding& u, const WindowStore& s, std::uint32_t edge, std::uint32_t w) {
  OnLine o;
  const Window& W = s.windows[w];
  if (!W.root()) return o;
  const PseudoSource& ps = s.pseudo[W.pseudo];
  const MedialComplex& mc = u.complex();
  const auto& ev = mc.edge(edge).v;
  if (ps.origin == SourceOrigin::EdgePoint && s.edge_points[ps.data].edge == edge) {
    const EdgePoint& ep = s.edge_points[ps.data];
    o.on = true, o.point = ps.data;
    o.corner = ep.exact >= 0 ? s.exact_times[ep.exact].approx() : ep.lambda;
    if (ep.exact >= 0 && s.exact_times[ep.exact].sqrt_terms().empty() && s.exact_times[ep.exact].constant_terms().empty())
      o.rational = true, o.exact = s.exact_times[ep.exact].rational_part();
  } else if (ps.origin == SourceOrigin::Vertex && (ps.vertex == ev[0] || ps.vertex == ev[1])) {
    o.on = o.rational = true, o.exact = ps.vertex == ev[0] ? 0 : 1;
  } else if (ps.origin == SourceOrigin::GivenPoint) {
    const ExactPoint3 &a = mc.vertex(ev[0]).exact, &b = mc.vertex(ev[1]).exact, &p = s.given[ps.data].point;
    if (!(cross(b - a, p - a) == ExactPoint3{})) return o;
    o.on = o.rational = true, o.exact = dot(p - a, b - a) / dot(b - a, b - a);
  }
  if (o.rational) o.corner = enclose(o.exact);
  return o;
}

// A window's time and its derivative in l over a parameter box, by interval arithmetic on
// the window's discs (window_values.h): rigorous enclosures.
Interval box_time(const Window& w, const EdgeImage& e, const Interval& l) {
  return window_time(w, IPoint{e.ax + l * e.dx, e.ay + l * e.dy});
}
// Which side of its corner the box [qa, qb] (enclosed by l) lies on: +1 after, -1 before,
// 0 around it (or not on the line).
int corner_side(const OnLine& o, const Interval& l, const mpq_class& qa, const mpq_class& qb) {
  if (!o.on) return 0;
  if (o.rational ? qa >= o.exact : l.lo > o.corner.hi) return 1;
  if (o.rational ? qb <= o.exact : l.hi < o.corner.lo) return -1;
  return 0;
}

// The box is [qa, qb] (rationals), enclosed by l.
Interval box_rate(const Window& w, const EdgeImage& e, const OnLine& o, const Interval& l, const mpq_class& qa,
                  const mpq_class& qb) {
  const Interval len = sqrt(square(e.dx) + square(e.dy));
  if (o.on) {  // +-|E| on either side of the corner (and |rate| <= |E| everywhere)
    const int side = corner_side(o, l, qa, qb);
    if (side == 1) return len;
    if (side == -1) return Interval(0.0) - len;
    return {-len.hi, len.hi};
  }
  const IPoint s = ipoint(w.source);
  if (w.plane()) return s.x * e.dx + s.y * e.dy;
  const Interval x = e.ax + l * e.dx - s.x, y = e.ay + l * e.dy - s.y;
  const Interval n2 = square(x) + square(y);
  if (!(n2.lo > 0.0)) return {-len.hi, len.hi};
  const Interval r = (x * e.dx + y * e.dy) / sqrt(n2);
  return {std::max(r.lo, -len.hi), std::min(r.hi, len.hi)};
}

struct Difference {
  const Unfolding& u;
  Certifier& cert;
  const Window &a, &b;
  std::uint32_t edge, wa, wb;
  EdgeImage ea, eb;
  OnLine oa, ob;
  std::vector<mpq_class> zeros;  // distinct rationals where f = 0 is proved
  std::vector<std::pair<mpq_class, int>> known;  // signs computed (a box's ends are asked twice)

  Interval value(const Interval& l) const { return box_time(a, ea, l) - box_time(b, eb, l); }
  Interval slope(const Interval& l, const mpq_class& qa, const mpq_class& qb) const {
    return box_rate(a, ea, oa, l, qa, qb) - box_rate(b, eb, ob, l, qa, qb);
  }
  int double_sign(const mpq_class& q) const { return certified_sign(value(enclose(q))); }
  // The certified sign of f at q (kUndecided: no stage settled it at max_bits).
  int sign(const mpq_class& q) {
    for (const auto& [x, g] : known)
      if (x == q) return g;
    int g = double_sign(q);
    if (g == kUndecided) {  // the exact stage before Arb's higher levels: ties are common here
      const ExactPoint3 p = edge_point_at(u.complex(), edge, q);
      g = cert.compare_times(wa, Target{kNoIndex, &p, 0, edge, &q}, wb, Target{kNoIndex, &p, 0, edge, &q}, false, true);
    }
    if (g == 0) zeros.push_back(q);
    known.emplace_back(q, g);
    return g;
  }
  // |f(x)| <= 2^-64, by Arb at max_bits: a tie no stage proves (the usual cause: one value
  // reached through two expressions). Where f is monotone with |f'| >= 2^-40, a root near
  // such a point lies within 2^-24 ulps-of-one of it, and between it and the point the two
  // times differ by at most 2^-64: an order taken there moves BT by at most that, far below
  // the engine's reported errors.
  bool negligible(const Target& x) {
    BallPrecision guard(cert.max_bits());
    const Interval d = (cert.time_ball(wa, x) - cert.time_ball(wb, x)).to_interval();
    return std::max(-d.lo, d.hi) <= 0x1p-64;
  }
  bool negligible_at(const mpq_class& q) {
    const ExactPoint3 p = edge_point_at(u.complex(), edge, q);
    return negligible(Target{kNoIndex, &p, 0, edge, &q});
  }
};

// r a first window of an edge point Q of E (on E's line) whose offset is w's time at Q
// (w the window named by r's time expression, or the other window of Q's defining
// crossing, equal to it at Q): along E, r = w(Q) + |x - Q| >= w(x), since w's time along E
// is 1-Lipschitz in arc length (a unit gradient in its frame): r - w has one sign on the
// whole line (Huygens along the edge; Q is where w burned the edge, 4.2.1).
bool relayed_from(const WindowStore& s, std::uint32_t edge, std::uint32_t r, std::uint32_t w) {
  const Window& R = s.windows[r];
  if (!R.root()) return false;
  const PseudoSource& ps = s.pseudo[R.pseudo];
  if (ps.origin != SourceOrigin::EdgePoint || ps.time == kNoIndex || s.edge_points[ps.data].edge != edge) return false;
  const TimeExpr& te = s.times[ps.time];
  if (te.kind != TimeExpr::Kind::WindowAt || te.b != (ps.data | kEdgePointBound)) return false;
  if (te.a == w) return true;
  const auto& eq = s.edge_points[ps.data].equal_windows;
  return (eq[0] == te.a && eq[1] == w) || (eq[1] == te.a && eq[0] == w);
}

bool opposite(int sa, int sb) { return (sa == 1 && sb == -1) || (sa == -1 && sb == 1); }
bool decided(int s) { return s != kUndecided; }

// The exact path: every root of f is among the candidates (the roots of the squared
// polynomial, exact sums), so between them f has one sign; a candidate inside (lo, hi) is a
// crossing iff the certified signs of f just below and just above its enclosure differ
// (a tangency or a spurious root of the squaring has equal signs). Returns false where the
// candidates cannot be placed (overlapping enclosures, a candidate within an ulp of an end):
// the subdivision decides then.
bool exact_isolation(Difference& f, const std::vector<ExactSum>& candidates, const mpq_class& lo, const mpq_class& hi,
                     std::vector<std::array<mpq_class, 2>>* found, std::uint32_t* undecided) {
  auto order = [](const ExactSum& r, const mpq_class& q) {  // sign of r - q, kUndecided
    if (r.constant_terms().empty()) return exact_sign(r - ExactSum::rational(q));
    return certified_sign(r.approx() - enclose(q));
  };
  std::vector<std::pair<Interval, const ExactSum*>> inside;
  for (const ExactSum& r : candidates) {
    const int a = order(r, lo), b = order(r, hi);
    if (a == kUndecided || b == kUndecided) return false;
    if (a == 1 && b == -1) inside.emplace_back(r.approx(), &r);
  }
  std::sort(inside.begin(), inside.end(), [](const auto& x, const auto& y) { return x.first.lo < y.first.lo; });
  for (std::size_t i = 0; i + 1 < inside.size(); ++i) {
    if (inside[i].first.hi < inside[i + 1].first.lo) continue;
    const ExactSum d = *inside[i].second - *inside[i + 1].second;
    if (!d.constant_terms().empty() || exact_sign(d) != 0) return false;
    inside.erase(inside.begin() + static_cast<std::ptrdiff_t>(i + 1)), --i;  // one root twice
  }
  for (const auto& [e, r] : inside) {
    const mpq_class cl(std::nextafter(e.lo, -1.0)), cr(std::nextafter(e.hi, 2.0));
    if (!(lo < cl && cr < hi)) return false;
    const int sl = f.sign(cl), sr = f.sign(cr);
    if (sl == 0 || sr == 0) return false;
    if (!decided(sl) || !decided(sr)) ++*undecided;
    if (opposite(sl, sr)) found->push_back({cl, cr});
  }
  return true;
}

}  // namespace

EdgeCrossings isolate_crossings(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                                std::uint32_t wa, std::uint32_t wb, const mpq_class& lo, const mpq_class& hi) {
  const Window &A = s.windows[wa], &B = s.windows[wb];
  Difference f{u,  cert, A, B, edge, wa, wb, EdgeImage(u, A, edge), EdgeImage(u, B, edge),
               on_line(u, s, edge, wa), on_line(u, s, edge, wb), {}, {}};
  EdgeCrossings out;
  struct Box {
    mpq_class a, b;
    int depth;
  };
  std::vector<Box> todo;
  std::vector<std::array<mpq_class, 2>> found;
  // One window thrown by the other's front (junction_tangents.h): b >= a on the whole
  // plane of their triangle, no sign change.
  if (A.triangle == B.triangle && (starts_on_front(u, s, cert, wa, wb) || starts_on_front(u, s, cert, wb, wa))) {
    out.equal = true;
    return out;
  }
  if (relayed_from(s, edge, wa, wb) || relayed_from(s, edge, wb, wa)) {
    out.equal = true;
    return out;
  }
  // One function along the edge (the same source reached through different unfoldings,
  // proved from exact data): no sign change anywhere.
  if (identical_along_edge(u, s, cert, edge, wa, wb)) {
    out.equal = true;
    return out;
  }
  if (const std::optional<std::vector<ExactSum>> c = crossing_candidates(u, s, cert, edge, wa, wb)) {
    std::uint32_t undecided = 0;
    if (exact_isolation(f, *c, lo, hi, &found, &undecided)) {
      out.undecided = undecided;
      for (auto& [a, b] : found) out.roots.push_back({a, b, mpq_class((a + b) / 2).get_d()});
      return out;
    }
    found.clear();
  }
  // The range cut at the corners of windows whose source lies on E's line: at a rational
  // corner exactly; around an irrational one (an edge point known by its closed form or
  // enclosure) at the rationals just outside its enclosure, the box between them decided by
  // the sign of f at the corner itself (corner_box).
  std::vector<mpq_class> cuts{lo, hi};
  std::vector<std::array<mpq_class, 2>> corner_boxes;
  for (const OnLine* o : {&f.oa, &f.ob}) {
    if (!o->on || !(o->corner.hi > lo.get_d() && o->corner.lo < hi.get_d())) continue;
    if (o->rational) {
      if (lo < o->exact && o->exact < hi) cuts.push_back(o->exact);
      continue;
    }
    const mpq_class cl(std::nextafter(o->corner.lo, -1.0)), cr(std::nextafter(o->corner.hi, 2.0));
    if (!(lo < cl && cr < hi)) {  // at the range's end: the whole range is decided around it
      ++out.undecided;
      continue;
    }
    cuts.push_back(cl), cuts.push_back(cr);
    corner_boxes.push_back({cl, cr});
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    bool corner = false;
    for (std::size_t k = 0; k < corner_boxes.size(); ++k) {
      if (corner_boxes[k][0] != cuts[i] || corner_boxes[k][1] != cuts[i + 1]) continue;
      corner = true;
      // The box is one ulp around the corner (an edge point: a breakpoint already), so every
      // sign change in it is at the corner to within an ulp: one bracket when the signs at
      // its ends differ, none otherwise (nothing is decided inside it).
      // An undecided end there (a tie along one side of the corner) changes nothing outside it.
      if (opposite(f.sign(cuts[i]), f.sign(cuts[i + 1]))) found.push_back({cuts[i], cuts[i + 1]});
      break;
    }
    if (!corner) todo.push_back({cuts[i], cuts[i + 1], 0});
  }
  std::size_t near_ties = 0;
  // The two fronts within 2^-64 of each other on the whole range (Arb at max_bits; asked
  // once, when the subdivision first fails to settle a box): whichever order is taken
  // anywhere in it, the (k-1)-th arrival moves by at most that (order statistics are
  // 1-Lipschitz in the sup norm), far below the reported errors; no crossing is claimed.
  std::optional<bool> tie_on_range;
  auto negligible_range = [&] {
    if (!tie_on_range) tie_on_range = cert.edge_difference_bound(wa, wb, edge, lo, hi, cert.max_bits()) <= kNegligible;
    return *tie_on_range;
  };
  while (!todo.empty()) {
    if (f.zeros.size() >= kEqualPoints) {  // one expression along the edge: no crossing
      out.equal = true;
      out.undecided = 0;
      return out;
    }
    Box x = std::move(todo.back());
    todo.pop_back();
    ++out.boxes;
    auto monotone = [&](const Interval& slope) {  // at most one root: present iff the end signs differ
      const int sa = f.sign(x.a), sb = f.sign(x.b);
      // A negligible tie at an end of the range (the other end decided), |f'| >= 2^-40 on
      // the box: a root, if any, lies within 2^-24 of that end, where a record ends (a
      // breakpoint already), and the times differ by at most 2^-64 up to it: none is claimed.
      const bool steep = std::min(std::fabs(slope.lo), std::fabs(slope.hi)) >= 0x1p-40;
      if (steep && !decided(sa) && x.a == lo && decided(sb) && sb != 0 && f.negligible_at(x.a)) return void(++out.negligible);
      if (steep && !decided(sb) && x.b == hi && decided(sa) && sa != 0 && f.negligible_at(x.b)) return void(++out.negligible);
      if (!decided(sa) || !decided(sb)) ++out.undecided;
      else if (opposite(sa, sb)) found.push_back({x.a, x.b});
    };
    const Interval L{enclose(x.a).lo, enclose(x.b).hi};
    // Both sources on E's line, the box on the same side of both corners: the slopes are
    // both +|E| or both -|E|, f is constant there (no sign change, whatever its sign).
    if (const int side = corner_side(f.oa, L, x.a, x.b); side != 0 && side == corner_side(f.ob, L, x.a, x.b)) continue;
    const Interval slope = f.slope(L, x.a, x.b);
    if (const int m = certified_sign(slope); m == 1 || m == -1) {
      monotone(slope);
      continue;
    }
    const mpq_class mid = (x.a + x.b) / 2;
    const Interval M = enclose(mid);
    const bool bounded = std::isfinite(slope.lo) && std::isfinite(slope.hi);
    const int naive = certified_sign(f.value(L));
    if (naive == 1 || naive == -1) continue;  // excluded
    if (bounded) {                            // the centred form, tighter on short boxes
      const int c = certified_sign(f.value(M) + slope * (L - M));
      if (c == 1 || c == -1) continue;
    }
    if (x.depth >= kMaxDepth || out.boxes > kNodeBudget) {
      if (negligible_range()) {
        ++out.negligible;
        return out;
      }
      // Arb on the whole box: exclusion or monotonicity, else undecided.
      int verdict = kUndecided;
      double bound = std::numeric_limits<double>::infinity();  // |f| on the box, at the last level
      for (long bits = 128; bits <= cert.max_bits() && verdict == kUndecided; bits *= 2) {
        const auto g = cert.edge_difference_signs(wa, wb, edge, x.a, x.b, bits, &bound);
        if (g[0] == 1 || g[0] == -1) verdict = 0;
        else if (g[1] == 1 || g[1] == -1) verdict = 1;
      }
      if (verdict == 1) monotone(Interval(0.0));
      else if (verdict == kUndecided && bound <= kNegligible)
        ++out.negligible;  // within 2^-64 on this box: either order moves A by at most that
      else if (verdict == kUndecided) {
        ++out.undecided;
        if (opposite(f.sign(x.a), f.sign(x.b))) found.push_back({x.a, x.b});
      }
      continue;
    }
    const int sm = f.sign(mid);
    if (sm == 0) found.push_back({mid, mid});  // undecided: the halves' tests count it if it matters
    // Signs no stage settles at three points (split points or the range's ends: ties no
    // stage proves, the fronts being one expression unproved): stop, one undecided
    // decision, rather than subdivide towards every point of the line.
    if (sm == kUndecided && ++near_ties + (f.sign(lo) == kUndecided) + (f.sign(hi) == kUndecided) >= 3) {
      if (negligible_range()) {
        ++out.negligible;
        return out;
      }
      ++out.undecided;
      break;
    }
    todo.push_back({mid, x.b, x.depth + 1});
    todo.push_back({x.a, mid, x.depth + 1});
  }
  if (f.zeros.size() >= kEqualPoints) {
    out.equal = true;
    out.undecided = 0;
    return out;
  }
  // Narrow each bracket while the double enclosures decide.
  for (auto& [a, b] : found) {
    if (a == b) continue;
    const int sa = f.double_sign(a);
    if (sa != 1 && sa != -1) continue;
    for (int i = 0; i < kNarrowSteps; ++i) {
      const mpq_class mid = (a + b) / 2;
      const int sm = f.double_sign(mid);
      if (sm != 1 && sm != -1) break;
      (sm == sa ? a : b) = mid;
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& p, const auto& q) { return p[0] < q[0]; });
  for (auto& [a, b] : found) {
    // A proved zero at an end of the range is a record's end, not a crossing inside.
    if (a == b && (a == lo || a == hi)) continue;
    out.roots.push_back({a, b, mpq_class((a + b) / 2).get_d()});
  }
  return out;
}

}  // namespace grassfire
