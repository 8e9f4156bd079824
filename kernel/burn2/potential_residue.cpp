// potential_residue.cpp -- see potential_residue.h.
#include "burn2/potential_residue.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "support/union_find.h"

namespace grassfire {

namespace {

Point2 mid(const IntervalPoint2& p) { return {p.x.mid(), p.y.mid()}; }

class Residues {
 public:
  explicit Residues(const ClosestPoints& cp) : cp_(cp) {}

  // PR between two boundary points.
  ResidueValue distance(const BoundaryPoint& p, const BoundaryPoint& q) {
    if (p.ring != q.ring) return {Interval::infinity(), std::nullopt};
    const Interval d = abs_of(p.arc - q.arc), l = cp_.ring_length[p.ring];
    ResidueValue r{min_of(d, l - d), std::nullopt};
    r.ring = p.ring;
    if (p.sample != kNoSample) {  // samples: an exact number of spacings L / m
      const std::int64_t m = cp_.ring_samples[p.ring], k = std::llabs(std::int64_t(p.sample) - q.sample);
      r.sample_steps = std::min(k, m - k);
      r.value = Interval(static_cast<double>(r.sample_steps)) * l / Interval(static_cast<double>(m));
      return r;
    }
    if (std::optional<ExactSum> e = cp_.exact_arc_difference(p, q)) {
      ExactSum abs_e = sign(*e, &stats_) < 0 ? ExactSum() - *e : *e;
      ExactSum twice = abs_e;
      twice.scale(2);
      r.exact = sign(length(p.ring) - twice, &stats_) >= 0 ? abs_e : length(p.ring) - abs_e;
      r.exact->simplify();
    }
    return r;
  }

  const ExactSum& length(std::uint32_t ring) {
    if (lengths_.size() <= ring) lengths_.resize(ring + 1);
    if (!lengths_[ring]) lengths_[ring] = cp_.exact_ring_length(ring);
    return *lengths_[ring];
  }

  // |arc(p) - arc(q)| - L / 2: its sign says which way round the boundary is shorter.
  int half_perimeter_side(const BoundaryPoint& p, const BoundaryPoint& q) {
    if (p.sample != kNoSample) {
      const std::int64_t m = cp_.ring_samples[p.ring], k = std::llabs(std::int64_t(p.sample) - q.sample);
      return (2 * k > m) - (2 * k < m);
    }
    const Interval l = cp_.ring_length[p.ring];
    const int quick = certified_sign(abs_of(p.arc - q.arc) - half(l));
    if (quick != kUndecided) return quick;
    if (std::optional<ExactSum> e = cp_.exact_arc_difference(p, q)) {
      ExactSum abs_e = sign(*e, &stats_) < 0 ? ExactSum() - *e : *e;
      abs_e.scale(2);
      return sign(abs_e - cp_.exact_ring_length(p.ring), &stats_);
    }
    ++undecided_;
    return 0;
  }

  int compare(const ResidueValue& a, const ResidueValue& b) {
    if (a.value.is_infinite() || b.value.is_infinite())
      return a.value.is_infinite() == b.value.is_infinite() ? 0 : (a.value.is_infinite() ? 1 : -1);
    if (a.sample_steps >= 0 && b.sample_steps >= 0 && a.ring == b.ring)
      return (a.sample_steps > b.sample_steps) - (a.sample_steps < b.sample_steps);
    const int quick = certified_sign(a.value - b.value);
    if (quick != kUndecided) return quick;
    if (a.exact && b.exact) return sign(*a.exact - *b.exact, &stats_);
    ++undecided_;
    return 0;
  }

  std::uint64_t undecided() const { return undecided_; }

