// extended_grassfire.cpp -- the arrival-ordered event simulation (Exact variant).
// The Dissertation variant lives in dissertation_thinning.cpp.
#include "burn2/extended_grassfire.h"

#include <algorithm>
#include <queue>
#include <stdexcept>
#include <string>

#include "burn2/ema.h"

namespace grassfire {

GrassfireResult dissertation_thinning(const MedialGraph& g);  // dissertation_thinning.cpp

namespace {

constexpr std::uint32_t kIgnition = 0xffffffffu;  // edge field of an ignition event

// A front reaching `node` along `edge` at `time`, or the ignition of a leaf.
struct Arrival {
  Interval value;
  TimeId time;
  std::uint32_t node;
  std::uint32_t edge;
};

class EventSimulation {
 public:
  explicit EventSimulation(const MedialGraph& g)
      : g_(g), result_(g), queue_(Later{this}), arrived_(g.node_count(), 0), edge_arrived_(g.edge_count(), 0),
        pending_(g.edge_count(), kNoTime) {
    result_.variant = GrassfireVariant::Exact;
    result_.burn.assign(g.node_count(), kNoTime);
    result_.fire.assign(g.edge_count(), EdgeFire{});
  }

  GrassfireResult run() {
    for (std::uint32_t v = 0; v < g_.node_count(); ++v)
      if (g_.degree(v) <= 1) push(result_.times.ignition(v), v, kIgnition);
    // Every pop retires one pushed event; at most one ignition per node and one
    // arrival per edge end are ever pushed.
    const std::uint64_t bound = std::uint64_t{g_.node_count()} + 2ull * g_.edge_count();
    std::uint64_t steps = 0;
    while (!queue_.empty()) {
      if (++steps > bound) throw std::logic_error("extended grassfire: event bound exceeded");
      const Arrival a = queue_.top();
      queue_.pop();
      if (a.edge == kIgnition)
        ignite(a);
      else
        arrive(a);
    }
    place_edge_quenches_in_time_order();
    assign_extended_medial_axis(g_, result_, quenches_);
    return std::move(result_);
  }

 private:
  // Orders the queue: certified time, then ignition before arrival, then node, then edge.
  struct Later {
    const EventSimulation* sim;
    bool operator()(const Arrival& a, const Arrival& b) const {
      int c;
      if (a.value.hi < b.value.lo || b.value.hi < a.value.lo) {
        c = a.value.hi < b.value.lo ? -1 : 1;
        sim->result_.times.count_filter_decision();
      } else {
        c = sim->result_.times.compare(a.time, b.time);
        if (c == 0 && a.time != b.time) ++sim->ties_;
      }
      if (c != 0) return c > 0;
      const bool ai = a.edge == kIgnition, bi = b.edge == kIgnition;
      if (ai != bi) return bi;
      if (a.node != b.node) return a.node > b.node;
      return a.edge > b.edge;
    }
  };

  void push(TimeId t, std::uint32_t node, std::uint32_t edge) {
    queue_.push({result_.times.approx(t), t, node, edge});
  }

  void ignite(const Arrival& a) {
    const std::uint32_t z = a.node;
    result_.burn[z] = a.time;
    result_.events.push_back({BurnEventType::Ignite, a.value, node_point(z), a.time});
    if (g_.degree(z) == 0) {
      quenches_.push_back({node_point(z), a.value});
      result_.events.push_back({BurnEventType::Quench, a.value, node_point(z), a.time});
      return;
    }
    std::uint32_t edge = 0;
    g_.for_each_incident(z, [&](std::uint32_t e) { edge = e; });
    fire_into(z, edge, a.time);
  }

  void arrive(const Arrival& a) {
    const std::uint32_t j = a.node, e = a.edge;
    if (sent_from(e, j) != kNoTime) return;  // j already sent fire into e: the fronts quenched
    if (g_.degree(j) == 1)
      throw std::logic_error("extended grassfire: a front reaches leaf " + std::to_string(j) +
                             " before it ignites; R is not 1-Lipschitz along edge " + std::to_string(e));
    edge_arrived_[e] |= (g_.edge(e).u == j) ? 1 : 2;
    const std::uint32_t count = ++arrived_[j];
    if (count + 1 < g_.degree(j)) {
      result_.events.push_back({BurnEventType::Annihilate, a.value, node_point(j), a.time});
      return;
    }
    result_.burn[j] = a.time;
    fire_into(j, remaining_edge(j), a.time);
  }

  // The one incident edge of j along which no front has arrived.
  std::uint32_t remaining_edge(std::uint32_t j) const {
    std::uint32_t found = kIgnition;
    g_.for_each_incident(j, [&](std::uint32_t e) {
      const std::uint8_t bit = (g_.edge(e).u == j) ? 1 : 2;
      if (!(edge_arrived_[e] & bit)) found = e;
    });
    if (found == kIgnition) throw std::logic_error("extended grassfire: node without a remaining edge");
    return found;
  }

  TimeId& sent_from(std::uint32_t e, std::uint32_t v) {
    return g_.edge(e).u == v ? result_.fire[e].from_u : result_.fire[e].from_v;
  }

