// edge_crossings.cpp -- see edge_crossings.h.
#include "burn3/exact/edge_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "burn3/exact/edge_fronts.h"
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

// Which side of its corner the box [a, b] lies on: +1 after, -1 before, 0 around it (or
// not on the line). The box's ends are exact doubles; a box ending at the corner is on
// one side of it.
int corner_side(const OnLine& o, double a, double b) {
  if (!o.on) return 0;
  if (a >= o.corner.hi) return 1;
  if (b <= o.corner.lo) return -1;
  return 0;
}

// f = time_a - time_b along E over boxes of doubles (exact rationals), from the fronts'
// closed forms (edge_fronts.h): the double enclosures first, then Arb at 128 bits (boxes:
// and at max_bits), then (signs at points) the staged comparison at the exact point.
struct Difference {
  const Unfolding& u;
  Certifier& cert;
  EdgeFronts& fronts;
  std::uint32_t edge, wa, wb;
  const EdgeFront &fa, &fb;
  OnLine oa, ob;
  std::vector<double> zeros;                    // distinct points where f = 0 is proved
  std::vector<std::pair<double, int>> known;    // signs computed (a box's ends are asked twice)
  std::optional<bool> tie;                      // tie_on_range(), once asked

  Interval value(const Interval& l) const { return front_time(fa.d, l) - front_time(fb.d, l); }
  Interval slope(const Interval& l) const { return front_rate(fa.d, l) - front_rate(fb.d, l); }
  const FrontCoefficients<Ball>& ball_a(int level) { return fronts.ball(cert, wa, edge, level); }
  const FrontCoefficients<Ball>& ball_b(int level) { return fronts.ball(cert, wb, edge, level); }
  long bits(int level) const { return level == 0 ? 128 : cert.max_bits(); }
  int double_sign(double q) const { return certified_sign(value(Interval(q))); }
  int arb_sign(double q) {  // at 128 bits
    BallPrecision guard(bits(0));
    const Ball x(q);
    return (front_time(ball_a(0), x) - front_time(ball_b(0), x)).sign();
  }
  // The certified sign of f at q (kUndecided: no stage settled it at max_bits).
  int sign(double q) {
    for (const auto& [x, g] : known)
      if (x == q) return g;
    int g = double_sign(q);
    if (g != 1 && g != -1) g = arb_sign(q);
    if (g != 1 && g != -1) {  // structural and exact stages, Arb to max_bits: ties are common here
      const mpq_class l(q);
      const ExactPoint3 p = edge_point_at(u.complex(), edge, l);
      g = cert.compare_times(wa, Target{kNoIndex, &p, 0, edge, &l}, wb, Target{kNoIndex, &p, 0, edge, &l}, false, true);
    }
    if (g == 0) zeros.push_back(q);
    known.emplace_back(q, g);
    return g;
  }
  // The box [a, b] in Arb at `level`: -1 excluded (no root), 1 monotone, 0 neither;
  // *exhausted: the point value's own width dominates (a finer box would not help).
  int arb_box(double a, double b, int level, bool* exhausted, double* bound) {
    BallPrecision guard(bits(level));
    const FrontCoefficients<Ball>&A = ball_a(level), &B = ball_b(level);
    const Ball X = hull(Ball(a), Ball(b)), m(0.5 * a + 0.5 * b);
    const Ball slope = front_rate(A, X) - front_rate(B, X);
    const int ms = slope.sign();
    if (ms == 1 || ms == -1) return 1;
    const Ball naive = front_time(A, X) - front_time(B, X);
    if (const int g = naive.sign(); g == 1 || g == -1) return -1;
    const Ball at_m = front_time(A, m) - front_time(B, m);
    const Interval c = (at_m + slope * (X - m)).to_interval(), pm = at_m.to_interval();
    if (certified_sign(c) == 1 || certified_sign(c) == -1) return -1;
    const Interval v = naive.to_interval();
    *bound = std::min(std::max(-c.lo, c.hi), std::max(-v.lo, v.hi));
    if (!(*bound >= 0)) *bound = std::numeric_limits<double>::infinity();
    *exhausted = 4 * (pm.hi - pm.lo) >= c.hi - c.lo;
    return 0;
  }
  // |f(q)| <= 2^-64, by Arb at max_bits: a tie no stage proves (the usual cause: one value
  // reached through two expressions). Where f is monotone with |f'| >= 2^-40, a root near
  // such a point lies within 2^-24 ulps-of-one of it, and between it and the point the two
  // times differ by at most 2^-64: an order taken there moves BT by at most that, far below
  // the engine's reported errors.
  bool negligible_at(double q) {
    BallPrecision guard(bits(1));
    const Interval d = (front_time(ball_a(1), Ball(q)) - front_time(ball_b(1), Ball(q))).to_interval();
    return std::max(-d.lo, d.hi) <= kNegligible;
  }
  // The two fronts within 2^-64 of each other on the whole range [lo, hi], from their
  // coefficients (edge_fronts.h front_difference_bound, at 128 bits, else max_bits), else
  // from Arb's centred form over the range (Certifier::edge_difference_bound): an
  // order taken anywhere in it moves the (k-1)-th arrival by at most that (order
  // statistics are 1-Lipschitz in the sup norm), far below the reported errors.
  bool tie_on_range(double lo, double hi) {
    if (!tie)
      tie = front_difference_bound(ball_a(0), ball_b(0), lo, hi) <= kNegligible ||
            front_difference_bound(ball_a(1), ball_b(1), lo, hi) <= kNegligible ||
            cert.edge_difference_bound(wa, wb, edge, mpq_class(lo), mpq_class(hi), cert.max_bits()) <= kNegligible;
    return *tie;
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
bool exact_isolation(Difference& f, const std::vector<ExactSum>& candidates, double lo, double hi,
                     std::vector<std::array<double, 2>>* found, std::uint32_t* undecided) {
  auto order = [](const ExactSum& r, double q) {  // sign of r - q, kUndecided
    if (r.constant_terms().empty()) return exact_sign(r - ExactSum::rational(mpq_class(q)));
    return certified_sign(r.approx() - Interval(q));
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
    const double cl = std::nextafter(e.lo, -1.0), cr = std::nextafter(e.hi, 2.0);
    if (!(lo < cl && cr < hi)) return false;
    const int sl = f.sign(cl), sr = f.sign(cr);
    if (sl == 0 || sr == 0) return false;
    if (!decided(sl) || !decided(sr)) ++*undecided;
    if (opposite(sl, sr)) found->push_back({cl, cr});
  }
  return true;
}

}  // namespace

EdgeCrossings isolate_crossings(const Unfolding& u, const WindowStore& s, Certifier& cert, EdgeFronts& fronts,
                                std::uint32_t edge, std::uint32_t wa, std::uint32_t wb, const mpq_class& qlo,
                                const mpq_class& qhi) {
  const Window &A = s.windows[wa], &B = s.windows[wb];
  EdgeCrossings out;
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
  // The range as doubles (the boxes' ends are doubles, exact rationals), outwards.
  double lo = qlo.get_d(), hi = qhi.get_d();
  if (mpq_class(lo) > qlo) lo = std::nextafter(lo, -1.0);
  if (mpq_class(hi) < qhi) hi = std::nextafter(hi, 2.0);
  const OnLine oa = on_line(u, s, edge, wa), ob = on_line(u, s, edge, wb);
  Difference f{u, cert, fronts, edge, wa, wb, fronts.front(cert, wa, edge, oa.on, oa.corner),
               fronts.front(cert, wb, edge, ob.on, ob.corner),
               oa, ob, {}, {}, {}};
  // One function along the edge (the same source reached through different unfoldings):
  // proved from exact data where the coefficients say the fronts are within 2^-64 (asked
  // only then: the exact data costs far more than the isolation).
  auto tie = [&] {
    if (!f.tie_on_range(lo, hi)) return false;
    if (identical_along_edge(u, s, cert, edge, wa, wb)) out.equal = true;
    else ++out.negligible;
    return true;
  };
  struct Box {
    double a, b;
    int depth;
    bool arb;  // the double enclosures no longer decide it
  };
  std::vector<Box> todo;
  std::vector<std::array<double, 2>> found;
  // The range cut at the corners of windows whose source lies on E's line: at a corner
  // that is a double exactly; around any other (an edge point known by its closed form or
  // enclosure, a rational between doubles) at the doubles just outside its enclosure, the
  // box between them decided by the signs at its ends (corner_box).
  std::vector<double> cuts{lo, hi};
  std::vector<std::array<double, 2>> corner_boxes;
  for (const OnLine* o : {&f.oa, &f.ob}) {
    if (!o->on || !(o->corner.hi > lo && o->corner.lo < hi)) continue;
    if (o->corner.lo == o->corner.hi) {
      cuts.push_back(o->corner.lo);
      continue;
    }
    const double cl = std::nextafter(o->corner.lo, -1.0), cr = std::nextafter(o->corner.hi, 2.0);
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
    if (!corner) todo.push_back({cuts[i], cuts[i + 1], 0, false});
  }
  std::size_t near_ties = 0;
  auto equal_fronts = [&] {  // f proved 0 at five points: one expression along the edge
    out = EdgeCrossings{};
    out.equal = true;
    return out;
  };
  while (!todo.empty()) {
    if (f.zeros.size() >= kEqualPoints) return equal_fronts();
    const Box x = todo.back();
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
    // Both sources on E's line, the box on the same side of both corners: the slopes are
    // both +|E| or both -|E|, f is constant there (no sign change, whatever its sign).
    if (const int side = corner_side(f.oa, x.a, x.b); side != 0 && side == corner_side(f.ob, x.a, x.b)) continue;
    const double mid = 0.5 * x.a + 0.5 * x.b;
    bool exhausted = x.arb;
    {
      const Interval L(x.a, x.b), M(mid);
      const Interval slope = f.slope(L);
      if (const int m = certified_sign(slope); m == 1 || m == -1) {
        monotone(slope);
        continue;
      }
      if (const int naive = certified_sign(f.value(L)); naive == 1 || naive == -1) continue;  // excluded
      const Interval at_m = f.value(M);
      if (std::isfinite(slope.lo) && std::isfinite(slope.hi)) {  // the centred form, tighter on short boxes
        const Interval c = at_m + slope * (L - M);
        if (const int g = certified_sign(c); g == 1 || g == -1) continue;
        exhausted = exhausted || 4 * (at_m.hi - at_m.lo) >= c.hi - c.lo;
      }
    }
    const bool last = x.depth >= kMaxDepth || out.boxes > kNodeBudget || !(x.a < mid && mid < x.b);
    if (exhausted || last) {  // Arb: at 128 bits, at max_bits where 128 are exhausted too
      int verdict = 0;
      bool deeper = false;
      double bound = std::numeric_limits<double>::infinity();  // |f| on the box, at the last level
      for (int level = 0; level < 2 && verdict == 0; ++level) {
        deeper = false;
        verdict = f.arb_box(x.a, x.b, level, &deeper, &bound);
        if (!deeper && !last) break;
      }
      if (verdict == -1) continue;
      if (verdict == 1) {
        monotone(Interval(0.0));
        continue;
      }
      if (last && bound <= kNegligible) {  // within 2^-64 on this box: either order moves A by at most that
        ++out.negligible;
        continue;
      }
      if (last) {
        if (tie()) return out.equal ? equal_fronts() : out;
        ++out.undecided;
        if (opposite(f.sign(x.a), f.sign(x.b))) found.push_back({x.a, x.b});
        continue;
      }
    }
    const int sm = f.sign(mid);
    if (sm == 0) found.push_back({mid, mid});  // undecided: the halves' tests count it if it matters
    // Signs no stage settles at three points (split points or the range's ends: ties no
    // stage proves, the fronts being one expression unproved): stop, one undecided
    // decision, rather than subdivide towards every point of the line.
    if (sm == kUndecided && (tie() || ++near_ties + (f.sign(lo) == kUndecided) + (f.sign(hi) == kUndecided) >= 3)) {
      if (out.equal) return equal_fronts();
      if (out.negligible) return out;
      ++out.undecided;
      break;
    }
    todo.push_back({mid, x.b, x.depth + 1, exhausted});
    todo.push_back({x.a, mid, x.depth + 1, exhausted});
  }
  if (f.zeros.size() >= kEqualPoints) return equal_fronts();
  // What the subdivision left undecided, the exact path may settle (planar sheets with short
  // rational data: every root of f among the roots of the squared polynomial).
  if (out.undecided)
    if (const std::optional<std::vector<ExactSum>> c = crossing_candidates(u, s, cert, edge, wa, wb)) {
      std::uint32_t undecided = 0;
      std::vector<std::array<double, 2>> exact;
      if (exact_isolation(f, *c, lo, hi, &exact, &undecided)) found = std::move(exact), out.undecided = undecided;
    }
  // Narrow each bracket while the double enclosures decide.
  for (auto& [a, b] : found) {
    if (a == b) continue;
    const int sa = f.double_sign(a);
    if (sa != 1 && sa != -1) continue;
    for (int i = 0; i < kNarrowSteps; ++i) {
      const double mid = 0.5 * a + 0.5 * b;
      if (!(a < mid && mid < b)) break;
      const int sm = f.double_sign(mid);
      if (sm != 1 && sm != -1) break;
      (sm == sa ? a : b) = mid;
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& p, const auto& q) { return p[0] < q[0]; });
  for (auto& [a, b] : found) {
    // A proved zero at an end of the range is a record's end, not a crossing inside.
    if (a == b && (a == lo || a == hi)) continue;
    out.roots.push_back({mpq_class(a), mpq_class(b), 0.5 * a + 0.5 * b});
  }
  return out;
}

}  // namespace grassfire
