// mutants2d.cpp -- the 2D mutants (see mutants2d.h).
#include "mutants2d.h"

#include <algorithm>

namespace grassfire::checks {
namespace {

TimeId& sent_from(const MedialGraph& g, GrassfireResult& r, std::uint32_t e, std::uint32_t v) {
  return g.edge(e).u == v ? r.fire[e].from_u : r.fire[e].from_v;
}

bool on_ema(const GrassfireResult& r, std::uint32_t v) {
  for (const ExtendedMedialAxis& e : r.ema)
    if (e.kind == ExtendedMedialAxis::Kind::Point && e.point.at_node && e.point.node == v) return true;
  return false;
}

void leaf_late(const MedialGraph& g, GrassfireResult& r) {
  for (std::uint32_t z = 0; z < g.node_count(); ++z) {
    if (g.degree(z) != 1 || r.is_infinite(z)) continue;
    std::uint32_t e = 0;
    g.for_each_incident(z, [&](std::uint32_t f) { e = f; });
    const TimeId late = r.times.advance(r.burn[z], e);
    if (sent_from(g, r, e, z) == r.burn[z]) sent_from(g, r, e, z) = late;
    r.burn[z] = late;
    return;
  }
}

// The arrivals at v: (time, edge) for every incident edge whose other end sent fire.
std::vector<std::pair<TimeId, std::uint32_t>> arrivals(const MedialGraph& g, GrassfireResult& r, std::uint32_t v) {
  std::vector<std::pair<TimeId, std::uint32_t>> out;
  g.for_each_incident(v, [&](std::uint32_t e) {
    const TimeId from = sent_from(g, r, e, g.other_end(e, v));
    if (from != kNoTime) out.push_back({r.times.advance(from, e), e});
  });
  return out;
}

// The first junction (degree >= 3, burnt, not on the EMA) where `pick` finds an arrival
// other than its burn time; it then burns at that arrival.
template <class Pick>
void rewire_junction(const MedialGraph& g, GrassfireResult& r, Pick pick) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    if (g.degree(v) < 3 || r.is_infinite(v) || on_ema(r, v)) continue;
    const auto a = arrivals(g, r, v);
    const TimeId t = pick(a, v);
    if (t == kNoTime || r.times.compare(t, r.burn[v]) == 0) continue;
    g.for_each_incident(v, [&](std::uint32_t e) {
      if (sent_from(g, r, e, v) == r.burn[v]) sent_from(g, r, e, v) = t;
    });
    r.burn[v] = t;
    return;
  }
}

void junction_first(const MedialGraph& g, GrassfireResult& r) {
  rewire_junction(g, r, [&](const std::vector<std::pair<TimeId, std::uint32_t>>& a, std::uint32_t) {
    TimeId best = kNoTime;
    for (const auto& [t, e] : a)
      if (best == kNoTime || r.times.compare(t, best) < 0) best = t;
    return best;
  });
}

void junction_last(const MedialGraph& g, GrassfireResult& r) {
  rewire_junction(g, r, [&](const std::vector<std::pair<TimeId, std::uint32_t>>& a, std::uint32_t v) {
    for (const auto& [t, e] : a)  // the front along the edge v burnt into, if it exists
      if (sent_from(g, r, e, v) == r.burn[v]) return t;
    return kNoTime;
  });
}

void edf_shift_edge(const MedialGraph& g, GrassfireResult& r) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    if (r.fire[e].from_u != kNoTime) {
      r.fire[e].from_u = r.times.advance(r.fire[e].from_u, e);
      return;
    }
}

void core_burns(const MedialGraph& g, GrassfireResult& r) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (r.is_infinite(v) && g.degree(v) >= 2) {
      r.burn[v] = r.times.ignition(v);
      return;
    }
}

void ema_moved(const MedialGraph& g, GrassfireResult& r) {
  for (ExtendedMedialAxis& e : r.ema) {
    if (e.kind != ExtendedMedialAxis::Kind::Point || g.degree(e.point.at_node ? e.point.node : e.point.from) == 0)
      continue;
    if (e.point.at_node) {
      std::uint32_t edge = 0;
      g.for_each_incident(e.point.node, [&](std::uint32_t f) { edge = f; });
      e.point.node = g.other_end(edge, e.point.node);
    } else {
      e.point.at_node = true;
      e.point.node = e.point.from;
    }
    return;
  }
}

