// segment_voronoi.cpp -- sites of a polygon in the exact frame (see segment_voronoi.h).
#include "medial2/polygon/segment_voronoi.h"

#include "geometry2/predicates2.h"

namespace grassfire {

PolygonSites make_sites(const Shape2& shape, double scale) {
  PolygonSites s;
  for (const Ring& ring : shape.rings) {
    const std::uint32_t first = s.vertex_count();
    const std::uint32_t n = static_cast<std::uint32_t>(ring.points.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      s.vertex.push_back({ring.points[i].x * scale, ring.points[i].y * scale});
      s.next.push_back(first + (i + 1) % n);
      s.prev.push_back(first + (i + n - 1) % n);
    }
  }
  return s;
}

bool is_convex_vertex(const PolygonSites& s, std::uint32_t v) {
  return orientation(s.vertex[s.prev[v]], s.vertex[v], s.vertex[s.next[v]]) > 0;
}

}  // namespace grassfire
