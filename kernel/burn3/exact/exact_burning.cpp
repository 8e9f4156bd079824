// exact_burning.cpp -- see exact_burning.h.
#include "burn3/exact/exact_burning.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "burn3/exact/window_values.h"
#include "geometry3/exact_predicates3.h"
#include "number/sqrt_field.h"

namespace grassfire {

ExactBurning::ExactBurning(const MedialComplex& mc, const ExactBurningOptions& o)
    : mc_(mc), unfolding_(std::make_unique<Unfolding>(mc)), prop_(std::make_unique<WindowPropagation>(*unfolding_, o)) {}

ExactBurning::~ExactBurning() = default;

void ExactBurning::add_point_source(std::uint32_t triangle, const ExactPoint3& point, const mpq_class& start) {
  prop_->add_point_source(triangle, point, start);
}
void ExactBurning::add_point_source(const ComplexPoint& x, const mpq_class& start) {
  switch (x.kind) {
    case ComplexPoint::Kind::Vertex:
      if (mc_.vertex_triangles(x.id).empty())
        prop_->add_vertex_source(x.id, start);
      else
        add_point_source(mc_.vertex_triangles(x.id).front(), x.point, start);
      return;
    case ComplexPoint::Kind::Edge:
      if (mc_.edge_triangles(x.id).empty())
        throw std::invalid_argument("a point source inside a segment (edge " + std::to_string(x.id) +
                                    ") is not supported by the exact engine");
      add_point_source(mc_.edge_triangles(x.id).front(), x.point, start);
      return;
    case ComplexPoint::Kind::Triangle:
      add_point_source(x.id, x.point, start);
      return;
  }
}

void ExactBurning::add_border_ignition() { prop_->add_border_ignition(); }

void ExactBurning::run() {
  prop_->run();
  index_windows();
}

void ExactBurning::index_windows() {
  const auto& ws = prop_->store().windows;
  first_.assign(mc_.triangle_count() + 1, 0);
  auto live = [](const Window& w) { return !w.dead(); };
  for (const Window& w : ws)
    if (live(w)) ++first_[w.triangle + 1];
  for (std::size_t t = 0; t < mc_.triangle_count(); ++t) first_[t + 1] += first_[t];
  list_.assign(first_.back(), 0);
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::uint32_t i = 0; i < ws.size(); ++i)
    if (live(ws[i])) list_[fill[ws[i].triangle]++] = i;
}

std::vector<std::uint32_t> ExactBurning::triangle_windows(std::uint32_t t) const {
  return {list_.begin() + first_[t], list_.begin() + first_[t + 1]};
}

// +1: x in the closed wedge; 0: outside; -1: undecided by every stage (then *widen gets
// twice the certified distance from x to the undecided rays).
int ExactBurning::membership(std::uint32_t w, const Target& x, double* widen) {
  const Window& win = prop_->store().windows[w];
  if (win.root()) return 1;
  Certifier& cert = prop_->certifier();
  const IPoint p = ipoint(cert.target_disc(win.triangle, x));
  bool undecided = false;
  for (int j = 0; j < 2; ++j) {
    const Interval s = window_side(win, ipoint(win.image[j]), p);
    const int want = j == 0 ? 1 : -1;  // inside: side(B0) >= 0, side(B1) <= 0
    int sg = certified_sign(s);
    if (sg == kUndecided) {
      const std::uint64_t before = cert.counts.uncertified;
      sg = cert.side(w, j, x);
      if (cert.counts.uncertified != before) {
        --cert.counts.uncertified;  // a query, not a propagation decision: widen instead
        const Interval lever = win.plane() ? Interval(1.0) - Interval(win.source.r)
                                           : sqrt(square(ipoint(win.image[j]).x - ipoint(win.source).x) +
                                                  square(ipoint(win.image[j]).y - ipoint(win.source).y));
        *widen += 2 * round_up(std::max(-s.lo, s.hi) / lever.lo);
        undecided = true;
        continue;
      }
    }
    if (sg == -want) return 0;
  }
  return undecided ? -1 : 1;
}

Interval ExactBurning::burn_time(std::uint32_t t, const Target& x) {
  const double inf = std::numeric_limits<double>::infinity();
  ++queries_.queries;
  Interval best(inf, inf);
  Certifier& cert = prop_->certifier();
  for (std::uint32_t i = first_[t]; i < first_[t + 1]; ++i) {
    const std::uint32_t w = list_[i];
    ++queries_.candidates;
    double widen = 0.0;
    const int m = membership(w, x, &widen);
    if (m == 0) continue;
    if (m < 0) ++queries_.widened;
    Interval tw = cert.time_interval(w, x);
    if (!std::isfinite(tw.hi - tw.lo)) {  // the double stage could not bound it (a sliver): Arb
      BallPrecision guard(128);
      tw = cert.time_ball(w, x).to_interval();
    }
    best = {std::min(best.lo, tw.lo), std::min(best.hi, round_up(tw.hi + widen))};
  }
  return best;
}

