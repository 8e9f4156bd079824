// dissertation_thinning.cpp -- the discrete algorithm of 3.3.2, kept for reproduction.
//
// "At each iteration, the degree-1 node i with the smallest value is removed with its
// incident arc. If the removal exposes a new degree-1 node j, then its value is the
// value of i plus the weight of arc {i, j}. Iteration terminates when the graph is
// reduced to either a single node or a set of cycles, which are output as the EMA."
// The leaf order is by the leaf's own value, not by the arrival time at its neighbour,
// which is where it departs from the definition (see extended_grassfire.h).
// Comparisons are certified as in the Exact variant; ties go to the smaller node id.
// Complexity: O((n + m) log n).
#include <queue>
#include <stdexcept>
#include <string>

#include "burn2/ema.h"
#include "burn2/extended_grassfire.h"

namespace grassfire {

GrassfireResult dissertation_thinning(const MedialGraph& g) {
  GrassfireResult result(g);
  result.variant = GrassfireVariant::Dissertation;
  result.burn.assign(g.node_count(), kNoTime);
  result.fire.assign(g.edge_count(), EdgeFire{});
  BurnTimes& times = result.times;

  struct Leaf {
    TimeId value;
    std::uint32_t node;
  };
  auto later = [&times](const Leaf& a, const Leaf& b) {
    const int c = times.compare(a.value, b.value);
    return c != 0 ? c > 0 : a.node > b.node;
  };
  std::priority_queue<Leaf, std::vector<Leaf>, decltype(later)> leaves(later);
  std::vector<std::uint32_t> degree(g.node_count());
  std::vector<bool> edge_removed(g.edge_count(), false), node_removed(g.node_count(), false);
  std::vector<QuenchRecord> quenches;

  auto last_node = [&](std::uint32_t v) {
    GraphPoint p;
    p.node = v;
    quenches.push_back({p, times.approx(result.burn[v])});
  };
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    degree[v] = g.degree(v);
    if (degree[v] > 1) continue;
    result.burn[v] = times.ignition(v);
    if (degree[v] == 0)
      last_node(v);
    else
      leaves.push({result.burn[v], v});
  }
  std::uint64_t steps = 0;
  while (!leaves.empty()) {
    if (++steps > g.node_count()) throw std::logic_error("dissertation thinning: step bound exceeded");
    const Leaf leaf = leaves.top();
    leaves.pop();
    const std::uint32_t i = leaf.node;
    if (node_removed[i] || degree[i] != 1) continue;
    node_removed[i] = true;
    std::uint32_t edge = 0;
    g.for_each_incident(i, [&](std::uint32_t e) {
      if (!edge_removed[e]) edge = e;
    });
    edge_removed[edge] = true;
    degree[i] = 0;
    const std::uint32_t j = g.other_end(edge, i);
    (g.edge(edge).u == i ? result.fire[edge].from_u : result.fire[edge].from_v) = leaf.value;
    --degree[j];
    if (degree[j] == 1) {
      result.burn[j] = times.advance(leaf.value, edge);
      leaves.push({result.burn[j], j});
    } else if (degree[j] == 0) {
      node_removed[j] = true;  // the graph is reduced to the single node j
      last_node(j);
    }
  }
  assign_extended_medial_axis(g, result, quenches);
  return result;
}

}  // namespace grassfire
