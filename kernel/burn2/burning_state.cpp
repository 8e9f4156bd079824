// burning_state.cpp -- see burning_state.h.
#include "burn2/burning_state.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace grassfire {

namespace {

class StateBuilder {
 public:
  StateBuilder(const MedialGraph& g, const GrassfireResult& r, double t)
      : g_(g), r_(r), t_(t), t_exact_(ExactSum::rational(mpq_class(t))) {}

  BurningState build() {
    BurningState s;
    s.time = t_;
    s.edges.resize(g_.edge_count());
    for (std::uint32_t e = 0; e < g_.edge_count(); ++e) burn_edge(e, s);
    s.node_burnt.assign(g_.node_count(), false);
    for (std::uint32_t v = 0; v < g_.node_count(); ++v) {
      const TimeId tv = r_.burn[v];
      s.node_burnt[v] = tv != kNoTime && reached(r_.times.approx(tv), [&] { return r_.times.exact(tv); });
    }
    collect_events(s);
    return s;
  }

 private:
  // Certified: is the value enclosed by `approx` (exactly `exact()`) at most t?
  template <class Exact>
  bool reached(const Interval& approx, Exact&& exact) const {
    if (approx.hi <= t_) return true;
    if (approx.lo > t_) return false;
    return sign(exact() - t_exact_, &stats_) <= 0;
  }

  bool reached_time(TimeId id) const {
    return reached(r_.times.approx(id), [&] { return r_.times.exact(id); });
  }
  // Fire sent at `sent` arrives at the other end of `e`.
  bool reached_arrival(TimeId sent, std::uint32_t e) const {
    return reached(r_.times.approx(sent) + g_.edge(e).length,
                   [&] { return r_.times.exact(sent) + g_.geometry().exact_length(e); });
  }
  bool reached_quench(TimeId tu, TimeId tv, std::uint32_t e) const {
    return reached(half(r_.times.approx(tu) + r_.times.approx(tv) + g_.edge(e).length),
                   [&] { return quench_time(tu, tv, e); });
  }
  ExactSum quench_time(TimeId tu, TimeId tv, std::uint32_t e) const {
    ExactSum q = r_.times.exact(tu) + r_.times.exact(tv) + g_.geometry().exact_length(e);
    return q.scale(mpq_class(1, 2));
  }

  // t - sent, which is known to lie in [0, length(e)].
  Interval offset(TimeId sent, std::uint32_t e) const {
    const Interval d = Interval(t_) - r_.times.approx(sent);
    return {std::max(0.0, d.lo), std::min(g_.edge(e).length.hi, d.hi)};
  }

  void add_front(BurningState& s, std::uint32_t e, std::uint32_t from, TimeId sent, Interval& burnt) const {
    burnt = offset(sent, e);
    s.fronts.push_back({e, from, sent, burnt});
  }

  void burn_edge(std::uint32_t e, BurningState& s) const {
    const MedialEdge& edge = g_.edge(e);
    const EdgeFire& f = r_.fire[e];
    EdgeBurning& b = s.edges[e];
    const bool su = f.from_u != kNoTime, sv = f.from_v != kNoTime;
    if (!su && !sv) return;  // the 2-core: never burns
    // Both ends sent: the fronts quench inside; one end sent: its front runs to the other end.
    const bool done = su && sv ? reached_quench(f.from_u, f.from_v, e) : reached_arrival(su ? f.from_u : f.from_v, e);
    if (done) {
      b.whole = true;
      b.from_u = edge.length;
      return;
    }
    if (su && reached_time(f.from_u)) add_front(s, e, edge.u, f.from_u, b.from_u);
    if (sv && reached_time(f.from_v)) add_front(s, e, edge.v, f.from_v, b.from_v);
  }

  // Exact arrival times of fronts at j, earliest first (see the header).
  const std::vector<ExactSum>& arrivals_at(std::uint32_t j) const {
    auto it = arrivals_.find(j);
    if (it != arrivals_.end()) return it->second;
    std::vector<ExactSum> times;
    std::vector<Interval> approx;
    g_.for_each_incident(j, [&](std::uint32_t e) {
      const EdgeFire& f = r_.fire[e];
      const bool j_is_u = g_.edge(e).u == j;
      const TimeId mine = j_is_u ? f.from_u : f.from_v, theirs = j_is_u ? f.from_v : f.from_u;
      if (mine != kNoTime || theirs == kNoTime) return;
      times.push_back(r_.times.exact(theirs) + g_.geometry().exact_length(e));
      approx.push_back(r_.times.approx(theirs) + g_.edge(e).length);
    });
    std::vector<std::size_t> order(times.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (approx[a].hi < approx[b].lo) return true;
      if (approx[b].hi < approx[a].lo) return false;
      return sign(times[a] - times[b], &stats_) < 0;
    });
    std::vector<ExactSum> sorted;
    for (std::size_t i : order) sorted.push_back(times[i]);
    return arrivals_.emplace(j, std::move(sorted)).first->second;
  }

  ExactSum exact_event_time(const BurnEvent& ev, std::uint32_t annihilation_rank) const {
    const GraphPoint& p = ev.place;
    if (ev.type == BurnEventType::Annihilate) {
      const std::vector<ExactSum>& a = arrivals_at(p.node);
      if (annihilation_rank >= a.size()) throw std::logic_error("burning state: annihilation without an arrival");
      return a[annihilation_rank];
    }
    if (p.at_node) return r_.times.exact(r_.burn[p.node]);
    const EdgeFire& f = r_.fire[p.edge];
    return quench_time(f.from_u, f.from_v, p.edge);
  }

  void collect_events(BurningState& s) const {
    std::unordered_map<std::uint32_t, std::uint32_t> annihilations;  // per node, seen so far
    for (std::size_t i = 0; i < r_.events.size(); ++i) {
      const BurnEvent& ev = r_.events[i];
      std::uint32_t rank = 0;
      if (ev.type == BurnEventType::Annihilate) rank = annihilations[ev.place.node]++;
      if (reached(ev.time, [&] { return exact_event_time(ev, rank); })) s.events.push_back(i);
    }
  }

  const MedialGraph& g_;
  const GrassfireResult& r_;
  double t_;
  ExactSum t_exact_;
  mutable NumberStats stats_;
  mutable std::unordered_map<std::uint32_t, std::vector<ExactSum>> arrivals_;
};

}  // namespace

Interval BurningState::burnt_length(const MedialGraph& g) const {
  Interval total(0.0);
  for (std::uint32_t e = 0; e < edges.size(); ++e)
    total += edges[e].whole ? g.edge(e).length : edges[e].from_u + edges[e].from_v;
  return total;
}

BurningState burning_state_at(const MedialGraph& g, const GrassfireResult& burning, double t) {
  if (burning.variant != GrassfireVariant::Exact)
    throw std::invalid_argument("burning state: needs the exact variant's event log, got the " +
                                std::string(to_string(burning.variant)) + " variant");
  if (burning.burn.size() != g.node_count() || burning.fire.size() != g.edge_count())
    throw std::invalid_argument("burning state: the burning was computed on another graph");
  if (!std::isfinite(t)) throw std::invalid_argument("burning state: the time must be finite");
  return StateBuilder(g, burning, t).build();
}

}  // namespace grassfire
