// edf_definition.cpp -- see edf_definition.h.
#include "burn2/edf_definition.h"

#include <algorithm>
#include <stdexcept>

#include "burn2/graph_sum.h"

namespace grassfire {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// The largest reach over one branch at a node: d(x, leaf) + R(leaf), or infinity.
struct Reach {
  bool infinite = false;
  bool found = false;
  std::uint32_t leaf = kNone;
  Interval approx;
  GraphSum value;
};

class Oracle {
 public:
  explicit Oracle(const MedialGraph& g)
      : g_(g), core_(two_core(g)), parent_edge_(g.node_count(), kNone), stamp_(g.node_count(), kNone),
        distance_(g.node_count()) {}

  DefinitionalEdf run() {
    DefinitionalEdf out;
    out.edf.assign(g_.node_count(), std::nullopt);
    branch_reach_.assign(g_.node_count(), {});
    for (std::uint32_t x = 0; x < g_.node_count(); ++x) {
      if (core_.node_in_core[x]) continue;
      explore_branches(x);
      node_edf_.push_back(edf_at(x));
    }
    // node_edf_ was filled for non-core nodes in order; spread it out.
    std::uint32_t k = 0;
    std::vector<std::optional<GraphSum>> by_node(g_.node_count());
    for (std::uint32_t x = 0; x < g_.node_count(); ++x)
      if (!core_.node_in_core[x]) by_node[x] = node_edf_[k++];
    out.edf = by_node;
    out.branches.assign(g_.node_count(), {});
    for (std::uint32_t x = 0; x < g_.node_count(); ++x)
      for (const auto& [e, r] : branch_reach_[x])
        out.branches[x].push_back({e, r.infinite ? std::nullopt : std::optional<GraphSum>(r.value)});
    extended_medial_axis(by_node, out);
    out.stats = stats_;
    return out;
  }

 private:
  // Fills branch_reach_[x]: one Reach per incident edge, in incidence order.
  void explore_branches(std::uint32_t x) {
    std::vector<std::pair<std::uint32_t, Reach>>& reaches = branch_reach_[x];
    g_.for_each_incident(x, [&](std::uint32_t e0) { reaches.push_back({e0, explore(x, e0)}); });
  }

  Reach explore(std::uint32_t x, std::uint32_t e0) {
    Reach best;
    const std::uint32_t start = g_.other_end(e0, x);
    stamp_[x] = x;
    parent_edge_[x] = kNone;
    std::vector<std::uint32_t> stack{start};
    stamp_[start] = x;
    parent_edge_[start] = e0;
    distance_[start] = g_.edge(e0).length;
    const std::uint64_t bound = g_.node_count() + 1;
    std::uint64_t steps = 0;
    while (!stack.empty()) {
      if (++steps > bound) throw std::logic_error("oracle: branch walk exceeded the node count");
      const std::uint32_t y = stack.back();
      stack.pop_back();
      if (core_.node_in_core[y]) {
        best.infinite = true;
        continue;
      }
      if (g_.degree(y) == 1) consider_leaf(x, y, best);
      g_.for_each_incident(y, [&](std::uint32_t e) {
        const std::uint32_t z = g_.other_end(e, y);
        if (stamp_[z] == x) return;
        stamp_[z] = x;
        parent_edge_[z] = e;
        distance_[z] = distance_[y] + g_.edge(e).length;
        stack.push_back(z);
      });
    }
    return best;
  }

  void consider_leaf(std::uint32_t x, std::uint32_t y, Reach& best) {
    const Interval value = distance_[y] + g_.node(y).radius;
    if (!best.found || best.approx.hi < value.lo) {
      take(x, y, value, best);
      return;
    }
    if (value.hi < best.approx.lo) return;
    if (compare(path_value(x, y), best.value, g_, &stats_) > 0) take(x, y, value, best);
  }

  void take(std::uint32_t x, std::uint32_t y, const Interval& value, Reach& best) {
    best.found = true;
    best.leaf = y;
    best.approx = value;
    best.value = path_value(x, y);
  }

  // R(y) plus the lengths of the tree path from x to y of the current exploration.
  GraphSum path_value(std::uint32_t x, std::uint32_t y) const {
    GraphSum s;
    s.add_radius(y);
    for (std::uint32_t v = y; v != x; v = g_.other_end(parent_edge_[v], v)) s.add_length(parent_edge_[v]);
    return s;
  }