std::optional<ExactSum> ExactBurning::exact_burn_time(std::uint32_t t, const ExactPoint3& x) {
  Certifier& cert = prop_->certifier();
  const Target at{kNoIndex, &x};
  std::optional<ExactSum> best;
  for (std::uint32_t i = first_[t]; i < first_[t + 1]; ++i) {
    const std::uint32_t w = list_[i];
    const Window& win = prop_->store().windows[w];
    if (!win.root()) {
      const Interval s0 = window_side(win, ipoint(win.image[0]), ipoint(cert.target_disc(t, at)));
      const Interval s1 = window_side(win, ipoint(win.image[1]), ipoint(cert.target_disc(t, at)));
      if (s0.hi < 0 || s1.lo > 0) continue;  // certainly outside
    }
    if (!cert.exact_window(w)) return std::nullopt;
    if (!win.root() && (cert.side(w, 0, at) < 0 || cert.side(w, 1, at) > 0)) continue;
    std::optional<ExactSum> v = cert.exact_time(w, at);
    if (!v) return std::nullopt;
    if (!best || exact_sign(*v - *best) < 0) best = std::move(v);
  }
  return best;
}

Interval ExactBurning::vertex_burn_time(std::uint32_t v) {
  const double inf = std::numeric_limits<double>::infinity();
  if (prop_->is_link_rule_vertex(v)) {
    const std::uint32_t t = prop_->link_burn_time(v);
    return t == kNoIndex ? Interval::infinity() : prop_->store().times[t].value;
  }
  Interval best(inf, inf);
  for (std::uint32_t t : mc_.vertex_triangles(v)) {
    const Interval b = burn_time(t, Target{v, nullptr});
    best = {std::min(best.lo, b.lo), std::min(best.hi, b.hi)};
  }
  return best;
}

Interval ExactBurning::segment_burn_time(std::uint32_t e, const mpq_class& s) {
  if (mc_.edge(e).stratum != EdgeStratum::Dangling) throw std::invalid_argument("segment_burn_time: not a segment");
  const Interval len = sqrt(enclose(prop_->certifier().edge_length2(e)));
  Interval best = Interval::infinity();
  for (int j = 0; j < 2; ++j) {
    const Interval end = vertex_burn_time(mc_.edge(e).v[j]);
    if (end.is_infinite()) continue;
    const Interval t = end + len * enclose(j == 0 ? s : mpq_class(1 - s));
    best = best.is_infinite() ? t : Interval(std::min(best.lo, t.lo), std::min(best.hi, t.hi));
  }
  return best;
}

Interval ExactBurning::edge_burn_time(std::uint32_t e, const ExactPoint3& x) {
  std::vector<Interval> sides;
  for (std::uint32_t t : mc_.edge_triangles(e)) sides.push_back(burn_time(t, x));
  if (sides.empty()) throw std::invalid_argument("edge_burn_time: edge " + std::to_string(e) + " has no triangle");
  // The j-th smallest of enclosures: lower ends and upper ends sorted separately.
  const std::size_t j = mc_.edge(e).stratum == EdgeStratum::Singular && !prop_->walls() ? sides.size() - 2 : 0;
  std::vector<double> lo, hi;
  for (const Interval& i : sides) lo.push_back(i.lo), hi.push_back(i.hi);
  std::nth_element(lo.begin(), lo.begin() + j, lo.end());
  std::nth_element(hi.begin(), hi.begin() + j, hi.end());
  return {lo[j], hi[j]};
}

Interval ExactBurning::burn_time(const ComplexPoint& x) {
  switch (x.kind) {
    case ComplexPoint::Kind::Vertex:
      return vertex_burn_time(x.id);
    case ComplexPoint::Kind::Edge:
      if (mc_.edge(x.id).stratum == EdgeStratum::Dangling) return segment_burn_time(x.id, x.parameter);
      return edge_burn_time(x.id, x.point);
    case ComplexPoint::Kind::Triangle:
      break;
  }
  return burn_time(x.id, x.point);
}

std::optional<std::string> exact_engine_unsupported(const MedialComplex&) {
  // Singular edges follow the junction rule (edge_junction.cpp) and singular points the
  // link rule (vertex_burning.cpp) since the junction rule (docs/exact-engine.md): every validated complex is burned. What
  // stays unsupported is per source, not per complex: a point source inside a segment.
  return std::nullopt;
}

std::vector<Interval> ExactBurning::vertex_burn_times() {
  std::vector<Interval> r(mc_.vertex_count());
  for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) r[v] = vertex_burn_time(v);
  return r;
}

}  // namespace grassfire
