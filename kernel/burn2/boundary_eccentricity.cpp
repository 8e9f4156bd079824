// boundary_eccentricity.cpp -- see boundary_eccentricity.h.
#include "burn2/boundary_eccentricity.h"

#include <stdexcept>

namespace grassfire {

GraphSum AxisEccentricity::exact(std::uint32_t node) const {
  GraphSum sum;
  std::uint32_t v = node;
  for (std::size_t steps = 0; parent_edge[v] != kNoSample; ++steps) {
    if (steps > graph->edge_count()) throw std::logic_error("distance to the EMA: a cycle of parent edges");
    sum.add_length(parent_edge[v]);
    v = graph->other_end(parent_edge[v], v);
  }
  return sum + source_offset[v];
}

AxisEccentricity distance_to_ema(const MedialGraph& g, const GrassfireResult& burning) {
  AxisEccentricity out;
  out.graph = &g;
  out.node.assign(g.node_count(), Interval::infinity());
  out.parent_edge.assign(g.node_count(), kNoSample);
  out.source_offset.assign(g.node_count(), GraphSum());
  std::vector<bool> edge_used(g.edge_count(), false), reached(g.node_count(), false);
  std::vector<std::uint32_t> queue;
  auto source = [&](std::uint32_t v, const Interval& e, const GraphSum& exact) {
    out.node[v] = e;
    out.source_offset[v] = exact;
    reached[v] = true;
    queue.push_back(v);
  };
  for (const ExtendedMedialAxis& ema : burning.ema) {
    if (ema.kind == ExtendedMedialAxis::Kind::Cycles) {
      for (std::uint32_t e : ema.edges) edge_used[e] = true;
      for (std::uint32_t v : ema.nodes) source(v, Interval(0.0), GraphSum());
    } else if (ema.point.at_node) {
      source(ema.point.node, Interval(0.0), GraphSum());
    } else {
      // offset from `from` = (w + T_other - T_from) / 2 (extended_grassfire.h).
      const std::uint32_t e = ema.point.edge, from = ema.point.from, other = g.other_end(e, from);
      GraphSum offset = burning.times.as_graph_sum(ema.sent_other) - burning.times.as_graph_sum(ema.sent_from);
      offset.add_length(e).divide(2);
      GraphSum rest;
      rest.add_length(e);
      rest -= offset;
      edge_used[e] = true;
      source(from, ema.point.offset, offset);
      source(other, g.edge(e).length - ema.point.offset, rest);
    }
  }
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const std::uint32_t v = queue[i];
    g.for_each_incident(v, [&](std::uint32_t e) {
      const std::uint32_t w = g.other_end(e, v);
      if (edge_used[e] || reached[w]) return;
      edge_used[e] = reached[w] = true;
      out.node[w] = out.node[v] + g.edge(e).length;
      out.parent_edge[w] = e;
      queue.push_back(w);
    });
  }
  return out;
}

BoundaryEccentricity boundary_eccentricity(const MedialGraph& g, const GrassfireResult& burning,
                                           const AxisEccentricity& e, const ClosestPoints& cp) {
  if (cp.ring_samples.empty()) throw std::invalid_argument("boundary eccentricity needs a sampled axis");
  BoundaryEccentricity out;
  std::vector<std::vector<std::vector<std::uint32_t>>> closest_to(cp.ring_samples.size());
  for (std::size_t r = 0; r < cp.ring_samples.size(); ++r) {
    closest_to[r].resize(cp.ring_samples[r]);
    out.value.emplace_back(cp.ring_samples[r], Interval::infinity());
    out.argmin.emplace_back(cp.ring_samples[r], kNoSample);
  }
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    for (const BoundaryPoint& p : cp.node[v]) closest_to[p.ring][p.sample].push_back(v);
  // The EMA inside an edge minimises BE for the edge's two generators.
  for (const ExtendedMedialAxis& ema : burning.ema) {
    if (ema.kind != ExtendedMedialAxis::Kind::Point || ema.point.at_node) continue;
    const std::uint32_t from = ema.point.from, to = g.other_end(ema.point.edge, from);
    const Interval t = ema.point.offset / g.edge(ema.point.edge).length;
    const double err = std::max(g.node(from).position_error, g.node(to).position_error);
    const Point2 a = g.node(from).position, b = g.node(to).position;
    const Interval x = Interval(a.x) + t * (Interval(b.x) - Interval(a.x)) + Interval(-err, err);
    const Interval y = Interval(a.y) + t * (Interval(b.y) - Interval(a.y)) + Interval(-err, err);
    for (int k = 0; k < 2; ++k) {
      const BoundaryPoint& p = cp.edge[ema.point.edge][k];
      out.value[p.ring][p.sample] = sqrt(square(x - p.position.x) + square(y - p.position.y));
      out.argmin[p.ring][p.sample] = kEmaPoint;
    }
  }
  NumberStats stats;
  for (std::size_t r = 0; r < closest_to.size(); ++r)
    for (std::size_t k = 0; k < closest_to[r].size(); ++k) {
      if (out.argmin[r][k] == kEmaPoint) continue;
      std::uint32_t& best = out.argmin[r][k];
      for (std::uint32_t v : closest_to[r][k]) {
        if (e.node[v].is_infinite()) continue;
        const Interval value = e.node[v] + g.node(v).radius;
        if (best != kNoSample) {
          const Interval& held = out.value[r][k];
          if (value.lo > held.hi) continue;
          if (!(value.hi < held.lo)) {  // overlapping enclosures: compare exactly
            GraphSum candidate = e.exact(v), incumbent = e.exact(best);
            candidate.add_radius(v);
            incumbent.add_radius(best);
            if (compare(candidate, incumbent, g, &stats) >= 0) continue;
          }
        }
        best = v;
        out.value[r][k] = value;
      }
      out.samples_without_medial_point += out.argmin[r][k] == kNoSample;
    }
  return out;
}

}  // namespace grassfire
