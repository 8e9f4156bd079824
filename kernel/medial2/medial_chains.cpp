// medial_chains.cpp -- see medial_chains.h.
#include "medial2/medial_chains.h"

#include <stdexcept>

namespace grassfire {

MedialChains medial_chains(const MedialGraph& g) {
  MedialChains out;
  out.chain_of_edge.assign(g.edge_count(), MedialChains::kNone);
  out.node_begin.push_back(0);
  out.edge_begin.push_back(0);
  std::uint64_t steps = 0;
  for (std::uint32_t s = 0; s < g.node_count(); ++s) {
    if (g.degree(s) == 2) continue;
    g.for_each_incident(s, [&](std::uint32_t first) {
      if (out.chain_of_edge[first] != MedialChains::kNone) return;
      const std::uint32_t c = out.count();
      std::uint32_t at = s, e = first;
      out.nodes.push_back(s);
      while (true) {
        // Every edge is walked once, in one chain.
        if (++steps > g.edge_count()) throw std::logic_error("medial chains: walk exceeded the edge count");
        out.chain_of_edge[e] = c;
        out.edges.push_back(e);
        at = g.other_end(e, at);
        out.nodes.push_back(at);
        if (g.degree(at) != 2) break;
        std::uint32_t next = e;
        g.for_each_incident(at, [&](std::uint32_t f) {
          if (f != e) next = f;
        });
        e = next;
      }
      out.node_begin.push_back(static_cast<std::uint32_t>(out.nodes.size()));
      out.edge_begin.push_back(static_cast<std::uint32_t>(out.edges.size()));
    });
  }
  return out;
}

}  // namespace grassfire
