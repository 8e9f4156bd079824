// lpdf.cpp -- LPDF by resolutions of the singular curves (see header).
#include "curves3/lpdf.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <string>

#include "burn3/discrete/steiner_graph.h"
#include "geometry3/vec3.h"
#include "support/union_find.h"

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The singular curves: per singular edge its curve and, per triangle of the edge (in
// edge_triangles order), the label of its sheet along the curve.
struct SingularCurves {
  std::vector<std::uint32_t> curve;               // per edge; kNoIndex unless singular
  std::vector<std::vector<std::uint32_t>> label;  // per edge
  std::vector<std::uint32_t> sheets;              // per curve: k
};

std::uint32_t position_in(const std::vector<std::uint32_t>& list, std::uint32_t x) {
  return static_cast<std::uint32_t>(std::find(list.begin(), list.end(), x) - list.begin());
}

// Across vertex v (a point of M1), the triangle of the singular edge `next` in the same
// sector as triangle t of edge e.
std::uint32_t across(const MedialComplex& mc, std::uint32_t v, std::uint32_t t, std::uint32_t next) {
  const LinkElement& el = mc.link_elements(v)[mc.corner_element(t, corner_of(mc.triangle(t), v))];
  const Sector& s = mc.sectors()[el.id];
  return s.ends[0] == next ? s.triangles.front() : s.triangles.back();
}

void walk(const MedialComplex& mc, SingularCurves& sc, std::uint32_t e0, std::uint32_t start, std::uint32_t id) {
  std::uint32_t e = e0, at = start;
  for (std::size_t guard = 0; guard < mc.edge_count(); ++guard) {
    at = mc.edge(e).v[0] == at ? mc.edge(e).v[1] : mc.edge(e).v[0];
    if (mc.vertex(at).kind != VertexKind::SingularCurve) return;
    std::uint32_t next = kNoIndex;
    for (std::uint32_t f : mc.vertex_edges(at))
      if (f != e && mc.edge(f).stratum == EdgeStratum::Singular) next = f;
    if (next == kNoIndex) return;
    std::vector<std::uint32_t> label(mc.edge_triangles(next).size(), kNoIndex);
    for (std::uint32_t j = 0; j < mc.edge_triangles(e).size(); ++j)
      label[position_in(mc.edge_triangles(next), across(mc, at, mc.edge_triangles(e)[j], next))] = sc.label[e][j];
    if (sc.curve[next] != kNoIndex) {  // a closed curve: its sheets must come back in place
      if (label != sc.label[next])
        throw std::invalid_argument(mc.source() + ": LPDF: a closed singular curve permutes its sheets");
      return;
    }
    sc.curve[next] = id;
    sc.label[next] = label;
    e = next;
  }
}

SingularCurves singular_curves(const MedialComplex& mc) {
  SingularCurves sc;
  sc.curve.assign(mc.edge_count(), kNoIndex);
  sc.label.resize(mc.edge_count());
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular || sc.curve[e] != kNoIndex) continue;
    const auto id = static_cast<std::uint32_t>(sc.sheets.size());
    sc.sheets.push_back(static_cast<std::uint32_t>(mc.edge_triangles(e).size()));
    sc.curve[e] = id;
    for (std::uint32_t j = 0; j < mc.edge_triangles(e).size(); ++j) sc.label[e].push_back(j);
    walk(mc, sc, e, mc.edge(e).v[0], id);
    walk(mc, sc, e, mc.edge(e).v[1], id);
  }
  return sc;
}

// Maximal matchings of k sheets, each as a group id per sheet (a pair shares its id; the
// unmatched sheet, when k is odd, has its own): perfect matchings of the sheets left.
void perfect_matchings(std::vector<std::uint32_t>& group, std::uint32_t next_id,
                       std::vector<std::vector<std::uint32_t>>& out) {
  const auto first = static_cast<std::size_t>(std::find(group.begin(), group.end(), kNoIndex) - group.begin());
  if (first == group.size()) {
    out.push_back(group);
    return;
  }
  for (std::size_t j = first + 1; j < group.size(); ++j) {
    if (group[j] != kNoIndex) continue;
    group[first] = group[j] = next_id;
    perfect_matchings(group, next_id + 1, out);
    group[first] = group[j] = kNoIndex;
  }
}

