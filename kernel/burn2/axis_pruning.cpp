// axis_pruning.cpp -- see axis_pruning.h.
#include "burn2/axis_pruning.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>

#include "number/ball.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

// ---- certified signs ---------------------------------------------------------------------

Ball ball_of(const ExactSum& x) {
  const long bits = BallPrecision::bits();
  mpfr_t lo, hi;
  mpfr_init2(lo, bits);
  mpfr_init2(hi, bits);
  x.enclose(lo, hi);
  Ball b;
  arb_set_interval_mpfr(b.get(), lo, hi, bits);
  mpfr_clear(lo);
  mpfr_clear(hi);
  return b;
}

struct Product {
  mpq_class coef;
  ExactSum x, y;
};

class Signs {
 public:
  int exact(const ExactSum& x) { return sign(x, &stats_); }

  // Sign of sum coef x y: exactly when no factor has certified constants, else by balls.
  int products(const std::vector<Product>& terms) {
    const bool constants = std::any_of(terms.begin(), terms.end(), [](const Product& p) {
      return !p.x.constant_terms().empty() || !p.y.constant_terms().empty();
    });
    if (!constants) {
      ExactSum sum;
      for (const Product& p : terms) sum += multiply(p.x, p.y).scale(p.coef);
      return sign(sum, &stats_);
    }
    return balls([&] {
      Ball sum(0.0);
      for (const Product& p : terms) sum += ball_of(ExactSum::rational(p.coef)) * ball_of(p.x) * ball_of(p.y);
      return sum;
    });
  }

  // Sign by balls at doubling precision; a value no precision separates from 0 is an
  // (uncertified) tie.
  int balls(const std::function<Ball()>& f) {
    for (long bits = 64; bits <= kMaxBits; bits *= 2) {
      BallPrecision guard(bits);
      const int s = f().sign();
      if (s != kUndecided) return s;
    }
    ++uncertified_;
    return 0;
  }

  std::uint64_t uncertified() const { return uncertified_; }

 private:
  NumberStats stats_;
  std::uint64_t uncertified_ = 0;
};

// ---- one edge: its linear pieces and the kept stretches ------------------------------------

enum class BoundKind { U, V, Quench, Cut };
struct Bound {
  BoundKind kind;
  Interval s;  // distance from the edge's u
};
struct Stretch {
  Bound lo, hi;
};

// The EDF on a piece [p0, p1] of an edge is a + sigma s, with a = T_u (sigma = +1, fire
// from u) or T_v + w (sigma = -1); the piece ends are u (s = 0), the quench point or v.
enum class Origin { U, V };
enum class Place { Zero, Quench, Length };
struct Piece {
  Origin origin;
  int sigma;
  Bound p0, p1;
  Place s0, s1;
};

class EdgePruner {
 public:
  EdgePruner(const MedialGraph& g, const GrassfireResult& b, const PruningThresholds& t, Signs& signs)
      : g_(g), b_(b), t_(t), signs_(signs), keep_(1 - t.tubularity) {}

  // Kept stretches of edge e, from u to v; an edge of infinite EDF is kept whole.
  std::vector<Stretch> stretches(std::uint32_t e) {
    load(e);
    std::vector<Stretch> out;
    if (!tu_id_ && !tv_id_) return {{{BoundKind::U, Interval(0.0)}, {BoundKind::V, iw_}}};
    for (const Piece& p : pieces()) {
      std::optional<Stretch> k = kept(p);
      if (!k) continue;
      if (!out.empty() && out.back().hi.kind == BoundKind::Quench && k->lo.kind == BoundKind::Quench)
        out.back().hi = k->hi;
      else
        out.push_back(*k);
    }
    for (Stretch& st : out)  // a stretch cannot end at the quench point (the EDF is continuous)
      for (Bound* bd : {&st.lo, &st.hi})
        if (bd->kind == BoundKind::Quench) bd->kind = BoundKind::Cut;
    return out;
  }

