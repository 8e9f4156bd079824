// rate_pruning.cpp -- see rate_pruning.h.
#include "burn2/rate_pruning.h"

#include <array>
#include <map>
#include <memory>
#include <queue>
#include <stdexcept>
#include <string>

#include "number/mpfr_bounds.h"

namespace grassfire {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr long kRefinedBits = 128;

// 128-bit enclosures of pruning times are memoised per record: the second stage of
// comparisons, between the double enclosure and the exact sum.
using Refined = MpfrBounds;

class PruningFronts {
 public:
  explicit PruningFronts(const MedialGraph& g)
      : g_(g), queue_(Later{this}), reached_(g.node_count(), 0), arrived_(g.edge_count(), 0),
        sent_(g.edge_count(), {kNone, kNone}), pruned_(g.node_count(), kNone),
        component_(g.component_of_nodes()) {}

  RatePruning run() {
    for (std::uint32_t v = 0; v < g_.node_count(); ++v)
      if (g_.degree(v) <= 1) queue_.push({start(v), v, kNone});
    const std::uint64_t bound = std::uint64_t{g_.node_count()} + 2ull * g_.edge_count();
    while (!queue_.empty()) {
      if (++out_.events > bound) throw std::logic_error("rate pruning: event bound exceeded");
      const Arrival a = queue_.top();
      queue_.pop();
      if (a.edge == kNone)
        prune_leaf(a);
      else
        arrive(a);
    }
    out_.time.resize(g_.node_count());
    out_.approx.assign(g_.node_count(), Interval::infinity());
    for (std::uint32_t v = 0; v < g_.node_count(); ++v) {
      if (pruned_[v] == kNone) continue;
      out_.time[v] = exact(pruned_[v]);
      out_.approx[v] = records_[pruned_[v]].value;
    }
    for (const auto& [component, quench] : last_) out_.last_quench.push_back(quench);
    return std::move(out_);
  }

 private:
  // A pruning time: 0 at a leaf, or pred + w - R(node) + R(previous node) along `edge`.
  struct Record {
    Interval value;
    std::uint32_t pred, edge, node, origin;
  };
  struct Arrival {
    std::uint32_t time, node, edge;  // edge kNone: a leaf starts
  };
  struct Later {
    const PruningFronts* self;
    bool operator()(const Arrival& a, const Arrival& b) const {
      const int c = self->compare(a.time, b.time);
      if (c != 0) return c > 0;
      if (a.node != b.node) return a.node > b.node;
      return a.edge > b.edge;
    }
  };

  std::uint32_t start(std::uint32_t leaf) {
    records_.push_back({Interval(0.0), kNone, kNone, leaf, leaf});
    return static_cast<std::uint32_t>(records_.size() - 1);
  }

  std::uint32_t advance(std::uint32_t t, std::uint32_t e) {
    const Record& r = records_[t];
    const std::uint32_t j = g_.other_end(e, r.node);
    const Interval value = r.value + g_.edge(e).length - g_.node(j).radius + g_.node(r.node).radius;
    records_.push_back({value, t, e, j, r.origin});
    return static_cast<std::uint32_t>(records_.size() - 1);
  }

  // P = R(origin) - R(node) + the lengths along the chain.
  GraphSum exact(std::uint32_t t) const {
    GraphSum s;
    s.add_radius(records_[t].origin).add_radius(records_[t].node, -1);
    for (std::uint32_t k = t; records_[k].pred != kNone; k = records_[k].pred) s.add_length(records_[k].edge);
    return s;
  }

  int compare(std::uint32_t a, std::uint32_t b) const {
    if (a == b) return 0;
    const Interval &x = records_[a].value, &y = records_[b].value;
    if (x.hi < y.lo) return -1;
    if (y.hi < x.lo) return 1;
    const Refined &ra = refined(a), &rb = refined(b);
    if (mpfr_less_p(ra.hi, rb.lo)) return -1;
    if (mpfr_less_p(rb.hi, ra.lo)) return 1;
    return grassfire::compare(exact(a), exact(b), g_, &out_.stats);
  }

