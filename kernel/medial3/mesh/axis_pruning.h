// axis_pruning.h -- pruning a polygonal 2-complex without changing its homotopy type.
//
// Computes: the complex left after elementary collapses of the cells that a caller's test
// does not keep: a polygon that is not kept goes away with one of its free sides (a side
// no other polygon has), and an edge without polygons that is not kept goes away with a
// free end (a vertex no other edge has). Elementary collapses are deformation retractions,
// so the result has the homotopy type of the input, whatever the test says: the test
// decides what may go, the topology decides what must stay. This is the filtering of a
// Voronoi axis by a noise criterion (the theta-medial axis of Foskey-Lin-Manocha, the
// angle condition of Dey-Zhao 2004) made topology-preserving, in the spirit of the
// homotopic thinning of digital skeletons.
// Order: cells are collapsed in first-in first-out order of becoming collapsible,
// starting from increasing ids, so the result is a deterministic function of the input.
// Contract: polygons are rings of >= 3 distinct vertex ids < vertex_count; segments are
// not polygon sides; no polygon or segment repeated (std::invalid_argument for bad rings).
// Complexity: O(s log s) for s polygon sides and segments (sorting the edges), then
// linear, with one test per cell that becomes collapsible.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "complex3/polygon_rings.h"

namespace grassfire {

struct PolygonalComplex {
  std::size_t vertex_count = 0;
  PolygonRings polygons;
  std::vector<std::array<std::uint32_t, 2>> segments;  // edges of no polygon
};

// Where an edge of the complex first occurs: side `side` of polygon `index`, or segment
// `index`.
struct EdgeOrigin {
  bool segment = false;
  std::uint32_t index = 0, side = 0;
};

struct PrunedComplex {
  std::vector<bool> polygon_kept;
  std::vector<std::array<std::uint32_t, 2>> bare_edges;  // kept edges with no kept polygon
  std::vector<EdgeOrigin> bare_origins;                  // parallel to bare_edges
  std::vector<bool> vertex_kept;
  std::size_t collapsed_polygons = 0, collapsed_edges = 0;
};

PrunedComplex prune_by_collapse(const PolygonalComplex& complex, const std::function<bool(std::uint32_t polygon)>& keep_polygon,
                                const std::function<bool(const EdgeOrigin& edge)>& keep_edge);

}  // namespace grassfire