  // Largest reach over the branches at x, skipping the branch through edge `skip`.
  // Returns nullopt for an infinite reach; `second` asks for the second largest instead.
  std::optional<GraphSum> ranked_reach(std::uint32_t x, std::uint32_t skip, bool second) {
    std::vector<const Reach*> finite;
    int infinite = 0;
    for (const auto& [e, r] : branch_reach_[x]) {
      if (e == skip) continue;
      if (r.infinite)
        ++infinite;
      else if (r.found)
        finite.push_back(&r);
    }
    std::sort(finite.begin(), finite.end(), [&](const Reach* a, const Reach* b) {
      return compare(a->value, b->value, g_, &stats_) > 0;
    });
    const std::size_t rank = static_cast<std::size_t>(second ? 1 : 0);
    if (infinite > static_cast<int>(rank)) return std::nullopt;
    const std::size_t index = rank - static_cast<std::size_t>(infinite);
    if (index >= finite.size()) throw std::logic_error("oracle: node without enough branches");
    return finite[index]->value;
  }

  std::optional<GraphSum> edf_at(std::uint32_t x) {
    if (g_.degree(x) <= 1) return GraphSum().add_radius(x);
    return ranked_reach(x, kNone, true);
  }

  // A_i: the largest reach at i away from edge e (R(i) when i is a leaf).
  std::optional<GraphSum> away_reach(std::uint32_t i, std::uint32_t e) {
    if (g_.degree(i) == 1) return GraphSum().add_radius(i);
    return ranked_reach(i, e, false);
  }

  void extended_medial_axis(const std::vector<std::optional<GraphSum>>& edf, DefinitionalEdf& out) {
    const std::vector<std::uint32_t> component = g_.component_of_nodes();
    std::uint32_t count = 0;
    for (std::uint32_t c : component) count = std::max(count, c + 1);
    out.ema.assign(count, DefinitionalEma{});
    std::vector<std::optional<GraphSum>> best(count);
    for (std::uint32_t v = 0; v < g_.node_count(); ++v) {
      if (!core_.node_in_core[v]) continue;
      out.ema[component[v]].cycles = true;
      out.ema[component[v]].core_nodes.push_back(v);
    }
    for (std::uint32_t v = 0; v < g_.node_count(); ++v) {
      DefinitionalEma& ema = out.ema[component[v]];
      if (!core_.node_in_core[v]) {
        offer(ema, best[component[v]], *edf[v], [&](DefinitionalEma& m) {
          m.at_node = true;
          m.node = v;
        });
      }
    }
    for (std::uint32_t e = 0; e < g_.edge_count(); ++e) {
      const std::uint32_t i = g_.edge(e).u, j = g_.edge(e).v;
      if (core_.node_in_core[i] || core_.node_in_core[j]) continue;
      const std::optional<GraphSum> ai = away_reach(i, e), aj = away_reach(j, e);
      if (!ai || !aj) continue;  // a branch into the core: the EDF is monotone on e
      GraphSum w = GraphSum().add_length(e);
      // Interior maximum iff |A_i - A_j| < w.
      if (compare(*ai, *aj + w, g_, &stats_) >= 0 || compare(*aj, *ai + w, g_, &stats_) >= 0) continue;
      GraphSum value = *ai + *aj + w;
      value.divide(2);
      GraphSum offset = w + *aj - *ai;
      offset.divide(2);
      offer(out.ema[component[i]], best[component[i]], value, [&](DefinitionalEma& m) {
        m.at_node = false;
        m.edge = e;
        m.from = i;
        m.offset = offset;
      });
    }
    for (std::uint32_t c = 0; c < count; ++c)
      if (!out.ema[c].cycles && best[c]) out.ema[c].edf = *best[c];
  }

  template <class Place>
  void offer(DefinitionalEma& ema, std::optional<GraphSum>& best, const GraphSum& value, Place place) {
    if (ema.cycles) return;
    const int c = best ? compare(value, *best, g_, &stats_) : 1;
    if (c < 0) return;
    if (c == 0) {
      ++ema.maxima;
      return;
    }
    best = value;
    ema.maxima = 1;
    place(ema);
  }

  const MedialGraph& g_;
  TwoCore core_;
  std::vector<std::uint32_t> parent_edge_;
  std::vector<std::uint32_t> stamp_;
  std::vector<Interval> distance_;
  std::vector<std::vector<std::pair<std::uint32_t, Reach>>> branch_reach_;
  std::vector<std::optional<GraphSum>> node_edf_;
  NumberStats stats_;
};

}  // namespace

DefinitionalEdf edf_by_definition(const MedialGraph& g) { return Oracle(g).run(); }

}  // namespace grassfire