std::vector<std::vector<std::uint32_t>> maximal_matchings(std::uint32_t k) {
  std::vector<std::vector<std::uint32_t>> out;
  std::vector<std::uint32_t> group(k, kNoIndex);
  if (k % 2 == 0) {
    perfect_matchings(group, 0, out);
    return out;
  }
  for (std::uint32_t alone = 0; alone < k; ++alone) {
    group[alone] = 0;
    perfect_matchings(group, 1, out);
    group[alone] = kNoIndex;
  }
  return out;
}

// One resolved surface: copies of the graph points and the Dijkstra from its boundary.
class ResolvedSurface {
 public:
  ResolvedSurface(const MedialComplex& mc, const SteinerGraph& g) : mc_(mc), g_(g) {}

  // group[e][j]: the group of triangle j of edge e (manifold and border edges: all 0).
  void resolve(const std::vector<std::vector<std::uint32_t>>& group) {
    group_ = &group;
    corner_copy_.assign(3 * mc_.triangle_count(), 0);
    state_base_.assign(g_.node_count() + 1, 0);
    source_.clear();
    for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) state_base_[v + 1] = state_base_[v] + vertex_copies(v);
    for (std::uint32_t n = g_.vertex_count(); n < g_.node_count(); ++n) {
      const std::uint32_t e = g_.edge_of(n);
      const auto& gr = group[e];
      const std::uint32_t count = gr.empty() ? 1 : 1 + *std::max_element(gr.begin(), gr.end());
      state_base_[n + 1] = state_base_[n] + count;
    }
    source_.resize(state_base_.back(), kInf);
    for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) vertex_sources(v);
    for (std::uint32_t n = g_.vertex_count(); n < g_.node_count(); ++n) edge_point_sources(n);
  }

  // Multi-source Dijkstra over the states; dist per state.
  std::vector<double> distances() const {
    std::vector<double> dist = source_;
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> q;
    std::vector<std::uint32_t> node_of(dist.size());
    for (std::uint32_t n = 0; n < g_.node_count(); ++n)
      for (std::uint32_t s = state_base_[n]; s < state_base_[n + 1]; ++s) {
        node_of[s] = n;
        if (std::isfinite(dist[s])) q.push({dist[s], s});
      }
    while (!q.empty()) {
      const auto [d, s] = q.top();
      q.pop();
      if (d > dist[s]) continue;
      const std::uint32_t n = node_of[s];
      for (std::uint32_t t : triangles_at(n)) {
        if (state(n, t) != s) continue;
        const Vec3d p = g_.position(n);
        for (std::uint32_t y : boundary_nodes(t)) {
          const std::uint32_t sy = state(y, t);
          const double nd = d + v3::dist(p, g_.position(y));
          if (nd < dist[sy]) dist[sy] = nd, q.push({nd, sy});
        }
      }
    }
    return dist;
  }

  std::uint32_t state(std::uint32_t node, std::uint32_t t) const {
    if (g_.is_vertex(node)) return state_base_[node] + corner_copy_[3 * t + corner_of(mc_.triangle(t), node)];
    const std::uint32_t e = g_.edge_of(node);
    const auto& tris = mc_.edge_triangles(e);
    const auto& gr = (*group_)[e];
    return state_base_[node] + (gr.empty() ? 0 : gr[position_in(tris, t)]);
  }
  std::uint32_t first_state(std::uint32_t node) const { return state_base_[node]; }
  std::uint32_t end_state(std::uint32_t node) const { return state_base_[node + 1]; }

  std::vector<std::uint32_t> triangles_at(std::uint32_t node) const {
    if (g_.is_vertex(node)) return mc_.vertex_triangles(node);
    return mc_.edge_triangles(g_.edge_of(node));
  }

  std::vector<std::uint32_t> boundary_nodes(std::uint32_t t) const {
    const ComplexTriangle& tr = mc_.triangle(t);
    std::vector<std::uint32_t> nodes(tr.v.begin(), tr.v.end());
    for (std::uint32_t e : tr.e)
      for (std::uint32_t i = 1; i <= g_.steiner_count(e); ++i) nodes.push_back(g_.steiner_node(e, i));
    return nodes;
  }

 private:
  std::uint32_t group_of(std::uint32_t e, std::uint32_t t) const {
    const auto& gr = (*group_)[e];
    return gr.empty() ? 0 : gr[position_in(mc_.edge_triangles(e), t)];
  }
  // A (edge, group) link node is free (an end of a path) when its group has one triangle.
  bool lone(std::uint32_t e, std::uint32_t t) const {
    const auto& gr = (*group_)[e];
    if (gr.empty()) return mc_.edge_triangles(e).size() == 1;
    return std::count(gr.begin(), gr.end(), gr[position_in(mc_.edge_triangles(e), t)]) == 1;
  }
  // The boundary value at parameter s of edge e: f on M's border, R on a cut side.
  double free_value(std::uint32_t e, double s) const {
    if (mc_.edge(e).stratum == EdgeStratum::Border) return mc_.ignition_on_edge(e, s);
    const double r0 = mc_.vertex(mc_.edge(e).v[0]).radius, r1 = mc_.vertex(mc_.edge(e).v[1]).radius;
    return r0 + s * (r1 - r0);  // a cut side
  }

  // Components of the resolved link of v: union the corners of triangles through shared
  // (edge, group) link nodes.
  std::uint32_t vertex_copies(std::uint32_t v) {
    const auto& tris = mc_.vertex_triangles(v);
    UnionFind uf(tris.size());
    for (std::size_t a = 0; a < tris.size(); ++a)
      for (std::size_t b = a + 1; b < tris.size(); ++b)
        for (std::uint32_t ea : edges_at(mc_.triangle(tris[a]), v))
          for (std::uint32_t eb : edges_at(mc_.triangle(tris[b]), v))
            if (ea == eb && group_of(ea, tris[a]) == group_of(eb, tris[b])) uf.unite(a, b);
    std::vector<std::uint32_t> copy_of_root(tris.size(), kNoIndex);
    std::uint32_t copies = 0;
    for (std::size_t a = 0; a < tris.size(); ++a) {
      const std::uint32_t r = uf.find(static_cast<std::uint32_t>(a));
      if (copy_of_root[r] == kNoIndex) copy_of_root[r] = copies++;
      corner_copy_[3 * tris[a] + corner_of(mc_.triangle(tris[a]), v)] = copy_of_root[r];
    }
    return std::max<std::uint32_t>(copies, 1);
  }

  void vertex_sources(std::uint32_t v) {
    for (std::uint32_t t : mc_.vertex_triangles(v))
      for (std::uint32_t e : edges_at(mc_.triangle(t), v))
        if (lone(e, t)) {
          const double value = free_value(e, mc_.edge(e).v[0] == v ? 0.0 : 1.0);
          double& s = source_[state(v, t)];
          s = std::min(s, value);
        }
  }

  void edge_point_sources(std::uint32_t n) {
    const std::uint32_t e = g_.edge_of(n);
    const double s = g_.parameter(e, g_.index_on_edge(n));
    for (std::uint32_t t : mc_.edge_triangles(e))
      if (lone(e, t)) source_[state(n, t)] = std::min(source_[state(n, t)], free_value(e, s));
  }

  const MedialComplex& mc_;
  const SteinerGraph& g_;
  const std::vector<std::vector<std::uint32_t>>* group_ = nullptr;
  std::vector<std::uint32_t> corner_copy_;
  std::vector<std::uint32_t> state_base_;
  std::vector<double> source_;
};

}  // namespace

