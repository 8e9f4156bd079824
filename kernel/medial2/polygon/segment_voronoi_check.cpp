// segment_voronoi_check.cpp -- see segment_voronoi_check.h.
#include "medial2/polygon/segment_voronoi_check.h"

#include <algorithm>
#include <vector>

#include "geometry2/predicates2.h"
#include "support/union_find.h"

namespace grassfire {

namespace {

bool lists(const VoronoiTopology::Vertex& v, std::uint32_t site) {
  return std::find(v.sites.begin(), v.sites.end(), site) != v.sites.end();
}

std::string site_name(const PolygonSites& s, std::uint32_t site) {
  return s.is_point(site) ? "vertex " + std::to_string(site)
                          : "edge " + std::to_string(s.seg_start(site)) + "-" + std::to_string(s.seg_end(site));
}

}  // namespace

std::optional<std::string> voronoi_topology_defect(const PolygonSites& s, const VoronoiTopology& topo,
                                                   std::uint32_t holes) {
  const std::size_t nv = topo.vertices.size();
  // 1. One apex per convex vertex.
  std::vector<std::uint32_t> apexes(s.vertex_count(), 0);
  for (const VoronoiTopology::Vertex& v : topo.vertices) {
    if (!v.apex) continue;
    const std::uint32_t p = v.sites[0];
    if (!s.is_point(p) || !is_convex_vertex(s, p) || v.sites[1] != s.vertex_count() + s.prev[p] ||
        v.sites[2] != s.vertex_count() + p)
      return std::string("an apex that is no convex polygon vertex's");
    ++apexes[p];
  }
  for (std::uint32_t p = 0; p < s.vertex_count(); ++p)
    if (is_convex_vertex(s, p) && apexes[p] != 1)
      return "convex " + site_name(s, p) + " has " + std::to_string(apexes[p]) + " apexes";
  // 2. Edges between listed vertices, their two sites defining both ends.
  UnionFind components(nv);
  for (const VoronoiTopology::Edge& e : topo.edges) {
    if (e.u >= nv || e.v >= nv) return std::string("an edge to an unlisted vertex");
    if (e.site_a == e.site_b) return "an edge separating " + site_name(s, e.site_a) + " from itself";
    for (std::uint32_t end : {e.u, e.v})
      if (!lists(topo.vertices[end], e.site_a) || !lists(topo.vertices[end], e.site_b))
        return "the edge between " + site_name(s, e.site_a) + " and " + site_name(s, e.site_b) +
               " ends at a vertex they do not define";
    components.unite(e.u, e.v);
  }
  // 3. Every site with a cell meeting the interior is a site of some vertex.
  std::vector<bool> seen(s.site_count(), false);
  for (const VoronoiTopology::Vertex& v : topo.vertices)
    for (std::uint32_t site : v.sites)
      if (site < s.site_count()) seen[site] = true;
  for (std::uint32_t site = 0; site < s.site_count(); ++site) {
    if (seen[site]) continue;
    if (s.is_point(site) && orientation(s.vertex[s.prev[site]], s.vertex[site], s.vertex[s.next[site]]) == 0) continue;
    return site_name(s, site) + " has no Voronoi vertex";
  }
  // 4. Connected, with one independent cycle per hole.
  for (std::uint32_t i = 0; i < nv; ++i)
    if (components.find(i) != 0) return std::string("the diagram's interior is not connected");
  const long long euler = static_cast<long long>(nv) - static_cast<long long>(topo.edges.size());
  if (nv == 0 || euler != 1 - static_cast<long long>(holes))
    return std::to_string(nv) + " vertices and " + std::to_string(topo.edges.size()) + " edges for " +
           std::to_string(holes) + " holes (V - E must be 1 - holes)";
  return std::nullopt;
}

}  // namespace grassfire