void ema_topology(const MedialGraph& g, GrassfireResult& r) {
  for (std::size_t i = 0; i < r.ema.size(); ++i) {
    ExtendedMedialAxis& e = r.ema[i];
    if (e.kind == ExtendedMedialAxis::Kind::Cycles && !e.edges.empty()) {
      e.edges.pop_back();
      return;
    }
    if (e.kind == ExtendedMedialAxis::Kind::Point && g.node_count() > 1) {
      ExtendedMedialAxis second = e;
      second.point.at_node = true;
      second.point.node = (e.point.at_node ? e.point.node + 1 : e.point.from + 1) % g.node_count();
      r.ema.push_back(second);
      return;
    }
  }
}

ResidueValue halved(ResidueValue v) {
  v.value = Interval(v.value.lo / 2, v.value.hi / 2);
  v.exact.reset();
  v.sample_steps = -1;
  return v;
}

ResidueValue& limit_at(const MedialGraph& g, PotentialResidue& pr, std::uint32_t e, std::uint32_t v) {
  return g.edge(e).u == v ? pr.edge[e].at_u : pr.edge[e].at_v;
}

bool is_maximum(const PotentialResidue& pr, std::uint32_t v) { return pr.maximum.at_node && pr.maximum.node == v; }

}  // namespace

MutantList grassfire_mutants() {
  return {
      {"leaf-late", "output: one leaf ignites one edge length late (its EDF and the fire it sends)"},
      {"junction-first", "output: one junction burns at its first arrival"},
      {"junction-last", "output: one junction burns at the arrival along the edge it should burn into"},
      {"edf-shift-edge", "output: the fire sent into one edge starts one edge length late"},
      {"core-burns", "output: one node of the 2-core gets the finite EDF R"},
      {"ema-moved", "output: the EMA point of one tree component moves to a neighbouring node"},
      {"ema-topology", "output: a second EMA point, or one edge dropped from a cycle EMA"},
      {"axis-edge-dropped", "builder output: the axis loses its last edge"},
  };
}

MutantList residue_mutants() {
  return {
      {"pr-dip", "output: PR halved at one degree-2 node (its value and both limits)"},
      {"pr-junction-dip", "output: the largest PR limit at one junction halved"},
      {"pr-extra-maximum", "output: PR at one leaf raised above the PR maximum"},
  };
}

void mutate_grassfire(const CheckContext& ctx, const MedialGraph& g, GrassfireResult& r) {
  if (ctx.mutated("leaf-late")) leaf_late(g, r);
  if (ctx.mutated("junction-first")) junction_first(g, r);
  if (ctx.mutated("junction-last")) junction_last(g, r);
  if (ctx.mutated("edf-shift-edge")) edf_shift_edge(g, r);
  if (ctx.mutated("core-burns")) core_burns(g, r);
  if (ctx.mutated("ema-moved")) ema_moved(g, r);
  if (ctx.mutated("ema-topology")) ema_topology(g, r);
}

void mutate_residue(const CheckContext& ctx, const MedialGraph& g, PotentialResidue& pr) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    if (is_maximum(pr, v)) continue;
    if (ctx.mutated("pr-dip") && g.degree(v) == 2) {
      pr.node[v] = halved(pr.node[v]);
      g.for_each_incident(v, [&](std::uint32_t e) { limit_at(g, pr, e, v) = halved(limit_at(g, pr, e, v)); });
      return;
    }
    if (ctx.mutated("pr-junction-dip") && g.degree(v) >= 3) {
      std::uint32_t top = 0;
      double best = -1;
      g.for_each_incident(v, [&](std::uint32_t e) {
        if (limit_at(g, pr, e, v).value.mid() > best) best = limit_at(g, pr, e, v).value.mid(), top = e;
      });
      limit_at(g, pr, top, v) = halved(limit_at(g, pr, top, v));
      return;
    }
    if (ctx.mutated("pr-extra-maximum") && g.degree(v) == 1) {
      ResidueValue high = pr.maximum.value;
      high.value = Interval(2 * high.value.lo + 1, 2 * high.value.hi + 1);
      high.exact.reset();
      high.sample_steps = -1;
      pr.node[v] = high;
      g.for_each_incident(v, [&](std::uint32_t e) { limit_at(g, pr, e, v) = high; });
      return;
    }
  }
}

MedialGraph mutate_axis(const CheckContext& ctx, const MedialGraph& g) {
  if (!ctx.mutated("axis-edge-dropped") || g.edge_count() == 0) return g;
  std::vector<MedialEdge> edges = g.edges();
  edges.pop_back();
  return MedialGraph(g.nodes(), std::move(edges), g.geometry_ptr());
}

}  // namespace grassfire::checks