  // EDF and linear R at distance s from u on edge e (for cut points).
  void values_at(std::uint32_t e, const Interval& s, Interval& edf, Interval& r) {
    load(e);
    edf = Interval::infinity();
    if (tu_id_) edf = itu_ + s;
    if (tv_id_) {
      const Interval other = itv_ + iw_ - s;
      edf = edf.is_infinite() ? other : Interval(std::fmin(edf.lo, other.lo), std::fmin(edf.hi, other.hi));
    }
    r = iru_ + idr_ * (s / iw_);
  }

 private:
  void load(std::uint32_t e) {
    e_ = e;
    u_ = g_.edge(e).u;
    v_ = g_.edge(e).v;
    iw_ = g_.edge(e).length;
    iru_ = g_.node(u_).radius;
    idr_ = g_.node(v_).radius - iru_;
    const EdgeFire& f = b_.fire[e];
    tu_id_ = f.from_u == kNoTime ? std::nullopt : std::optional<TimeId>(f.from_u);
    tv_id_ = f.from_v == kNoTime ? std::nullopt : std::optional<TimeId>(f.from_v);
    if (tu_id_) itu_ = b_.times.approx(*tu_id_);
    if (tv_id_) itv_ = b_.times.approx(*tv_id_);
    w_.reset(), ru_.reset(), dr_.reset(), tu_.reset(), tv_.reset();
  }

  // Exact values, built only when an enclosure does not decide.
  template <class F>
  const ExactSum& cached(std::optional<ExactSum>& slot, F&& make) {
    if (!slot) slot = make();
    return *slot;
  }
  const ExactSum& w() { return cached(w_, [&] { return g_.geometry().exact_length(e_); }); }
  const ExactSum& ru() { return cached(ru_, [&] { return g_.geometry().exact_radius(u_); }); }
  const ExactSum& dr() { return cached(dr_, [&] { return g_.geometry().exact_radius(v_) - ru(); }); }
  const ExactSum& tu() { return cached(tu_, [&] { return b_.times.exact(*tu_id_); }); }
  const ExactSum& tv() { return cached(tv_, [&] { return b_.times.exact(*tv_id_); }); }

  Interval a_approx(const Piece& p) const { return p.origin == Origin::U ? itu_ : itv_ + iw_; }
  ExactSum a_exact(const Piece& p) { return p.origin == Origin::U ? tu() : tv() + w(); }
  Interval s_approx(Place s) const {
    if (s == Place::Zero) return Interval(0.0);
    return s == Place::Length ? iw_ : half(iw_ + itv_ - itu_);
  }
  ExactSum s_exact(Place s) {
    if (s == Place::Zero) return ExactSum();
    if (s == Place::Length) return w();
    ExactSum q = w() + tv() - tu();  // the quench point (w + T_v - T_u) / 2
    return q.scale(mpq_class(1, 2));
  }

  std::vector<Piece> pieces() const {
    const Bound bu{BoundKind::U, Interval(0.0)}, bv{BoundKind::V, iw_};
    if (tu_id_ && !tv_id_) return {{Origin::U, +1, bu, bv, Place::Zero, Place::Length}};
    if (tv_id_ && !tu_id_) return {{Origin::V, -1, bu, bv, Place::Zero, Place::Length}};
    const Bound bq{BoundKind::Quench, s_approx(Place::Quench)};
    return {{Origin::U, +1, bu, bq, Place::Zero, Place::Quench}, {Origin::V, -1, bq, bv, Place::Quench, Place::Length}};
  }

  // The sign of w f(s) for the ET condition, or for the ST one:
  //   ET: w (a + sigma s) - w R_u - dR s - w T;   ST: (1 - S) w (a + sigma s) - w R_u - dR s.
  int condition(const Piece& p, Place s, bool tubularity) {
    const Interval is = s_approx(s), edf = a_approx(p) + Interval(p.sigma) * is;
    if (tubularity && certified_sign(edf) != 1) {  // where the EDF is 0 (a leaf with R = 0), ST is 0
      ExactSum e = s_exact(s);
      if (signs_.exact(a_exact(p) + e.scale(p.sigma)) == 0) return sgn(t_.tubularity) > 0 ? -1 : 0;
    }
    const Interval k = tubularity ? enclose(keep_) : Interval(1.0);
    Interval quick = k * iw_ * edf - iw_ * iru_ - idr_ * is;
    if (!tubularity) quick -= iw_ * enclose(t_.erosion);
    const int q = certified_sign(quick);
    if (q != kUndecided) return q;
    const mpq_class kq = tubularity ? keep_ : mpq_class(1);
    const ExactSum se = s_exact(s);
    std::vector<Product> terms{{kq, w(), a_exact(p)}, {kq * p.sigma, w(), se}, {-1, w(), ru()}, {-1, dr(), se}};
    if (!tubularity) terms.push_back({-t_.erosion, w(), ExactSum::rational(1)});
    return signs_.products(terms);
  }