  // pred + w(e) - R(node) + R(previous node), each atom enclosed at 128 bits.
  const Refined& refined(std::uint32_t t) const {
    if (refined_.size() < records_.size()) refined_.resize(records_.size());
    std::vector<std::uint32_t> chain;
    for (std::uint32_t k = t; !refined_[k]; k = records_[k].pred) {
      chain.push_back(k);
      if (records_[k].pred == kNone) break;
    }
    Refined atom(kRefinedBits);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const Record& r = records_[*it];
      auto out = std::make_unique<Refined>(kRefinedBits);
      if (r.pred == kNone) {
        mpfr_set_zero(out->lo, 1);
        mpfr_set_zero(out->hi, 1);
      } else {
        const Refined& p = *refined_[r.pred];
        const std::uint32_t prev = records_[r.pred].node;
        mpfr_set(out->lo, p.lo, MPFR_RNDD);
        mpfr_set(out->hi, p.hi, MPFR_RNDU);
        g_.geometry().enclose_length(r.edge, atom.lo, atom.hi);
        mpfr_add(out->lo, out->lo, atom.lo, MPFR_RNDD);
        mpfr_add(out->hi, out->hi, atom.hi, MPFR_RNDU);
        g_.geometry().enclose_radius(prev, atom.lo, atom.hi);
        mpfr_add(out->lo, out->lo, atom.lo, MPFR_RNDD);
        mpfr_add(out->hi, out->hi, atom.hi, MPFR_RNDU);
        g_.geometry().enclose_radius(r.node, atom.lo, atom.hi);
        mpfr_sub(out->lo, out->lo, atom.hi, MPFR_RNDD);
        mpfr_sub(out->hi, out->hi, atom.lo, MPFR_RNDU);
      }
      refined_[*it] = std::move(out);
    }
    return *refined_[t];
  }

  std::uint32_t& sent(std::uint32_t e, std::uint32_t v) { return g_.edge(e).u == v ? sent_[e][0] : sent_[e][1]; }

  void prune_leaf(const Arrival& a) {
    pruned_[a.node] = a.time;
    if (g_.degree(a.node) == 0) {
      PruningQuench q;
      q.component = component_[a.node];
      q.node = a.node;
      last_[q.component] = q;
      return;
    }
    std::uint32_t edge = kNone;
    g_.for_each_incident(a.node, [&](std::uint32_t e) { edge = e; });
    send(a.node, edge, a.time);
  }

  void arrive(const Arrival& a) {
    const std::uint32_t j = a.node, e = a.edge;
    if (sent(e, j) != kNone) return;  // j pruned first and sent a front into e: they met inside
    if (g_.degree(j) == 1)
      throw std::logic_error("rate pruning: a front reaches leaf " + std::to_string(j) +
                             "; R is not 1-Lipschitz along edge " + std::to_string(e));
    arrived_[e] |= g_.edge(e).u == j ? 1 : 2;
    if (++reached_[j] + 1 < g_.degree(j)) return;  // two or more edges still unreached
    pruned_[j] = a.time;
    std::uint32_t remaining = kNone;
    g_.for_each_incident(j, [&](std::uint32_t f) {
      if (!(arrived_[f] & (g_.edge(f).u == j ? 1 : 2))) remaining = f;
    });
    if (remaining == kNone) throw std::logic_error("rate pruning: a node without a remaining edge");
    send(j, remaining, a.time);
  }

  void send(std::uint32_t i, std::uint32_t e, std::uint32_t t) {
    sent(e, i) = t;
    const std::uint32_t j = g_.other_end(e, i);
    const std::uint32_t from_j = sent(e, j);
    const std::uint32_t arrival = advance(t, e);
    if (from_j == kNone) {
      queue_.push({arrival, j, e});
      return;
    }
    // Fronts from j (sent at from_j) and i (sent at t) meet at (w + P_i + R(i) - P_j - R(j)) / 2
    // from j; exactly at i when i was pruned just as j's front would arrive there.
    PruningQuench q;
    q.component = component_[i];
    if (compare(t, advance(from_j, e)) == 0) {
      q.node = i;
    } else {
      q.at_node = false;
      q.edge = e;
      q.from = j;
      q.offset = exact(t) - exact(from_j);
      q.offset.add_radius(i).add_radius(j, -1).add_length(e).divide(2);
      q.offset_approx = half(records_[t].value - records_[from_j].value + g_.node(i).radius - g_.node(j).radius +
                             g_.edge(e).length);
    }
    last_[q.component] = q;
  }

  const MedialGraph& g_;
  mutable RatePruning out_;
  std::vector<Record> records_;
  std::priority_queue<Arrival, std::vector<Arrival>, Later> queue_;
  std::vector<std::uint32_t> reached_;
  std::vector<std::uint8_t> arrived_;  // bit 1: a front arrived at u, bit 2: at v
  std::vector<std::array<std::uint32_t, 2>> sent_;
  std::vector<std::uint32_t> pruned_;
  std::vector<std::uint32_t> component_;
  std::map<std::uint32_t, PruningQuench> last_;
  mutable std::vector<std::unique_ptr<Refined>> refined_;  // by record, on demand
};

}  // namespace

RatePruning rate_pruning(const MedialGraph& g) { return PruningFronts(g).run(); }

}  // namespace grassfire
