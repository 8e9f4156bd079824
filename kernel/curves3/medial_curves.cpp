// medial_curves.cpp -- raw ends, punctures, the burning collapse and peeling (see header).
#include "curves3/medial_curves.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <unordered_map>

#include "geometry3/vec3.h"
#include "support/union_find.h"

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Unit conormal of edge e of K in triangle s, pointing out of s across e.
Vec3d outward_conormal(const AxisRefinement& k, std::uint32_t s, std::uint32_t e) {
  const RefinedTriangle& t = k.triangles[s];
  std::uint32_t apex = t.v[0];
  for (int c = 0; c < 3; ++c)
    if (t.e[c] == e) apex = t.v[c];
  const Vec3d a = k.vertices[k.edges[e].v[0]].position, b = k.vertices[k.edges[e].v[1]].position;
  const Vec3d along = v3::unit(v3::sub(b, a));
  const Vec3d out = v3::sub(v3::lerp(a, b, 0.5), k.vertices[apex].position);
  return v3::unit(v3::sub(out, v3::scale(along, v3::dot(out, along))));
}

double inflow(const AxisRefinement& k, std::uint32_t s, std::uint32_t e) {
  if (!std::isfinite(k.burn_key(s))) return 0;
  return v3::dot(k.triangles[s].fire, outward_conormal(k, s, e));
}

// Mean of triangle s's side times at the K vertices a and b.
double side_time(const AxisRefinement& k, std::uint32_t s, std::uint32_t a, std::uint32_t b) {
  const RefinedTriangle& t = k.triangles[s];
  double sum = 0;
  for (int c = 0; c < 3; ++c)
    if (t.v[c] == a || t.v[c] == b) sum += t.side_bt[c];
  return sum / 2;
}

using Entry = std::pair<double, std::uint32_t>;
using MinQueue = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;

// Steps 2 and 3 of the header on K: which triangles and edges remain, and counts.
class BurningCollapse {
 public:
  BurningCollapse(const AxisRefinement& k, std::vector<bool> walls, MedialCurveStats& stats)
      : k_(k), wall_(std::move(walls)), stats_(stats) {
    cofaces_.resize(k.edges.size());
    for (std::size_t e = 0; e < k.edges.size(); ++e) cofaces_[e] = static_cast<std::uint32_t>(k.edge_triangles[e].size());
    free_since_.assign(k.edges.size(), -kInf);
    edge_gone_.assign(k.edges.size(), false);
    triangle_gone_.assign(k.triangles.size(), false);
  }

  void puncture_cycles() {
    std::vector<std::uint32_t> never;
    std::vector<std::vector<std::uint32_t>> columns;
    for (std::uint32_t s = 0; s < k_.triangles.size(); ++s) {
      if (std::isfinite(k_.burn_key(s))) continue;
      never.push_back(s);
      std::vector<std::uint32_t> col(k_.triangles[s].e.begin(), k_.triangles[s].e.end());
      std::sort(col.begin(), col.end());
      columns.push_back(col);
    }
    for (std::size_t c : gf2_zero_columns(std::move(columns))) {
      remove_triangle(never[c], kInf);
      ++stats_.punctures;
    }
  }

  void run() {
    for (std::uint32_t s = 0; s < k_.triangles.size(); ++s)
      if (!triangle_gone_[s]) main_.push({k_.burn_key(s), s});
    for (std::size_t guard = 0; guard <= k_.triangles.size(); ++guard) {
      drain();
      if (!open_a_wall()) break;
    }
    for (std::uint32_t s = 0; s < k_.triangles.size(); ++s) stats_.residual_triangles += triangle_gone_[s] ? 0 : 1;
  }

  bool edge_remains(std::uint32_t e) const { return !edge_gone_[e]; }
  std::uint32_t cofaces(std::uint32_t e) const { return cofaces_[e]; }
  bool wall(std::uint32_t e) const { return wall_[e]; }

 private:
  bool is_free(std::uint32_t e) const { return !edge_gone_[e] && cofaces_[e] == 1; }

