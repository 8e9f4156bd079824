// sampled_axis.h -- the medial axis of a planar shape from boundary samples (2.1.2, 3.3.2).
//
// Computes: the medial graph whose nodes are the Voronoi vertices of the boundary samples
// that lie strictly inside the shape, and whose edges are the Voronoi edges between two
// such vertices, except (a) edges dual to a boundary segment between consecutive samples
// of one ring (they separate two neighbouring samples of the same boundary curve and
// cross the boundary when the sampling is dense) and (b) edges that meet the shape
// boundary (possible where the sampling is sparse or near sharp corners). R at a node is
// the circumradius of its Delaunay triangle (the distance to the nearest sample). Voronoi
// vertices that coincide (cocircular samples, common on symmetric shapes) are merged into
// one node, so no edge has zero length. The shape is connected, and so is its medial
// axis; where undersampled sharp features cut the Voronoi graph into several components,
// only the largest is kept and the others are counted as fragments in the report.
// Exactness: the Delaunay triangulation uses CGAL's exact predicates; cocircularity is
// decided by CGAL's exact in-circle predicate; inside/outside and boundary crossings by
// exact orientations on the rational circumcentres (geometry2/shape_locator.h); R and
// edge lengths are square roots of rationals computed exactly on demand (MedialGeometry).
// Contract: `shape` is validated (geometry2/shape2.h); `samples[r]` are points on ring r in
// ring order, pairwise distinct over all rings. The result approximates the medial axis
// and converges to it as the sampling densifies (Brandt and Algazi 1992; dissertation [17]).
// Complexity: O(n log n) expected for n samples (the Delaunay triangulation dominates; it
// inserts the samples in random rounds, each in ring order, which the contract provides).
// Nodes are numbered by the smallest sample id of their Delaunay triangle, edges by their
// smaller end, so the nodes of a chain of the axis are mostly consecutive.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry2/lazy_point.h"
#include "medial2/medial_graph.h"
#include "geometry2/shape2.h"

namespace grassfire {

struct SampledAxisReport {
  std::uint64_t samples = 0;
  std::uint64_t delaunay_triangles = 0;
  std::uint64_t merged_triangles = 0;      // triangles merged into a cocircular neighbour's node
  std::uint64_t inside_nodes = 0;
  std::uint64_t boundary_dual_edges = 0;   // rule (a) above
  std::uint64_t crossing_edges = 0;        // rule (b) above
  std::uint64_t edges = 0;
  std::uint64_t components = 0;           // of the Voronoi graph, before fragments are dropped
  std::uint64_t fragment_nodes = 0;       // nodes in the dropped components
  std::uint64_t exact_locations = 0;       // centres located exactly (not in an empty locator cell)
  OrientationStats predicates;            // orientation filter successes and exact fallbacks
  // Thread CPU seconds (they do not count time the CPU spent on other processes).
  double delaunay_seconds = 0;
  double locate_seconds = 0;               // circumcircles, inside tests, adjacency, freeing the triangulation
  double edges_seconds = 0;                // cocircular merging and the Voronoi edges
  double graph_seconds = 0;                // the largest component and the medial graph
  double axis_seconds = 0;                 // everything after the triangulation
};

MedialGraph sampled_medial_axis(const Shape2& shape, const std::vector<std::vector<Point2>>& samples,
                                SampledAxisReport* report = nullptr);

// CGAL Delaunay_triangulation_2 alone on the same points (the benchmark's baseline);
// returns the number of finite faces.
std::uint64_t plain_delaunay_triangle_count(const std::vector<Point2>& points);

}  // namespace grassfire