  // The crossing of a condition inside the piece: s = -A / B for w f(s) = A + B s.
  Interval crossing(const Piece& p, bool tubularity) const {
    const Interval k = tubularity ? enclose(keep_) : Interval(1.0);
    const Interval a = a_approx(p), ru = iru_, dr = idr_;
    Interval big_a = k * iw_ * a - iw_ * ru;
    if (!tubularity) big_a -= iw_ * enclose(t_.erosion);
    const Interval big_b = k * Interval(p.sigma) * iw_ - dr;
    const Interval c = -big_a / big_b;
    return {std::fmax(c.lo, p.p0.s.lo), std::fmin(c.hi, p.p1.s.hi)};
  }

  // The passing set of one condition on the piece, as [lo, hi] or nothing.
  std::optional<Stretch> passing(const Piece& p, bool tubularity) {
    const int f0 = condition(p, p.s0, tubularity), f1 = condition(p, p.s1, tubularity);
    if (f0 >= 0 && f1 >= 0) return Stretch{p.p0, p.p1};
    if (f0 > 0 && f1 < 0) return Stretch{p.p0, {BoundKind::Cut, crossing(p, tubularity)}};
    if (f0 < 0 && f1 > 0) return Stretch{{BoundKind::Cut, crossing(p, tubularity)}, p.p1};
    return std::nullopt;  // failing, or passing at a single end point
  }

  std::optional<Stretch> kept(const Piece& p) {
    const std::optional<Stretch> et = passing(p, false);
    if (!et) return std::nullopt;
    const std::optional<Stretch> st = passing(p, true);
    if (!st) return std::nullopt;
    Stretch s;
    s.lo = et->lo.kind == BoundKind::Cut ? et->lo : st->lo;
    if (et->lo.kind == BoundKind::Cut && st->lo.kind == BoundKind::Cut)
      s.lo.s = Interval(std::fmax(et->lo.s.lo, st->lo.s.lo), std::fmax(et->lo.s.hi, st->lo.s.hi));
    s.hi = et->hi.kind == BoundKind::Cut ? et->hi : st->hi;
    if (et->hi.kind == BoundKind::Cut && st->hi.kind == BoundKind::Cut)
      s.hi.s = Interval(std::fmin(et->hi.s.lo, st->hi.s.lo), std::fmin(et->hi.s.hi, st->hi.s.hi));
    // A lower cut from one condition and an upper cut from the other: empty unless they are
    // in order, which the other condition decides at the lower cut.
    if (s.lo.kind == BoundKind::Cut && s.hi.kind == BoundKind::Cut && (et->lo.kind == BoundKind::Cut) !=
                                                                          (et->hi.kind == BoundKind::Cut)) {
      const bool lower_is_et = et->lo.kind == BoundKind::Cut;
      if (!ordered(p, lower_is_et)) return std::nullopt;
    }
    return s;
  }

  // w f(s) = A + B s for one condition, as balls at the current precision.
  void coefficients(const Piece& p, bool tubularity, Ball& a, Ball& b) const {
    const Ball k = tubularity ? ball_of(ExactSum::rational(keep_)) : Ball(1.0);
    const Ball w = ball_of(w_.value()), ru = ball_of(ru_.value()), dr = ball_of(dr_.value());
    a = k * w * ball_of(p.origin == Origin::U ? tu_.value() : tv_.value() + w_.value()) - w * ru;
    if (!tubularity) a -= w * ball_of(ExactSum::rational(t_.erosion));
    b = k * Ball(static_cast<double>(p.sigma)) * w - dr;
  }