  // The free edge of s the fire entered it through: the smallest outward cosine of the
  // fire (most into s), then the earliest freed, then the smallest id; walls only when
  // `walls` is set.
  std::uint32_t entry_edge(std::uint32_t s, bool walls) const {
    std::uint32_t best = kNoIndex;
    double best_inflow = 0;
    for (std::uint32_t e : k_.triangles[s].e) {
      if (!is_free(e) || wall_[e] != walls) continue;
      const double c = inflow(k_, s, e);
      if (best == kNoIndex || c < best_inflow ||
          (c == best_inflow && (free_since_[e] < free_since_[best] || (free_since_[e] == free_since_[best] && e < best))))
        best = e, best_inflow = c;
    }
    return best;
  }

  void remove_triangle(std::uint32_t s, double time) {
    triangle_gone_[s] = true;
    for (std::uint32_t f : k_.triangles[s].e) {
      --cofaces_[f];
      if (cofaces_[f] != 1) continue;
      free_since_[f] = time;
      for (std::uint32_t other : k_.edge_triangles[f])
        if (!triangle_gone_[other]) main_.push({std::max(time, k_.burn_key(other)), other});
    }
  }

  // Flat event loop: pop the earliest triangle; collapse it through its entry edge, or
  // set it aside when only walls are free. Each triangle is pushed at most 4 times.
  void drain() {
    while (!main_.empty()) {
      const auto [key, s] = main_.top();
      main_.pop();
      if (triangle_gone_[s]) continue;
      const std::uint32_t e = entry_edge(s, false);
      if (e == kNoIndex) {
        if (entry_edge(s, true) != kNoIndex) blocked_.push({key, s});
        continue;
      }
      edge_gone_[e] = true;
      remove_triangle(s, key);
    }
  }

  // The blocked triangle with the smallest key loses the wall it was burned through.
  bool open_a_wall() {
    while (!blocked_.empty()) {
      const auto [key, s] = blocked_.top();
      blocked_.pop();
      if (triangle_gone_[s]) continue;
      if (entry_edge(s, false) == kNoIndex) {
        std::uint32_t best = kNoIndex;
        for (std::uint32_t e : k_.triangles[s].e)
          if (is_free(e) && wall_[e] && (best == kNoIndex || inflow(k_, s, e) < inflow(k_, s, best))) best = e;
        if (best == kNoIndex) continue;
        wall_[best] = false;
        ++stats_.walls_opened;
      }
      main_.push({key, s});
      return true;
    }
    return false;
  }

  const AxisRefinement& k_;
  std::vector<bool> wall_;
  MedialCurveStats& stats_;
  std::vector<std::uint32_t> cofaces_;
  std::vector<double> free_since_;
  std::vector<bool> edge_gone_, triangle_gone_;
  MinQueue main_, blocked_;
};

// Step 4: peel unanchored leaves in increasing BT of the leaf (the 2D grassfire on the
// hair: a component without anchors shrinks to its last-burning point).
std::vector<bool> peel(const AxisRefinement& k, const std::vector<bool>& graph_edge, const std::vector<bool>& anchor,
                       std::vector<bool>& edge_kept, MedialCurveStats& stats) {
  const std::size_t n = k.vertices.size();
  std::vector<std::vector<std::uint32_t>> incident(n);
  std::vector<std::uint32_t> degree(n, 0);
  edge_kept = graph_edge;
  for (std::uint32_t e = 0; e < k.edges.size(); ++e)
    if (graph_edge[e])
      for (std::uint32_t v : k.edges[e].v) incident[v].push_back(e), ++degree[v];
  std::vector<bool> alive(n, true);
  MinQueue leaves;
  auto key = [&](std::uint32_t v) { return std::isfinite(k.vertices[v].bt) ? k.vertices[v].bt : kInf; };
  for (std::uint32_t v = 0; v < n; ++v)
    if (degree[v] == 1) leaves.push({key(v), v});
  while (!leaves.empty()) {
    const std::uint32_t v = leaves.top().second;
    leaves.pop();
    if (!alive[v] || degree[v] != 1) continue;
    std::uint32_t e = kNoIndex;
    for (std::uint32_t f : incident[v])
      if (edge_kept[f]) e = f;
    if (anchor[e]) continue;
    edge_kept[e] = false;
    alive[v] = false;
    ++stats.peeled_edges;
    const std::uint32_t other = k.edges[e].v[0] == v ? k.edges[e].v[1] : k.edges[e].v[0];
    --degree[v];
    if (--degree[other] == 1) leaves.push({key(other), other});
  }
  return alive;
}