  void fire_into(std::uint32_t j, std::uint32_t e, TimeId t) {
    sent_from(e, j) = t;
    const std::uint32_t k = g_.other_end(e, j);
    const TimeId from_k = sent_from(e, k);
    if (from_k == kNoTime) {
      pending_[e] = result_.times.advance(t, e);
      push(pending_[e], k, e);
      return;
    }
    quench_in_edge(e, k, from_k, j, t);
  }

  // Fronts from k (sent at tk) and j (sent at tj >= tk) meet on edge e, at distance
  // (w + tj - tk) / 2 from k; exactly at j when tj equals the arrival tk + w.
  void quench_in_edge(std::uint32_t e, std::uint32_t k, TimeId tk, std::uint32_t j, TimeId tj) {
    const BurnTimes& times = result_.times;
    const Interval w = g_.edge(e).length;
    const Interval value = half(times.approx(tk) + times.approx(tj) + w);
    GraphPoint place;
    TimeId sent_from = kNoTime, sent_other = kNoTime;
    if (times.compare(tj, pending_[e]) == 0) {
      place = node_point(j);
    } else {
      sent_from = tk;
      sent_other = tj;
      place.at_node = false;
      place.edge = e;
      place.from = k;
      place.offset = half(w + times.approx(tj) - times.approx(tk));
    }
    quenches_.push_back({place, value, sent_from, sent_other});
    result_.events.push_back({BurnEventType::Quench, value, place, place.at_node ? tj : kNoTime});
  }

  // A quench inside an edge is logged when the second front enters the edge, but happens
  // later, when the fronts meet: move it forward past every event that is not later
  // (certified comparisons; at equal times the quench comes last).
  void place_edge_quenches_in_time_order() {
    std::vector<BurnEvent>& ev = result_.events;
    for (std::size_t i = ev.size(); i-- > 0;) {
      if (ev[i].type != BurnEventType::Quench || ev[i].place.at_node) continue;
      const GraphSum when = event_time(result_, ev[i]);
      std::size_t k = i;
      while (k + 1 < ev.size() && !(ev[i].time.hi < ev[k + 1].time.lo) &&
             compare(event_time(result_, ev[k + 1]), when, g_) <= 0)
        ++k;
      std::rotate(ev.begin() + i, ev.begin() + i + 1, ev.begin() + k + 1);
    }
  }

  static GraphPoint node_point(std::uint32_t v) {
    GraphPoint p;
    p.node = v;
    return p;
  }

  const MedialGraph& g_;
  GrassfireResult result_;
  std::priority_queue<Arrival, std::vector<Arrival>, Later> queue_;
  std::vector<std::uint32_t> arrived_;
  std::vector<std::uint8_t> edge_arrived_;  // bit 1: arrived at u, bit 2: arrived at v
  std::vector<TimeId> pending_;             // time of the front travelling along each edge
  std::vector<QuenchRecord> quenches_;
  mutable std::uint64_t ties_ = 0;

 public:
  std::uint64_t ties() const { return ties_; }
};

}  // namespace

const char* to_string(GrassfireVariant v) {
  return v == GrassfireVariant::Exact ? "exact" : "dissertation";
}

const char* to_string(BurnEventType t) {
  switch (t) {
    case BurnEventType::Ignite: return "ignite";
    case BurnEventType::Annihilate: return "annihilate";
    case BurnEventType::Quench: return "quench";
  }
  return "unknown";
}

Interval GrassfireResult::edf(std::uint32_t node) const {
  return burn[node] == kNoTime ? Interval::infinity() : times.approx(burn[node]);
}

Interval GrassfireResult::edf_along(std::uint32_t edge, std::uint32_t from, double s) const {
  const MedialGraph& g = times.graph();
  const MedialEdge& e = g.edge(edge);
  const bool from_is_u = e.u == from;
  const TimeId t_from = from_is_u ? fire[edge].from_u : fire[edge].from_v;
  const TimeId t_to = from_is_u ? fire[edge].from_v : fire[edge].from_u;
  Interval best = Interval::infinity();
  if (t_from != kNoTime) best = times.approx(t_from) + Interval(s);
  if (t_to != kNoTime) {
    const Interval other = times.approx(t_to) + (e.length - Interval(s));
    best = best.is_infinite() ? other : Interval(std::fmin(best.lo, other.lo), std::fmin(best.hi, other.hi));
  }
  return best;
}

GraphSum event_time(const GrassfireResult& r, const BurnEvent& e) {
  if (e.time_id != kNoTime) return r.times.as_graph_sum(e.time_id);
  const EdgeFire& f = r.fire[e.place.edge];
  GraphSum s = r.times.as_graph_sum(f.from_u) + r.times.as_graph_sum(f.from_v);
  s.add_length(e.place.edge);
  return s.divide(2);
}

Point2 position_of(const MedialGraph& g, const GraphPoint& p) {
  if (p.at_node) return g.node(p.node).position;
  return g.geometry().point_along(g, p.edge, p.from, p.offset.mid());
}

GrassfireResult extended_grassfire(const MedialGraph& g, GrassfireVariant variant) {
  if (variant == GrassfireVariant::Dissertation) return dissertation_thinning(g);
  EventSimulation sim(g);
  GrassfireResult result = sim.run();
  result.queue_ties = sim.ties();
  return result;
}

}  // namespace grassfire