LpdfResult largest_plate_distance(const MedialComplex& mc, const LpdfOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SteinerGraph g(mc, options.spacing, options.max_points);
  const SingularCurves sc = singular_curves(mc);
  std::vector<std::vector<std::vector<std::uint32_t>>> choices;  // per curve, its matchings
  double total = 1;
  for (std::uint32_t k : sc.sheets) {
    choices.push_back(maximal_matchings(k));
    total *= static_cast<double>(choices.back().size());
  }
  if (total > static_cast<double>(options.max_resolutions))
    throw std::invalid_argument(mc.source() + ": LPDF needs " + std::to_string(static_cast<unsigned long long>(total)) + " resolutions of its " +
                                std::to_string(sc.sheets.size()) + " singular curves (limit " +
                                std::to_string(options.max_resolutions) + ")");
  LpdfResult out;
  out.spacing = options.spacing;
  out.singular_curves = sc.sheets.size();
  out.edge_first_steiner = g.first_steiner();
  out.vertex_lpdf.assign(mc.vertex_count(), -kInf);
  out.steiner_lpdf.assign(g.steiner_total(), -kInf);
  out.corner_lpdf.assign(3 * mc.triangle_count(), -kInf);
  ResolvedSurface surface(mc, g);
  std::vector<std::vector<std::uint32_t>> group(mc.edge_count());
  const auto runs = static_cast<std::uint64_t>(total);
  for (std::uint64_t r = 0; r < runs; ++r) {
    std::uint64_t code = r;
    for (std::uint32_t e = 0; e < mc.edge_count(); ++e) group[e].clear();
    std::vector<std::uint32_t> pick(sc.sheets.size());
    for (std::size_t c = 0; c < choices.size(); ++c) pick[c] = static_cast<std::uint32_t>(code % choices[c].size()), code /= choices[c].size();
    for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
      if (sc.curve[e] == kNoIndex) continue;
      const auto& m = choices[sc.curve[e]][pick[sc.curve[e]]];
      for (std::uint32_t label : sc.label[e]) group[e].push_back(m[label]);
    }
    surface.resolve(group);
    const std::vector<double> dist = surface.distances();
    for (std::uint32_t n = 0; n < g.node_count(); ++n) {
      double best = -kInf;
      for (std::uint32_t s = surface.first_state(n); s < surface.end_state(n); ++s) best = std::max(best, dist[s]);
      double& slot = g.is_vertex(n) ? out.vertex_lpdf[n] : out.steiner_lpdf[n - g.vertex_count()];
      slot = std::max(slot, best);
    }
    for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c)
        out.corner_lpdf[3 * t + c] = std::max(out.corner_lpdf[3 * t + c], dist[surface.state(mc.triangle(t).v[c], t)]);
  }
  out.resolutions = runs;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// The board and fin with zero radius (docs/design.md 5), a = 1, c = (1, 1, 0); F the fin's