  // With w f1 = A1 + B1 s rising (B1 > 0) and w f2 = A2 + B2 s falling, both cuts inside:
  // the stretch is nonempty iff f2 >= 0 at f1's root -A1 / B1, i.e. A2 B1 - B2 A1 > 0
  // (0, a single point, counts as empty).
  bool ordered(const Piece& p, bool rising_is_et) {
    w(), a_exact(p), dr();  // build the exact values the balls are taken from
    return signs_.balls([&] {
             Ball a_et, b_et, a_st, b_st;
             coefficients(p, false, a_et, b_et);
             coefficients(p, true, a_st, b_st);
             const Ball &a1 = rising_is_et ? a_et : a_st, &b1 = rising_is_et ? b_et : b_st;
             const Ball &a2 = rising_is_et ? a_st : a_et, &b2 = rising_is_et ? b_st : b_et;
             return a2 * b1 - b2 * a1;
           }) > 0;
  }

  const MedialGraph& g_;
  const GrassfireResult& b_;
  const PruningThresholds& t_;
  Signs& signs_;
  mpq_class keep_;  // 1 - S
  std::uint32_t e_ = 0, u_ = 0, v_ = 0;
  Interval iw_, iru_, idr_, itu_, itv_;
  std::optional<TimeId> tu_id_, tv_id_;
  std::optional<ExactSum> w_, ru_, dr_, tu_, tv_;
};

}  // namespace

namespace {

// ET >= T and ST >= S at a node, with the node's own EDF.
bool node_passes(const MedialGraph& g, const GrassfireResult& b, const PruningThresholds& t, std::uint32_t v,
                 Signs& signs) {
  if (b.is_infinite(v)) return t.tubularity <= 1;
  const Interval edf = b.edf(v), r = g.node(v).radius;
  auto decided = [&](const Interval& quick, const std::function<ExactSum()>& exact) {
    const int s = certified_sign(quick);
    return s != kUndecided ? s : signs.exact(exact());
  };
  const int et = decided(edf - r - enclose(t.erosion),
                         [&] { return b.times.exact(b.burn[v]) - g.geometry().exact_radius(v) -
                                      ExactSum::rational(t.erosion); });
  if (et < 0) return false;
  if (decided(edf, [&] { return b.times.exact(b.burn[v]); }) == 0) return t.tubularity <= 0;  // ST = 0
  const mpq_class keep = 1 - t.tubularity;
  return decided(enclose(keep) * edf - r, [&] {
           ExactSum e = b.times.exact(b.burn[v]);
           return e.scale(keep) - g.geometry().exact_radius(v);
         }) >= 0;
}

class Assembler {
 public:
  Assembler(const MedialGraph& g, const GrassfireResult& b, EdgePruner& pruner)
      : g_(g), b_(b), pruner_(pruner), index_(g.node_count(), kCutPoint) {}

  std::uint32_t original(std::uint32_t v) {
    if (index_[v] == kCutPoint) {
      index_[v] = add(g_.node(v).position, g_.node(v).radius, b_.edf(v));
      out_.nodes.back().source_node = v;
    }
    return index_[v];
  }

  std::uint32_t cut(std::uint32_t e, const Interval& s) {
    Interval edf, r;
    pruner_.values_at(e, s, edf, r);
    const std::uint32_t id = add(g_.geometry().point_along(g_, e, g_.edge(e).u, s.mid()), r, edf);
    out_.nodes.back().source_edge = e;
    out_.nodes.back().offset = s;
    ++out_.cut_points;
    return id;
  }

  void stretch(std::uint32_t e, const Bound& lo, const Bound& hi) {
    const std::uint32_t a = lo.kind == BoundKind::U ? original(g_.edge(e).u) : cut(e, lo.s);
    const std::uint32_t c = hi.kind == BoundKind::V ? original(g_.edge(e).v) : cut(e, hi.s);
    const Interval length = hi.s - lo.s;
    out_.edges.push_back({a, c, e, lo.s, hi.s, {std::fmax(0.0, length.lo), length.hi}, g_.edge(e).kind});
  }

  PrunedAxis take() { return std::move(out_); }