 private:
  const ClosestPoints& cp_;
  NumberStats stats_;
  std::uint64_t undecided_ = 0;
  std::vector<std::optional<ExactSum>> lengths_;  // exact perimeters, on demand
};

EdgeResidue edge_residue(Residues& r, const std::array<BoundaryPoint, 4>& gen, const Interval& ring_length) {
  EdgeResidue e;
  e.at_u = r.distance(gen[0], gen[1]);
  e.at_v = r.distance(gen[2], gen[3]);
  if (gen[0].ring != gen[1].ring) return e;
  const int su = r.half_perimeter_side(gen[0], gen[1]), sv = r.half_perimeter_side(gen[2], gen[3]);
  if (su * sv >= 0) return e;
  // |s - t| is linear in the foot positions: it crosses L / 2 at this fraction.
  const Interval du = abs_of(gen[0].arc - gen[1].arc), dv = abs_of(gen[2].arc - gen[3].arc);
  e.peak = true;
  e.peak_fraction = (half(ring_length) - du) / (dv - du);
  return e;
}

// The point of a peak: linear along a segment; on a parabolic arc (one generator fixed,
// the focus; the other's foot moving linearly on the directrix) the point whose foot is
// the interpolated foot: X = f + h n with h = |f - F|^2 / (2 n.(F - f)).
Point2 peak_point(const MedialGraph& g, std::uint32_t e, const std::array<BoundaryPoint, 4>& gen, double t,
                  std::array<Point2, 2>& closest) {
  const Point2 xu = g.node(g.edge(e).u).position, xv = g.node(g.edge(e).v).position;
  const Point2 a = mid(gen[0].position), b = mid(gen[1].position), c = mid(gen[2].position), d = mid(gen[3].position);
  closest = {Point2{a.x + t * (c.x - a.x), a.y + t * (c.y - a.y)}, Point2{b.x + t * (d.x - b.x), b.y + t * (d.y - b.y)}};
  if (g.edge(e).kind != EdgeKind::ParabolicArc) return {xu.x + t * (xv.x - xu.x), xu.y + t * (xv.y - xu.y)};
  const bool first_fixed = a == c;
  const Point2 focus = first_fixed ? a : b, foot = first_fixed ? closest[1] : closest[0];
  const Point2 foot_u = first_fixed ? b : a;
  const double nl = std::hypot(xu.x - foot_u.x, xu.y - foot_u.y);
  const Point2 n{(xu.x - foot_u.x) / nl, (xu.y - foot_u.y) / nl};
  const double fx = focus.x - foot.x, fy = focus.y - foot.y;
  const double h = (fx * fx + fy * fy) / (2 * (n.x * fx + n.y * fy));
  return {foot.x + h * n.x, foot.y + h * n.y};
}

const ResidueValue& limit(const MedialGraph& g, const PotentialResidue& pr, std::uint32_t e, std::uint32_t v) {
  return g.edge(e).u == v ? pr.edge[e].at_u : pr.edge[e].at_v;
}

// Peaks, plus plateaus (nodes joined by constant edges at their own value) next to no
// higher point: a node is `raised` when an incident edge rises above it.
std::uint32_t count_local_maxima(const MedialGraph& g, const PotentialResidue& pr, Residues& r) {
  UnionFind plateau(g.node_count());
  std::vector<bool> raised(g.node_count(), false);
  std::uint32_t peaks = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::uint32_t u = g.edge(e).u, v = g.edge(e).v;
    const EdgeResidue& er = pr.edge[e];
    const bool top_u = r.compare(er.at_u, pr.node[u]) == 0, top_v = r.compare(er.at_v, pr.node[v]) == 0;
    if (er.peak) {
      ++peaks;
      raised[u] = raised[u] || top_u;
      raised[v] = raised[v] || top_v;
      continue;
    }
    const int c = r.compare(er.at_u, er.at_v);
    if (c == 0 && top_u && top_v) {
      plateau.unite(u, v);
    } else {
      // Constant but lower than one end, or monotone: the lower end sees a rise.
      if (c <= 0 && top_u) raised[u] = true;
      if (c >= 0 && top_v) raised[v] = true;
    }
  }
  std::vector<bool> spoiled(g.node_count(), false);
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (raised[v]) spoiled[plateau.find(v)] = true;
  std::uint32_t maxima = peaks;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) maxima += plateau.find(v) == v && !spoiled[v];
  return maxima;
}

}  // namespace

