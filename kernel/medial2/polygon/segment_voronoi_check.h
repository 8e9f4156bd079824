// segment_voronoi_check.h -- is an interior segment Voronoi topology (segment_voronoi.h)
// the diagram of a polygon, as far as its combinatorics tell (2.1.1; docs/design.md 4)?
//
// Computes the first defect of `topo` against what every interior segment Voronoi diagram of
// a polygon with h holes has (the medial axis is a deformation retract of the polygon, and
// every boundary feature has a cell meeting the interior):
//  1. one apex per convex polygon vertex, at its own point site and its two segments;
//  2. every edge joins two listed vertices, separates two different sites, and both sites
//     are sites of both of its ends;
//  3. every site (point sites of non-convex vertices too, every segment) is a site of some
//     vertex, except the point sites of vertices between collinear segments (no cell of
//     their own meets the interior beyond their normal, which is not a primary edge);
//  4. the graph is connected with V - E = 1 - h (b1 = h: one independent cycle per hole).
// Builders that fail such a check gave a wrong diagram (Boost.Polygon's known wrong outputs:
// a missing Voronoi vertex at a reflex corner, an infinite edge reached from the interior);
// exact_polygon_axis then rebuilds the diagram with CGAL's segment Delaunay graph and counts
// the fallback. These checks are necessary, not sufficient: the definition-level check
// (polygon_axis_validate.h) is the complete one, run by the tests on the built axis.
// Contract: `sites` as given to the builder; `holes` = rings - 1.
// Complexity: O(n) for n polygon vertices.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "medial2/polygon/segment_voronoi.h"

namespace grassfire {

// The first defect found, in words, or nothing when the topology passes 1-4.
std::optional<std::string> voronoi_topology_defect(const PolygonSites& sites, const VoronoiTopology& topo,
                                                   std::uint32_t holes);

}  // namespace grassfire