 private:
  std::uint32_t add(const Point2& p, const Interval& r, const Interval& edf) {
    PrunedNode n;
    n.position = p;
    n.radius = r;
    n.edf = edf;
    n.erosion = edf.is_infinite() ? edf : edf - r;
    n.tubularity = edf.is_infinite() ? Interval(1.0) : edf.lo > 0 ? Interval(1.0) - r / edf : Interval(0.0);
    out_.nodes.push_back(n);
    return static_cast<std::uint32_t>(out_.nodes.size() - 1);
  }

  const MedialGraph& g_;
  const GrassfireResult& b_;
  EdgePruner& pruner_;
  std::vector<std::uint32_t> index_;
  PrunedAxis out_;
};

// The thinning of 3.3.2 stopped by the thresholds (see the header).
void peel(const MedialGraph& g, const GrassfireResult& b, const std::vector<bool>& passes,
          const std::vector<std::vector<Stretch>>& kept, Assembler& out) {
  std::vector<bool> alive(g.node_count(), true), edge_alive(g.edge_count(), true);
  std::vector<std::uint32_t> degree(g.node_count());
  std::vector<Stretch> extent(g.edge_count());
  std::vector<std::uint32_t> queue;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    extent[e] = {{BoundKind::U, Interval(0.0)}, {BoundKind::V, g.edge(e).length}};
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    degree[v] = g.degree(v);
    if (degree[v] == 1 && !passes[v]) queue.push_back(v);
  }
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const std::uint32_t v = queue[i];
    if (degree[v] != 1) continue;
    std::uint32_t e = 0;
    g.for_each_incident(v, [&](std::uint32_t f) {
      if (edge_alive[f]) e = f;
    });
    alive[v] = false;
    if (!kept[e].empty()) {  // cut back to the first passing point seen from v
      if (g.edge(e).u == v)
        extent[e].lo = kept[e].front().lo;
      else
        extent[e].hi = kept[e].back().hi;
      continue;
    }
    edge_alive[e] = false;
    const std::uint32_t w = g.other_end(e, v);
    if (--degree[w] == 1 && !passes[w]) queue.push_back(w);
  }
  // A tree component without passing points shrinks to its EMA.
  std::vector<bool> has_kept(g.node_count(), false);
  const std::vector<std::uint32_t> component = g.component_of_nodes();
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (passes[v]) has_kept[component[v]] = true;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (!kept[e].empty()) has_kept[component[g.edge(e).u]] = true;
  for (const ExtendedMedialAxis& ema : b.ema) {
    if (has_kept[ema.component] || ema.kind != ExtendedMedialAxis::Kind::Point) continue;
    if (ema.point.at_node) {
      out.original(ema.point.node);
    } else {
      const MedialEdge& e = g.edge(ema.point.edge);
      out.cut(ema.point.edge, ema.point.from == e.u ? ema.point.offset : e.length - ema.point.offset);
    }
  }
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (alive[v] && has_kept[component[v]]) out.original(v);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (edge_alive[e] && has_kept[component[g.edge(e).u]]) out.stretch(e, extent[e].lo, extent[e].hi);
}

}  // namespace

PrunedAxis prune_axis(const MedialGraph& g, const GrassfireResult& burning, const PruningThresholds& t) {
  if (t.tubularity < 0 || t.tubularity > 1) throw std::invalid_argument("pruning: the ST threshold must be in [0, 1]");
  Signs signs;
  EdgePruner pruner(g, burning, t, signs);
  std::vector<bool> passes(g.node_count());
  std::uint64_t passing = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) passing += passes[v] = node_passes(g, burning, t, v, signs);
  std::vector<std::vector<Stretch>> kept(g.edge_count());
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) kept[e] = pruner.stretches(e);
  Assembler out(g, burning, pruner);
  if (t.topology) {
    peel(g, burning, passes, kept, out);
  } else {
    for (std::uint32_t v = 0; v < g.node_count(); ++v)
      if (passes[v]) out.original(v);
    for (std::uint32_t e = 0; e < g.edge_count(); ++e)
      for (const Stretch& s : kept[e]) out.stretch(e, s.lo, s.hi);
  }
  PrunedAxis result = out.take();
  result.passing_nodes = passing;
  result.uncertified = signs.uncertified();
  return result;
}

}  // namespace grassfire