BettiNumbers graph_betti(std::size_t nodes, const std::vector<CurveEdge>& edges) {
  UnionFind uf(nodes);
  for (const CurveEdge& e : edges) uf.unite(e.u, e.v);
  BettiNumbers b;
  for (std::uint32_t v = 0; v < nodes; ++v) b.b0 += uf.find(v) == v ? 1 : 0;
  b.b1 = static_cast<long>(edges.size()) - static_cast<long>(nodes) + b.b0;
  return b;
}

MedialCurves assemble(const AxisRefinement& k, const std::vector<bool>& alive, const std::vector<bool>& kept,
                      const std::vector<bool>& raw) {
  MedialCurves out;
  std::vector<std::uint32_t> node_of(k.vertices.size(), kNoIndex);
  for (std::uint32_t v = 0; v < k.vertices.size(); ++v) {
    if (!alive[v]) continue;
    node_of[v] = static_cast<std::uint32_t>(out.nodes.size());
    const RefinedVertex& rv = k.vertices[v];
    out.nodes.push_back({rv.position, rv.radius, rv.bt, rv.on, rv.cell, rv.index, rv.weight});
  }
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    if (!kept[e]) continue;
    const RefinedEdge& re = k.edges[e];
    out.edges.push_back({node_of[re.v[0]], node_of[re.v[1]], k.length(e), re.on_edge, re.in_triangle, raw[e], re.segment});
  }
  out.curve_betti = graph_betti(out.nodes.size(), out.edges);
  return out;
}

}  // namespace

std::vector<bool> raw_end_edges(const AxisRefinement& k, const MedialCurveOptions& options, double time_margin) {
  std::vector<bool> raw(k.edges.size(), false);
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    const auto& sides = k.edge_triangles[e];
    if (sides.size() < 2) continue;
    const auto [a, b] = k.edges[e].v;
    const double bt = (k.vertices[a].bt + k.vertices[b].bt) / 2;
    int arriving = 0, departing = 0;
    bool early = false;
    for (std::uint32_t s : sides) {
      const double c = inflow(k, s, e);
      const bool arrives = c > options.arrive_cosine;
      arriving += arrives ? 1 : 0;
      departing += c < -options.depart_cosine ? 1 : 0;
      if (arrives && sides.size() > 2) early = early || side_time(k, s, a, b) < bt - time_margin;
    }
    raw[e] = (arriving >= 1 && departing == 0) || early;
  }
  return raw;
}