PotentialResidue potential_residue(const MedialGraph& g, const ClosestPoints& cp) {
  if (!cp.has_arc_length) throw std::invalid_argument("potential residue: the boundary has no arc length here");
  PotentialResidue pr;
  Residues r(cp);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const auto& gen = cp.edge[e];
    pr.edge.push_back(edge_residue(r, gen, cp.ring_length[gen[0].ring]));
  }
  std::vector<std::array<Point2, 2>> node_closest(g.node_count());
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    ResidueValue best{Interval(0.0), ExactSum()};
    bool first = true;
    auto offer = [&](const ResidueValue& value, const Point2& p, const Point2& q) {
      if (first || r.compare(value, best) > 0) best = value, node_closest[v] = {p, q};
      first = false;
    };
    g.for_each_incident(v, [&](std::uint32_t e) {
      const bool at_u = g.edge(e).u == v;
      const auto& gen = cp.edge[e];
      offer(at_u ? pr.edge[e].at_u : pr.edge[e].at_v, mid(gen[at_u ? 0 : 2].position), mid(gen[at_u ? 1 : 3].position));
    });
    if (g.degree(v) == 0) {
      const auto& pts = cp.node[v];
      for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size(); ++j)
          offer(r.distance(pts[i], pts[j]), mid(pts[i].position), mid(pts[j].position));
    }
    pr.node.push_back(best);
  }
  // The maximum: peaks first (their value L / 2 is the largest possible), then nodes.
  ResidueMaximum& m = pr.maximum;
  bool found = false;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (!pr.edge[e].peak) continue;
    const BoundaryPoint& p = cp.edge[e][0];
    ResidueValue value{half(cp.ring_length[p.ring]), cp.exact_ring_length(p.ring).scale(mpq_class(1, 2))};
    value.ring = p.ring;
    if (found && r.compare(value, m.value) <= 0) continue;
    found = true;
    m.at_node = false;
    m.edge = e;
    m.fraction = pr.edge[e].peak_fraction;
    m.value = value;
    m.position = peak_point(g, e, cp.edge[e], m.fraction.mid(), m.closest);
  }
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    if (found && r.compare(pr.node[v], m.value) <= 0) continue;
    found = true;
    m = ResidueMaximum{};
    m.node = v;
    m.value = pr.node[v];
    m.position = g.node(v).position;
    m.closest = node_closest[v];
  }
  pr.local_maxima = count_local_maxima(g, pr, r);
  pr.undecided = r.undecided();
  return pr;
}

ResidueMonotonicity residue_monotonicity(const MedialGraph& g, const PotentialResidue& pr) {
  ResidueMonotonicity out;
  if (g.node_count() == 0) return out;
  const ResidueMaximum& m = pr.maximum;
  const std::vector<std::uint32_t> component = g.component_of_nodes();
  const std::uint32_t root_component = component[m.at_node ? m.node : g.edge(m.edge).u];
  std::uint64_t nodes = 0, edges = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) nodes += component[v] == root_component;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) edges += component[g.edge(e).u] == root_component;
  if (edges + 1 != nodes) return out;  // not a tree
  // Orient every edge towards the maximum: parent edge of each node.
  std::vector<std::uint32_t> parent_edge(g.node_count(), kNoSample), queue;
  std::vector<bool> seen(g.node_count(), false);
  if (m.at_node) {
    queue.push_back(m.node);
  } else {
    queue = {g.edge(m.edge).u, g.edge(m.edge).v};
    parent_edge[g.edge(m.edge).u] = parent_edge[g.edge(m.edge).v] = m.edge;
  }
  for (std::uint32_t v : queue) seen[v] = true;
  for (std::size_t i = 0; i < queue.size(); ++i)
    g.for_each_incident(queue[i], [&](std::uint32_t e) {
      const std::uint32_t w = g.other_end(e, queue[i]);
      if (seen[w]) return;
      seen[w] = true;
      parent_edge[w] = e;
      queue.push_back(w);
    });
  auto drop = [](const ResidueValue& lower_side, const ResidueValue& higher_side) {
    return lower_side.value.mid() - higher_side.value.mid();
  };
  for (std::uint32_t c : queue) {
    const std::uint32_t e = parent_edge[c];
    if (e == kNoSample) continue;  // the root node
    if (!(e == m.edge && !m.at_node)) {
      ++out.edges_checked;
      const std::uint32_t p = g.other_end(e, c);
      if (certified_sign(limit(g, pr, e, p).value - limit(g, pr, e, c).value) == -1) ++out.edge_decreases;
    }
    const bool junction = g.degree(c) >= 3;
    (junction ? out.junctions : out.regular_nodes) += g.degree(c) >= 2;
    g.for_each_incident(c, [&](std::uint32_t f) {
      if (f == e) return;
      const ResidueValue &child = limit(g, pr, f, c), &parent = limit(g, pr, e, c);
      if (certified_sign(parent.value - child.value) != -1) return;
      if (junction) {
        ++out.junction_decreases;
        out.worst_junction_drop = std::max(out.worst_junction_drop, drop(child, parent));
      } else {
        ++out.regular_decreases;
        out.worst_regular_drop = std::max(out.worst_regular_drop, drop(child, parent));
      }
    });
  }
  return out;
}

}  // namespace grassfire