// border s = 1, B the board's y = 0, N the junction x = y >= 1 (z = 0). Definition 7 with
// R = 0: the largest geodesic radius of a disk centred at p inside a locally embedded disk.
//  - Fin: F is a border of every disk holding p, at distance sqrt2 (s - 1) inside the fin;
//    the disk made of the fin and the front side of the board reaches no other boundary
//    closer (B is reachable from the front side only around c, farther). So sqrt2 (s - 1).
//  - Board, back side (y < x): a disk holding p either is the board (then B at y, straight
//    down, bounds it) or pairs the back side with the fin across N: then F unfolds onto the
//    front side, whose nearest point to p is c, and B is still y away. So y.
//  - Board, front side (y > x): the board gives y. The front side glued to the fin (the
//    back side cut along N) is bounded by F, nearest at c, and by the cut, reached around c
//    only when x > 1 (the straight way down crosses N where the back side is cut), so at
//    |p - c|; for x <= 1 the way down to B (or to the cut below c) is shorter than y. So
//    max(y, |p - c|) for x > 1 (zone 2 where |p - c| > y: below the parabola P, (x - 1)^2 =
//    2 y - 1, through the kink k = (2 + sqrt2, 2 + sqrt2, 0)); y otherwise.
//  - N itself: the board gives s (B straight down the back side), the fin with the front
//    side sqrt2 (s - 1); the larger, the limit from the fin beyond k and from the board
//    before (upper semicontinuous, 4.1.2).
double board_fin_lpdf(const std::array<double, 3>& p) {
  const double x = p[0], y = p[1], z = p[2], sqrt2 = std::sqrt(2.0);
  if (z > 0) return sqrt2 * (x - 1);
  if (x == y && x >= 1) return std::max(x, sqrt2 * (x - 1));
  if (y > x && x > 1) return std::max(y, std::hypot(x - 1, y - 1));
  return y;
}

int board_fin_lpdf_zone(const std::array<double, 3>& p) {
  const double x = p[0], y = p[1];
  if (p[2] > 0 || (x == y && x >= 1)) return 1;
  return (y > x && x > 1 && std::hypot(x - 1, y - 1) > y) ? 2 : 3;
}

}  // namespace grassfire