// Closing and significance by length (step 1, second half; see header).
void close_raw_ends(const AxisRefinement& k, std::vector<bool>& raw, int hops, double min_length, double min_et) {
  const std::size_t n = k.vertices.size();
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> adjacent(n);  // (vertex, edge)
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    adjacent[k.edges[e].v[0]].push_back({k.edges[e].v[1], e});
    adjacent[k.edges[e].v[1]].push_back({k.edges[e].v[0], e});
  }
  UnionFind pieces(n);
  std::vector<std::uint32_t> degree(n, 0);
  for (std::uint32_t e = 0; e < k.edges.size(); ++e)
    if (raw[e]) pieces.unite(k.edges[e].v[0], k.edges[e].v[1]), ++degree[k.edges[e].v[0]], ++degree[k.edges[e].v[1]];
  for (std::uint32_t a = 0; a < n; ++a) {
    if (degree[a] != 1) continue;
    // Breadth-first up to `hops` edges of K to the nearest vertex of another piece.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> frontier = {{a, kNoIndex}};
    std::unordered_map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> parent;  // vertex -> (from, edge)
    parent[a] = {kNoIndex, kNoIndex};
    std::uint32_t found = kNoIndex;
    for (int hop = 0; hop < hops && found == kNoIndex; ++hop) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> next;
      for (const auto& [v, unused] : frontier)
        for (const auto& [w, e] : adjacent[v]) {
          if (parent.count(w)) continue;
          parent[w] = {v, e};
          next.push_back({w, e});
          const bool other_piece = degree[w] > 0 && pieces.find(w) != pieces.find(a);
          if (other_piece && (found == kNoIndex || v3::dist(k.vertices[w].position, k.vertices[a].position) <
                                                      v3::dist(k.vertices[found].position, k.vertices[a].position)))
            found = w;
        }
      frontier.swap(next);
    }
    if (found == kNoIndex) continue;
    for (std::uint32_t v = found; v != a; v = parent[v].first) {
      const std::uint32_t e = parent[v].second;
      if (!raw[e]) raw[e] = true, ++degree[k.edges[e].v[0]], ++degree[k.edges[e].v[1]];
    }
    pieces.unite(a, found);
  }
  std::unordered_map<std::uint32_t, double> length, et;
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    if (!raw[e]) continue;
    const std::uint32_t piece = pieces.find(k.edges[e].v[0]);
    length[piece] += k.length(e);
    double& best = et.emplace(piece, -1.0).first->second;
    for (std::uint32_t v : k.edges[e].v) best = std::max(best, k.vertices[v].bt - k.vertices[v].radius);
  }
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    if (!raw[e]) continue;
    const std::uint32_t piece = pieces.find(k.edges[e].v[0]);
    if (length[piece] < min_length || (min_et > 0 && et[piece] < min_et)) raw[e] = false;
  }
}

// The largest finite ET = BT - R over the vertices of K.
double largest_et(const AxisRefinement& k) {
  double best = 0;
  for (const RefinedVertex& v : k.vertices)
    if (std::isfinite(v.bt)) best = std::max(best, v.bt - v.radius);
  return best;
}

BettiNumbers complex_betti(const MedialComplex& mc) {
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (const ComplexEdge& e : mc.edges())
    if (e.stratum == EdgeStratum::Dangling) segments.push_back(e.v);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (const ComplexTriangle& t : mc.triangles()) triangles.push_back(t.v);
  return betti_numbers(mc.vertex_count(), segments, triangles, {});
}

MedialCurves medial_curves(const BurningField& field, const MedialCurveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MedialCurves out = medial_curves(AxisRefinement::build(field), field, options);
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

MedialCurves medial_curves(const AxisRefinement& k, const BurningField& field, const MedialCurveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MedialCurveStats stats;
  const double margin = options.time_margin >= 0 ? options.time_margin : field.resolution();
  std::vector<bool> raw = raw_end_edges(k, options, margin);
  close_raw_ends(k, raw, options.closing_hops, options.min_length >= 0 ? options.min_length : 3 * field.resolution(),
                 options.min_et_fraction * largest_et(k));
  for (bool r : raw) stats.raw_end_edges += r ? 1 : 0;
  BurningCollapse collapse(k, raw, stats);
  collapse.puncture_cycles();
  collapse.run();
  std::vector<bool> graph_edge(k.edges.size()), anchor(k.edges.size());
  for (std::uint32_t e = 0; e < k.edges.size(); ++e) {
    graph_edge[e] = collapse.edge_remains(e) && collapse.cofaces(e) == 0;
    anchor[e] = graph_edge[e] && (collapse.wall(e) || k.edges[e].segment);
  }
  std::vector<bool> kept;
  const std::vector<bool> alive = peel(k, graph_edge, anchor, kept, stats);
  MedialCurves out = assemble(k, alive, kept, raw);
  out.axis_betti = complex_betti(field.complex());
  out.method = field.method();
  out.options = options;
  stats.refined_vertices = k.vertices.size();
  stats.refined_edges = k.edges.size();
  stats.refined_triangles = k.triangles.size();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.stats = stats;
  return out;
}

double MedialCurves::total_length() const {
  double sum = 0;
  for (const CurveEdge& e : edges) sum += e.length;
  return sum;
}

}  // namespace grassfire
