// polygon_axis_symmetry.cpp -- see polygon_axis_symmetry.h.
#include "medial2/polygon/polygon_axis_symmetry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "support/union_find.h"

namespace grassfire {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

bool is_int32(double x) { return std::fabs(x) <= 2147483647.0 && x == std::floor(x); }

std::uint64_t pack(long long x, long long y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(static_cast<std::int32_t>(x))) << 32) |
         static_cast<std::uint32_t>(static_cast<std::int32_t>(y));
}

// The site that phi maps `site` to: a point to its image; the segment i -> next[i] to
// the segment starting at phi(i), or at phi(next[i]) when phi reverses orientation.
std::uint32_t map_site(const PolygonSites& s, const PolygonSymmetry& phi, std::uint32_t site) {
  if (s.is_point(site)) return phi.vertex[site];
  const std::uint32_t start = s.seg_start(site);
  return s.vertex_count() + (phi.reverses ? phi.vertex[s.next[start]] : phi.vertex[start]);
}

// A circle named up to the swaps its formula is symmetric under (see the header).
struct CircleKey {
  std::array<std::uint32_t, 4> v{};  // kind and root, then the three sites
  bool operator==(const CircleKey& o) const { return v == o.v; }
};
struct CircleKeyHash {
  std::size_t operator()(const CircleKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t x : k.v) h = (h ^ x) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

CircleKey key_of(VoronoiCircle c) {
  auto& s = c.sites;
  if (c.kind == CircleKind::Apex) s[1] = s[2] = 0;
  const int root = canonical_roles(c.kind, c.root, s, false);
  CircleKey k;
  k.v = {static_cast<std::uint32_t>(c.kind) * 4u + static_cast<std::uint32_t>(root + 1), s[0], s[1], s[2]};
  return k;
}

// phi of the circle c, as a circle of the mapped sites (roles and root by the header).
VoronoiCircle image(const PolygonSites& s, const PolygonSymmetry& phi, const VoronoiCircle& c) {
  VoronoiCircle m = c;
  for (std::uint32_t& site : m.sites) site = map_site(s, phi, site);
  if (phi.reverses) reflect_roles(c.kind, m.sites);
  return m;
}

bool overlap(const Interval& a, const Interval& b) { return a.lo <= b.hi && b.lo <= a.hi; }
bool centres_apart(const CircleValue<Interval>& a, const CircleValue<Interval>& b) {
  return !overlap(a.x, b.x) || !overlap(a.y, b.y);
}

// Is the circle of node w the circle c (c's sites among w's)? The circle of w is tangent
// to every site of w (its circles share one centre and R: polygon_axis.cpp), R > 0 here,
// so it is one of the circles tangent to c's three sites: the only one for PPP, SSS and
// PPS-linear; for PPS, PSS and PSS-parallel one of two, the other being c with the other
// root (PSS-parallel: L1 and L2 swapped). So w's circle is c when its centre's enclosure
// is disjoint from that of the other one (Arb at 256 bits when the doubles overlap), or
// when a point site of c lies on the line of a segment site of c: a circle through P
// tangent to a line through P touches it at P, its centre is on the normal there, and
// the remaining condition (the other line, the other point, or the strip's width) is
// linear in R: at most one circle (voronoi_circle.h, at_most_one_circle).
bool is_circle_of(const PolygonSites& s, const AxisNodeData& w, const VoronoiCircle& c) {
  if (!w.all_aliased || c.kind == CircleKind::Apex) return false;
  for (std::uint32_t site : c.sites)
    if (!std::binary_search(w.sites.begin(), w.sites.end(), site)) return false;
  const CircleValue<Interval> own = solve_interval(s, w.circle);
  if (!(own.r.lo > 0)) return false;
  if (at_most_one_circle(s, c)) return true;
  VoronoiCircle other = c;
  if (c.kind == CircleKind::PSSParallel)
    std::swap(other.sites[1], other.sites[2]);
  else
    other.root = static_cast<std::int8_t>(-c.root);
  if (centres_apart(own, solve_interval(s, other))) return true;
  BallPrecision guard(256);
  const CircleValue<Ball> a = solve_ball(s, w.circle), b = solve_ball(s, other);
  auto apart = [](const Ball& x, const Ball& y) {
    const int d = (x - y).sign();
    return d == 1 || d == -1;
  };
  return apart(a.x, b.x) || apart(a.y, b.y);
}

struct SiteSetHash {
  std::size_t operator()(const std::vector<std::uint32_t>& v) const {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t x : v) h = (h ^ x) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

struct EdgeKeyHash {
  std::size_t operator()(const std::array<std::uint32_t, 4>& k) const { return CircleKeyHash{}(CircleKey{k}); }
};
std::array<std::uint32_t, 4> edge_key(std::uint32_t u, std::uint32_t v, std::uint32_t a, std::uint32_t b) {
  return {std::min(u, v), std::max(u, v), std::min(a, b), std::max(a, b)};
}

}  // namespace

std::vector<PolygonSymmetry> polygon_symmetries(const PolygonSites& s) {
  const std::uint32_t n = s.vertex_count();
  std::vector<PolygonSymmetry> found;
  if (n == 0) return found;
  __int128 sx = 0, sy = 0;
  for (const Point2& p : s.vertex) {
    if (!is_int32(p.x) || !is_int32(p.y)) return found;
    sx += static_cast<long long>(p.x);
    sy += static_cast<long long>(p.y);
  }
  std::unordered_map<std::uint64_t, std::uint32_t> index;  // built on first need
  static const int kLinear[7][4] = {{-1, 0, 0, 1}, {1, 0, 0, -1}, {-1, 0, 0, -1}, {0, 1, 1, 0},
                                    {0, -1, -1, 0}, {0, -1, 1, 0}, {0, 1, -1, 0}};
  for (const auto& a : kLinear) {
    // phi fixes the centroid c = S / n: t = (S - A S) / n must be an integer vector.
    const __int128 ex = sx - (a[0] * sx + a[1] * sy), ey = sy - (a[2] * sx + a[3] * sy);
    if (ex % n != 0 || ey % n != 0) continue;
    if (index.empty()) {
      index.reserve(2 * n);
      for (std::uint32_t i = 0; i < n; ++i)
        if (!index.emplace(pack(static_cast<long long>(s.vertex[i].x), static_cast<long long>(s.vertex[i].y)), i).second)
          return found;  // repeated vertices: no symmetry claimed
    }
    PolygonSymmetry phi;
    phi.a00 = a[0], phi.a01 = a[1], phi.a10 = a[2], phi.a11 = a[3];
    phi.tx = static_cast<long long>(ex / n), phi.ty = static_cast<long long>(ey / n);
    phi.reverses = a[0] * a[3] - a[1] * a[2] < 0;
    phi.vertex.resize(n);
    bool ok = true;
    for (std::uint32_t i = 0; i < n && ok; ++i) {
      const long long x = static_cast<long long>(s.vertex[i].x), y = static_cast<long long>(s.vertex[i].y);
      const long long mx = a[0] * x + a[1] * y + phi.tx, my = a[2] * x + a[3] * y + phi.ty;
      if (!is_int32(static_cast<double>(mx)) || !is_int32(static_cast<double>(my))) {
        ok = false;
        break;
      }
      const auto it = index.find(pack(mx, my));
      ok = it != index.end();
      if (ok) phi.vertex[i] = it->second;
    }
    // Segments must map to segments: i -> next[i] to phi(i) -> phi(next[i]), traversed
    // backwards when phi reverses orientation (the interior stays on the left).
    for (std::uint32_t i = 0; i < n && ok; ++i)
      ok = phi.reverses ? s.next[phi.vertex[s.next[i]]] == phi.vertex[i] : s.next[phi.vertex[i]] == phi.vertex[s.next[i]];
    if (ok) found.push_back(std::move(phi));
  }
  return found;
}

AxisValueClasses axis_value_classes(const PolygonSites& s, const std::vector<AxisNodeData>& nodes,
                                    const std::vector<AxisEdgeData>& edges) {
  AxisValueClasses out;
  const auto n = static_cast<std::uint32_t>(nodes.size());
  const auto m = static_cast<std::uint32_t>(edges.size());
  const std::vector<JoinedEdges> joined = joinable_edges(s, nodes, edges);
  UnionFind node_uf(n), edge_uf(m + joined.size());
  const std::vector<PolygonSymmetry> symmetries = polygon_symmetries(s);
  out.symmetries = static_cast<std::uint32_t>(symmetries.size());
  if (!symmetries.empty()) {
    std::unordered_map<CircleKey, std::uint32_t, CircleKeyHash> node_of;
    node_of.reserve(2 * n);
    std::vector<bool> ambiguous_key(n, false);
    auto add_key = [&](const VoronoiCircle& c, std::uint32_t i) {
      const auto [it, fresh] = node_of.emplace(key_of(c), i);
      if (!fresh && it->second != i) ambiguous_key[i] = ambiguous_key[it->second] = true;
    };
    for (std::uint32_t i = 0; i < n; ++i) {
      add_key(nodes[i].circle, i);
      for (const VoronoiCircle& c : nodes[i].aliases) add_key(c, i);
    }
    std::unordered_map<std::array<std::uint32_t, 4>, std::uint32_t, EdgeKeyHash> edge_of;
    edge_of.reserve(2 * m);
    for (std::uint32_t e = 0; e < m; ++e)
      edge_of.emplace(edge_key(edges[e].u, edges[e].v, edges[e].site_a, edges[e].site_b), e);
    // Nodes by their site sets, for the images that no circle key names (a degenerate
    // vertex that the symmetry maps onto itself, split by Boost into other triples).
    std::unordered_map<std::vector<std::uint32_t>, std::uint32_t, SiteSetHash> node_of_sites;
    for (std::uint32_t i = 0; i < n; ++i)
      if (nodes[i].sites.size() > 3) node_of_sites.emplace(nodes[i].sites, i);
    std::vector<std::uint32_t> image_node(n);
    std::vector<std::uint32_t> mapped_sites;
    for (const PolygonSymmetry& phi : symmetries) {
      for (std::uint32_t i = 0; i < n; ++i) {
        const auto it = node_of.find(key_of(image(s, phi, nodes[i].circle)));
        // Equal keys are equal circles, so any node found has R(image) = R(i); ambiguous
        // keys (one circle representing two nodes) are left out only to keep the edge
        // map below one-to-one.
        image_node[i] = it == node_of.end() || ambiguous_key[it->second] ? kNone : it->second;
        if (it == node_of.end() && nodes[i].sites.size() > 3) {
          mapped_sites.clear();
          for (std::uint32_t site : nodes[i].sites) mapped_sites.push_back(map_site(s, phi, site));
          std::sort(mapped_sites.begin(), mapped_sites.end());
          const auto w = node_of_sites.find(mapped_sites);
          if (w != node_of_sites.end() && !ambiguous_key[w->second] &&
              is_circle_of(s, nodes[w->second], image(s, phi, nodes[i].circle)))
            image_node[i] = w->second;
        }
        if (image_node[i] != kNone)
          node_uf.unite(i, image_node[i]);
        else
          ++out.unmapped_nodes;
      }
      for (std::uint32_t e = 0; e < m; ++e) {
        const AxisEdgeData& d = edges[e];
        const auto it = image_node[d.u] == kNone || image_node[d.v] == kNone
                            ? edge_of.end()
                            : edge_of.find(edge_key(image_node[d.u], image_node[d.v], map_site(s, phi, d.site_a),
                                                    map_site(s, phi, d.site_b)));
        if (it != edge_of.end())
          edge_uf.unite(e, it->second);
        else
          ++out.unmapped_edges;
      }
    }
  }
  unite_congruent_atoms(s, nodes, edges, joined, node_uf, edge_uf);
  for (std::size_t k = 0; k < joined.size(); ++k)
    out.joined.emplace(joined_key(joined[k].first, joined[k].second),
                       edge_uf.find(static_cast<std::uint32_t>(m + k)));
  out.node.resize(n);
  out.edge.resize(m);
  for (std::uint32_t i = 0; i < n; ++i) out.node[i] = node_uf.find(i);
  for (std::uint32_t e = 0; e < m; ++e) out.edge[e] = edge_uf.find(e);
  std::vector<std::uint32_t> size(std::max(n, m), 0);
  for (std::uint32_t i = 0; i < n; ++i) ++size[out.node[i]];
  for (std::uint32_t i = 0; i < n; ++i) out.nodes_in_shared_classes += size[out.node[i]] > 1;
  std::fill(size.begin(), size.end(), 0);
  for (std::uint32_t e = 0; e < m; ++e) ++size[out.edge[e]];
  for (std::uint32_t e = 0; e < m; ++e) out.edges_in_shared_classes += size[out.edge[e]] > 1;
  return out;
}

}  // namespace grassfire
