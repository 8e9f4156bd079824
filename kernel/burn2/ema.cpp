// ema.cpp -- see ema.h.
#include "burn2/ema.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace grassfire {

void assign_extended_medial_axis(const MedialGraph& g, GrassfireResult& result,
                                 const std::vector<QuenchRecord>& quenches) {
  const std::vector<std::uint32_t> component = g.component_of_nodes();
  std::uint32_t components = 0;
  for (std::uint32_t c : component) components = std::max(components, c + 1);
  result.ema.assign(components, ExtendedMedialAxis{});
  std::vector<std::uint32_t> quench_count(components, 0);
  for (std::uint32_t c = 0; c < components; ++c) result.ema[c].component = c;

  // A graph with C components has at least V - C edges, exactly V - C when it is a
  // forest, and a forest's 2-core is empty: the peeling is skipped (sampled axes are trees).
  const bool forest = std::uint64_t{g.edge_count()} + components == g.node_count();
  if (!forest) {
    const TwoCore core = two_core(g);
    for (std::uint32_t v = 0; v < g.node_count(); ++v) {
      if (!core.node_in_core[v]) continue;
      ExtendedMedialAxis& ema = result.ema[component[v]];
      ema.kind = ExtendedMedialAxis::Kind::Cycles;
      ema.nodes.push_back(v);
      ema.edf = Interval::infinity();
    }
    for (std::uint32_t e = 0; e < g.edge_count(); ++e)
      if (core.edge_in_core[e]) result.ema[component[g.edge(e).u]].edges.push_back(e);
  }

  for (const QuenchRecord& q : quenches) {
    const std::uint32_t node = q.place.at_node ? q.place.node : g.edge(q.place.edge).u;
    ExtendedMedialAxis& ema = result.ema[component[node]];
    if (ema.kind == ExtendedMedialAxis::Kind::Cycles)
      throw std::logic_error("extended medial axis: a quench in component " + std::to_string(component[node]) +
                             ", which has cycles");
    ema.point = q.place;
    ema.edf = q.edf;
    ema.sent_from = q.sent_from;
    ema.sent_other = q.sent_other;
    ++quench_count[component[node]];
  }
  for (std::uint32_t c = 0; c < components; ++c) {
    if (result.ema[c].kind == ExtendedMedialAxis::Kind::Point && quench_count[c] != 1)
      throw std::logic_error("extended medial axis: tree component " + std::to_string(c) + " has " +
                             std::to_string(quench_count[c]) + " quench points instead of one");
  }
}

}  // namespace grassfire
