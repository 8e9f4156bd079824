// junction_points.cpp -- kinks, merges and quench points of the junction rule (see
// junction_points.h).
#include "burn3/exact/junction_points.h"

#include <algorithm>

#include "burn3/exact/junction_tangents.h"
#include "burn3/exact/sources.h"
#include "geometry3/exact_predicates3.h"
#include "number/ball.h"

namespace grassfire {

namespace {

// The derivative of window w's time along edge `edge` at its edge point ep, per unit of the
// parameter v[0] -> v[1], at the current Arb precision (a ball holding zero where S = X).
Ball slope(Certifier& cert, const MedialComplex& mc, const WindowStore& s, std::uint32_t w, std::uint32_t edge,
           std::uint32_t ep) {
  const WindowBall b = cert.evaluate(w, false);
  const std::uint32_t t = s.windows[w].triangle;
  const auto& ev = mc.edge(edge).v;
  const BallVec2 a = cert.target_ball(t, Target{ev[0], nullptr}), c = cert.target_ball(t, Target{ev[1], nullptr});
  const Ball dx = c.x - a.x, dy = c.y - a.y;
  if (b.plane) return b.source.x * dx + b.source.y * dy;
  const BallVec2 x = cert.target_ball(t, Target{ep | kEdgePointBound, nullptr});
  const Ball rx = x.x - b.source.x, ry = x.y - b.source.y;
  return (rx * dx + ry * dy) / sqrt(rx * rx + ry * ry);
}

struct Slopes {
  int left = kUndecided, right = kUndecided, corner = kUndecided;  // signs of a', b', b' - a'
};

Slopes certified_slopes(Certifier& cert, const MedialComplex& mc, const WindowStore& s,
                        const WindowPropagation::JunctionSwitch& sw, long max_bits) {
  Slopes r;
  for (long bits = 128; bits <= max_bits; bits *= 2) {
    BallPrecision guard(bits);
    Ball a = slope(cert, mc, s, sw.left, sw.edge, sw.point);
    Ball b = slope(cert, mc, s, sw.right, sw.edge2 == kNoIndex ? sw.edge : sw.edge2,
                   sw.edge2 == kNoIndex ? sw.point : sw.point2);
    if (sw.edge2 != kNoIndex) {
      // At a vertex v: both per unit length, along the curve from edge into edge2.
      const auto &e1 = mc.edge(sw.edge).v, &e2 = mc.edge(sw.edge2).v;
      const std::uint32_t v = (e1[0] == e2[0] || e1[0] == e2[1]) ? e1[0] : e1[1];
      const Ball l1 = sqrt(ball_of(squared_distance(mc.vertex(e1[0]).exact, mc.vertex(e1[1]).exact)));
      const Ball l2 = sqrt(ball_of(squared_distance(mc.vertex(e2[0]).exact, mc.vertex(e2[1]).exact)));
      a = (v == e1[1] ? a : -a) / l1;
      b = (v == e2[0] ? b : -b) / l2;
    }
    if (r.left == kUndecided) r.left = a.sign();
    if (r.right == kUndecided) r.right = b.sign();
    if (r.corner == kUndecided) r.corner = (b - a).sign();
    if (r.left != kUndecided && r.right != kUndecided && r.corner != kUndecided) break;
  }
  return r;
}

// a and b are one function along the edge: equal times at both ends (and at the switch).
// Never at a vertex switch (two edges: not one function along one line).
bool same_front(Certifier& cert, const MedialComplex& mc, const WindowPropagation::JunctionSwitch& sw) {
  if (sw.edge2 != kNoIndex) return false;
  for (std::uint32_t v : mc.edge(sw.edge).v) {
    const Target x{v, nullptr};
    if (cert.compare_times(sw.left, x, sw.right, x) != 0) return false;
  }
  return true;
}

// Undecided slopes of two fronts that are not one function: a tangent handover when b (or
// a) is proved to start on the other's front; both slopes certified finite (p is not the
// point window's source, where its time has no derivative).
bool tangent(ExactBurning& eb, const Slopes& d, const WindowPropagation::JunctionSwitch& sw) {
  if (d.corner != kUndecided || d.left == kUndecided || d.right == kUndecided) return false;
  return starts_on_front(eb, sw.left, sw.right) || starts_on_front(eb, sw.right, sw.left);
}

// A corner certified between two windows of one triangle of which one is proved to start
// on the other's front (junction_tangents.h: b >= a on the whole plane, equal only along a
// ray) cannot be a corner of A at a point where a(p) = b(p): there b - a has its minimum and
// the slopes agree. So such a switch is no point of continuity of the computed A (two
// record ends of one front ordered by their double parameters, a sliver between them
// realised by neither): not classified, never called a kink.
bool thrown_by_the_other(ExactBurning& eb, const Slopes& d, const WindowPropagation::JunctionSwitch& sw) {
  const WindowStore& s = eb.propagation().store();
  if (d.corner == kUndecided || s.windows[sw.left].triangle != s.windows[sw.right].triangle) return false;
  return starts_on_front(eb, sw.left, sw.right) || starts_on_front(eb, sw.right, sw.left);
}

std::optional<JunctionPoint::Kind> classify(const Slopes& d, bool same, bool tangent) {
  using K = JunctionPoint::Kind;
  if (d.corner == 1) return K::Kink;
  if (d.corner == -1) {
    // The fronts meet (one running along E into one arriving broadside counts: a' > 0 = b').
    if (d.left >= 0 && d.right <= 0 && d.left != kUndecided && d.right != kUndecided && (d.left == 1 || d.right == -1))
      return K::Quench;
    if (d.left == -1 || d.right == 1) return K::Merge;
    return std::nullopt;
  }
  if (same) return K::Merge;
  if (tangent) return K::Tangent;
  return std::nullopt;
}

}  // namespace

const char* to_string(JunctionPoint::Kind k) {
  switch (k) {
    case JunctionPoint::Kind::Kink: return "kink";
    case JunctionPoint::Kind::Merge: return "merge";
    case JunctionPoint::Kind::Quench: return "quench";
    case JunctionPoint::Kind::Tangent: return "tangent";
  }
  return "?";
}

JunctionPoints junction_points(ExactBurning& eb) {
  JunctionPoints out;
  const MedialComplex& mc = eb.complex();
  const std::vector<WindowPropagation::JunctionSwitch> switches = eb.junction_switches();
  const WindowStore& s = eb.propagation().store();
  Certifier& cert = eb.certifier();
  const long max_bits = 512;
  for (const auto& sw : switches) {
    const Slopes d = certified_slopes(cert, mc, s, sw, max_bits);
    // At a vertex: one pseudo-source's front continued from one edge's triangle into the
    // other's (equal slopes): not a switch.
    if (sw.edge2 != kNoIndex && d.corner == kUndecided && s.windows[sw.left].pseudo == s.windows[sw.right].pseudo)
      continue;
    const bool same = d.corner == kUndecided && same_front(cert, mc, sw);
    // One front through one sheet side, split between two windows by the mesh: BT runs on
    // smoothly and no front meets another there.
    if (same && s.windows[sw.left].triangle == s.windows[sw.right].triangle) continue;
    std::optional<JunctionPoint::Kind> kind = classify(d, same, !same && tangent(eb, d, sw));
    if (kind && *kind != JunctionPoint::Kind::Tangent && thrown_by_the_other(eb, d, sw)) kind.reset();
    if (!kind) {
      ++out.unclassified;
      continue;
    }
    JunctionPoint p;
    p.kind = *kind;
    p.edge = sw.edge, p.edge_point = sw.point, p.left = sw.left, p.right = sw.right;
    const EdgePoint& ep = s.edge_points[sw.point];
    const ExactPoint3 &a = mc.vertex(mc.edge(sw.edge).v[0]).exact, &b = mc.vertex(mc.edge(sw.edge).v[1]).exact;
    const Interval l = ep.exact >= 0 ? s.exact_times[ep.exact].approx() : ep.lambda;
    const mpq_class* ac[3] = {&a.x, &a.y, &a.z};
    const mpq_class* bc[3] = {&b.x, &b.y, &b.z};
    if (ep.exact >= 0) {
      p.lambda = s.exact_times[ep.exact];
      std::array<ExactSum, 3> x;
      for (int i = 0; i < 3; ++i) {
        x[i] = *p.lambda;
        x[i].scale(*bc[i] - *ac[i]);
        x[i] += ExactSum::rational(*ac[i]);
        x[i].simplify();
      }
      p.exact_x = x;
    }
    if (const ExactSum* bt = cert.exact_expr(sw.time)) p.exact_bt = *bt;
    for (int i = 0; i < 3; ++i) {
      const Interval ai = enclose(*ac[i]), bi = enclose(*bc[i]);
      const Interval c = p.exact_x ? (*p.exact_x)[i].approx() : ai + l * (bi - ai);
      p.x[i] = c.mid();
      p.error = std::max(p.error, round_up(std::max(c.hi - p.x[i], p.x[i] - c.lo)));
    }
    const Interval bt = p.exact_bt ? p.exact_bt->approx() : s.times[sw.time].value;
    p.bt = bt.mid();
    p.error = std::max(p.error, round_up(std::max(bt.hi - p.bt, p.bt - bt.lo)));
    std::vector<JunctionPoint>* lists[] = {&out.kinks, &out.merges, &out.quenches, &out.tangents};
    lists[static_cast<int>(p.kind)]->push_back(std::move(p));
  }
  return out;
}

}  // namespace grassfire
