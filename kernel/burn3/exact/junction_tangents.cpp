// junction_tangents.cpp -- tangent handovers at switch points (see junction_tangents.h).
#include "burn3/exact/junction_tangents.h"

#include <algorithm>
#include <array>
#include <vector>

#include "number/sqrt_field.h"

namespace grassfire {

namespace {

using Crossing = std::array<std::uint32_t, 3>;  // edge, triangle entered, triangle left

class Prover {
 public:
  Prover(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t a, std::uint32_t b)
      : u_(u), s_(s), cert_(cert), mc_(u.complex()), a_(a), b_(b) {}

  bool run() {
    const Window& B = s_.windows[b_];
    if (B.plane() || s_.windows[a_].triangle != B.triangle) return false;
    const PseudoSource& pb = s_.pseudo[B.pseudo];
    if (pb.origin == SourceOrigin::Vertex)
      q_ = pb.vertex;
    else if (pb.origin == SourceOrigin::EdgePoint)
      q_ = pb.data | kEdgePointBound;
    else
      return false;
    if (pb.time == kNoIndex) return false;
    carried_b_ = carried(b_, kNoIndex);
    endpoint_ = endpoint_value();
    return proved(pb.time);
  }

 private:
  // The frame changes from `stop` (an ancestor-or-self of w; kNoIndex: the root) down to w,
  // nearest to w first: the unfoldings that carry stop's frame onto w's.
  std::vector<Crossing> crossings(std::uint32_t w, std::uint32_t stop) const {
    std::vector<Crossing> out;
    for (std::uint32_t x = w; x != stop && s_.windows[x].parent != kNoIndex; x = s_.windows[x].parent) {
      const Window& X = s_.windows[x];
      const std::uint32_t from = s_.windows[X.parent].triangle;
      if (!u_.same_frame(from, X.triangle)) out.push_back({X.edge, X.triangle, from});
    }
    return out;
  }
  // Whether the unfolding across c fixes Q (it fixes its edge pointwise: Q on that edge).
  bool fixes_q(const Crossing& c) const {
    if (is_edge_point(q_)) return s_.edge_points[q_ & ~kEdgePointBound].edge == c[0];
    const auto& v = mc_.edge(c[0]).v;
    return v[0] == q_ || v[1] == q_;
  }
  // The unfoldings from stop down to w after those, nearest stop, that fix Q: the image of Q
  // in stop's frame, carried that far, is still Q's vertex (or edge point) image there.
  std::vector<Crossing> carried(std::uint32_t w, std::uint32_t stop) const {
    std::vector<Crossing> c = crossings(w, stop);
    while (!c.empty() && fixes_q(c.back())) c.pop_back();
    return c;
  }
  // b's source image is the image of Q in y's frame carried by the unfoldings from y down to
  // a (y an ancestor-or-self of a, Q imaged in y's frame): equal lists of the unfoldings that
  // move Q start from one triangle (so one frame) and compose to one isometry; with none
  // left, Q is imaged in t's frame on both sides.
  bool same_carriage(std::uint32_t y) const { return carried(a_, y) == carried_b_; }
  // a(S_b) = sqrt(R^2(Q)) when a is a plane wave whose border edge ends at the vertex Q and
  // Q's image in its root's frame is carried to S_b.
  bool endpoint_value() const {
    if (is_edge_point(q_)) return false;
    const PseudoSource& pa = s_.pseudo[s_.windows[a_].pseudo];
    return pa.origin == SourceOrigin::BorderPlane && ends_at(pa.data) && carried(a_, kNoIndex) == carried_b_;
  }
  bool ends_at(std::uint32_t edge) const {
    const auto& v = mc_.edge(edge).v;
    return v[0] == q_ || v[1] == q_;
  }
  bool proved(std::uint32_t e) {
    const TimeExpr& x = s_.times[e];
    if (x.kind == TimeExpr::Kind::Min) return proved(x.a) && proved(x.b);
    if (x.kind == TimeExpr::Kind::WindowAt && x.b == q_ && (window_term(x.a) || crossing_term(x.a))) return true;
    return endpoint_ && equals_r(e);
  }
  // w(Q) = a(S_b): w is of one front with a window y of a's chain in the same frame, or w
  // and y descend from one window z by unfoldings that all fix Q (the fan of windows about
  // Q: then w(Q) = z(Q) = y(Q)); and Q's image in y's frame is carried to S_b.
  bool window_term(std::uint32_t w) {
    const std::uint32_t fw = cert_.front_id(w);
    for (std::uint32_t y = a_; y != kNoIndex; y = s_.windows[y].parent) {
      if (!same_carriage(y)) continue;
      if (cert_.front_id(y) == fw && u_.same_frame(s_.windows[y].triangle, s_.windows[w].triangle)) return true;
      for (std::uint32_t z = w; z != kNoIndex && carried(w, z).empty(); z = s_.windows[z].parent) {
        if (ancestor_or_self(z, y) && carried(y, z).empty()) return true;
        if (sibling_roots_at_q(z, y)) return true;
      }
    }
    return false;
  }
  // At a certified crossing Q of w and w2 (a kink's edge point), w(Q) = w2(Q) by Q's
  // defining equation: w's term is proved when w2's is.
  bool crossing_term(std::uint32_t w) {
    if (!is_edge_point(q_)) return false;
    const auto& eq = s_.edge_points[q_ & ~kEdgePointBound].equal_windows;
    if (eq[0] == kNoIndex || (w != eq[0] && w != eq[1])) return false;
    return window_term(w == eq[0] ? eq[1] : eq[0]);
  }
  // z and y are first windows of one pseudo-source P in triangles that both hold Q: each
  // is sigma + |Q - P| measured in its own triangle's plane, which holds P and Q (a vertex
  // source's triangles hold the vertex, an edge point's the edge), so z(Q) = y(Q).
  bool sibling_roots_at_q(std::uint32_t z, std::uint32_t y) const {
    const Window &Z = s_.windows[z], &Y = s_.windows[y];
    return Z.root() && Y.root() && Z.pseudo == Y.pseudo && holds_q(Z.triangle) && holds_q(Y.triangle);
  }
  bool holds_q(std::uint32_t t) const {
    const ComplexTriangle& tr = mc_.triangle(t);
    for (int k = 0; k < 3; ++k)
      if (is_edge_point(q_) ? tr.e[k] == s_.edge_points[q_ & ~kEdgePointBound].edge : tr.v[k] == q_) return true;
    return false;
  }
  bool ancestor_or_self(std::uint32_t z, std::uint32_t y) const {
    for (; y != kNoIndex; y = s_.windows[y].parent)
      if (y == z) return true;
    return false;
  }
  // Term e is exactly sqrt(R^2(Q)).
  bool equals_r(std::uint32_t e) {
    const TimeExpr& x = s_.times[e];
    const mpq_class& r2 = mc_.vertex(q_).radius_squared;
    if (x.kind == TimeExpr::Kind::WindowAt && x.b == q_) {
      // A plane wave at an end of its border edge, in its root's frame: sqrt(R^2(Q)).
      const PseudoSource& p = s_.pseudo[s_.windows[x.a].pseudo];
      if (p.origin == SourceOrigin::BorderPlane && ends_at(p.data) && carried(x.a, kNoIndex).empty()) return true;
    }
    const ExactSum* v = cert_.exact_expr(e);
    return v && exact_sign(*v - ExactSum::sqrt_of(r2)) == 0;
  }

  const Unfolding& u_;
  const WindowStore& s_;
  Certifier& cert_;
  const MedialComplex& mc_;
  std::uint32_t a_, b_, q_ = kNoIndex;
  std::vector<Crossing> carried_b_;
  bool endpoint_ = false;
};

}  // namespace

bool starts_on_front(ExactBurning& eb, std::uint32_t a, std::uint32_t b) {
  return Prover(eb.unfolding(), eb.propagation().store(), eb.certifier(), a, b).run();
}
bool starts_on_front(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t a, std::uint32_t b) {
  return Prover(u, s, cert, a, b).run();
}

}  // namespace grassfire
