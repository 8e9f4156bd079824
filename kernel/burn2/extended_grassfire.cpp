// extended_grassfire.cpp -- the arrival-ordered event simulation (Exact variant), over
// the stops of the graph; the fronts inside chains are in chain_fronts.cpp, the
// Dissertation variant in dissertation_thinning.cpp.
#include "burn2/extended_grassfire.h"

#include <algorithm>
#include <queue>
#include <stdexcept>
#include <string>

#include "burn2/chain_fronts.h"
#include "burn2/ema.h"
#include "medial2/medial_chains.h"

namespace grassfire {

GrassfireResult dissertation_thinning(const MedialGraph& g);  // dissertation_thinning.cpp

namespace {

constexpr std::uint32_t kIgnition = 0xffffffffu;  // edge field of an ignition event

// A front reaching stop `node` along chain end `end` (its edge `edge`) at `time`, or the
// ignition of a leaf.
struct Arrival {
  Interval value;
  TimeId time;
  std::uint32_t node;
  std::uint32_t edge;
  std::uint32_t end;
};

// The event simulation runs over the stops (leaves, junctions, isolated nodes) and treats
// every chain of degree-2 nodes as one edge (medial2/medial_chains.h): a degree-2 node
// burns at its first arrival and passes the fire on, so nothing inside a chain changes
// the order of events at stops; chain_fronts.h fills in the chains afterwards.
class EventSimulation {
 public:
  explicit EventSimulation(const MedialGraph& g)
      : g_(g), chains_(medial_chains(g)), result_(g), fronts_(g, chains_, result_), queue_(Later{this}),
        arrived_(g.node_count(), 0), end_arrived_(2 * std::size_t{chains_.count()}, 0),
        sent_(2 * std::size_t{chains_.count()}, kNoTime), sent_rank_(2 * std::size_t{chains_.count()}) {
    result_.variant = GrassfireVariant::Exact;
    result_.burn.assign(g.node_count(), kNoTime);
    result_.fire.assign(g.edge_count(), EdgeFire{});
  }

  GrassfireResult run() {
    for (std::uint32_t v = 0; v < g_.node_count(); ++v)
      if (g_.degree(v) <= 1) push(result_.times.ignition(v), v, kIgnition, 0);
    // Every pop retires one pushed event; at most one ignition per node and one
    // arrival per chain end are ever pushed.
    const std::uint64_t bound = std::uint64_t{g_.node_count()} + 2ull * chains_.count();
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
    for (std::uint32_t c = 0; c < chains_.count(); ++c)
      fronts_.resolve(c, &sent_[2 * c], &sent_rank_[2 * c], quenches_, chain_quench_events_);
    place_chain_quenches_in_time_order();
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

  void push(TimeId t, std::uint32_t node, std::uint32_t edge, std::uint32_t end) {
    queue_.push({result_.times.approx(t), t, node, edge, end});
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
    fire_into(chains_.end_at(z, edge), a.time, EventRank{true, z, kIgnition});
  }

  void arrive(const Arrival& a) {
    const std::uint32_t j = a.node;
    if (sent_[a.end] != kNoTime) return;  // j already sent fire into this chain: the fronts quench in it
    if (g_.degree(j) == 1)
      throw std::logic_error("extended grassfire: a front reaches leaf " + std::to_string(j) +
                             " before it ignites; R is not 1-Lipschitz along edge " + std::to_string(a.edge));
    end_arrived_[a.end] = 1;
    const std::uint32_t count = ++arrived_[j];
    if (count + 1 < g_.degree(j)) {
      result_.events.push_back({BurnEventType::Annihilate, a.value, node_point(j), a.time});
      return;
    }
    result_.burn[j] = a.time;
    fire_into(remaining_end(j), a.time, EventRank{false, j, a.edge});
  }

  // The one chain end at stop j along which no front has arrived.
  std::uint32_t remaining_end(std::uint32_t j) const {
    std::uint32_t found = kIgnition;
    g_.for_each_incident(j, [&](std::uint32_t e) {
      const std::uint32_t end = chains_.end_at(j, e);
      if (!end_arrived_[end]) found = end;
    });
    if (found == kIgnition) throw std::logic_error("extended grassfire: node without a remaining edge");
    return found;
  }

  // Stop `end`'s node sends fire into its chain at t. The front runs to the other stop
  // unless that stop already sent fire into the chain (then they quench inside it).
  void fire_into(std::uint32_t end, TimeId t, EventRank rank) {
    sent_[end] = t;
    sent_rank_[end] = rank;
    const std::uint32_t other = end ^ 1u;
    if (sent_[other] != kNoTime) return;
    const TimeId arrival = fronts_.run(end, t);
    const std::uint32_t c = end >> 1;
    const std::uint32_t last = other & 1 ? chains_.edge(c, chains_.length(c)) : chains_.edge(c, 1);
    push(arrival, chains_.stop(other), last, other);
  }

  // The quenches inside chains are found after the event loop: insert each into the log
  // after every event that is not later (certified comparisons; the log is in time order).
  void place_chain_quenches_in_time_order() {
    std::vector<BurnEvent>& ev = result_.events;
    for (const BurnEvent& q : chain_quench_events_) {
      const GraphSum when = event_time(result_, q);
      auto not_later = [&](const BurnEvent& e) {
        if (e.time.hi < q.time.lo) return true;
        if (q.time.hi < e.time.lo) return false;
        NumberStats st;
        const bool not_later = compare(event_time(result_, e), when, g_, &st) <= 0;
        result_.times.count(st);
        return not_later;
      };
      std::size_t lo = 0, hi = ev.size();
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (not_later(ev[mid]))
          lo = mid + 1;
        else
          hi = mid;
      }
      ev.insert(ev.begin() + static_cast<std::ptrdiff_t>(lo), q);
    }
  }

  static GraphPoint node_point(std::uint32_t v) {
    GraphPoint p;
    p.node = v;
    return p;
  }

  const MedialGraph& g_;
  const MedialChains chains_;
  GrassfireResult result_;
  ChainFronts fronts_;
  std::priority_queue<Arrival, std::vector<Arrival>, Later> queue_;
  std::vector<std::uint32_t> arrived_;
  std::vector<std::uint8_t> end_arrived_;  // per chain end: a front arrived at its stop
  std::vector<TimeId> sent_;               // per chain end: when its stop sent fire into the chain
  std::vector<EventRank> sent_rank_;       // the queue rank of the event that made it send
  std::vector<QuenchRecord> quenches_;
  std::vector<BurnEvent> chain_quench_events_;
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
