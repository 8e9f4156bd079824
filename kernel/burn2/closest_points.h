// closest_points.h -- the closest boundary points of medial points (2.1, 2.2.1, 3.4.2),
// as positions along the shape boundary: the input of potential residue, separation
// angle, feature size and boundary eccentricity.
//
// Computes, for a medial graph:
//  - per node, its closest boundary points (the points at distance R);
//  - per edge, the two boundary points closest to every point of the edge (its
//    generators), at each of its two ends;
// each as a ring, an arc length along the ring from its vertex 0 (in the ring's vertex
// order; exact when the position is) and a certified enclosure of the point.
// By axis:
//  - sampled Voronoi axis (medial2/sampled/sampled_axis.h): a node's closest points are the
//    samples on its empty circle (its Delaunay triangle, or all samples of a cocircular
//    group, found by a nearest-neighbour query and exact rational distance tests); an
//    edge's generators are the two samples of its dual Delaunay edge, the samples common
//    to its two end nodes. Sample k of a ring with m samples and exact perimeter L sits at
//    arc length k L / m (shapes/resample.h places it there, up to double rounding); the
//    generators do not move along an edge.
//  - exact polygon axis (medial2/polygon/polygon_axis.h): a node's closest points are the feet
//    of its defining sites (the vertex of a point site, the perpendicular foot on a
//    segment site); an edge's generators are the feet of its two sites at each end, and
//    move along the edge. Arc lengths are exact sums of square roots when the node's
//    circle is (polygon edge lengths plus the foot's offset), enclosures otherwise.
//  - union of disks (medial2/disks/disk_union_axis.h): corners only (closest points of nodes
//    and edge generators); arc lengths along circular arcs are not provided
//    (has_arc_length is false), so no potential residue or boundary eccentricity.
// Contract: g was built by one of those constructions (the sampled axis from `samples`
// of `shape`). Throws std::invalid_argument otherwise.
// Complexity: O(n log N) for n nodes and N samples (sampled axis), O(n) otherwise.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry2/lazy_point.h"
#include "medial2/medial_graph.h"
#include "shapes/resample.h"
#include "geometry2/shape2.h"

namespace grassfire {

constexpr std::uint32_t kNoSample = 0xffffffffu;

// A point of the boundary. Its exact arc length is, on a sampled axis, sample L / m
// (sample = its index in the ring, m the ring's sample count), and on a polygon axis the
// ring length up to `vertex` plus `offset` (nullopt when the foot is not exact).
struct BoundaryPoint {
  std::uint32_t ring = 0;
  Interval arc;                        // arc length from vertex 0 of the ring (enclosure)
  IntervalPoint2 position;             // enclosure of the point
  std::uint32_t vertex = 0;            // polygon axis: the vertex at or before the point
  std::optional<ExactSum> offset;      // polygon axis: exact arc length from that vertex
  std::uint32_t sample = kNoSample;    // sampled axis: index of the sample in its ring
};

struct ClosestPoints {
  bool has_arc_length = true;
  std::vector<Interval> ring_length;                   // perimeters, enclosures
  // Exact squared lengths of the boundary edges of every ring (input units).
  std::vector<std::vector<mpq_class>> ring_edges;
  std::vector<std::uint32_t> ring_samples;             // sampled axis: samples per ring
  std::vector<std::vector<BoundaryPoint>> node;        // closest points of each node
  // Generators of each edge: [0], [1] at its end u; [2], [3] at its end v.
  std::vector<std::array<BoundaryPoint, 4>> edge;

  // arc(p) - arc(q) exactly, for points of one ring; nullopt when an offset is unknown.
  std::optional<ExactSum> exact_arc_difference(const BoundaryPoint& p, const BoundaryPoint& q) const;
  ExactSum exact_ring_length(std::uint32_t ring) const;
};

// Dispatches on the graph's geometry; `shape` and `samples` are needed for a sampled axis.
ClosestPoints closest_points(const MedialGraph& g, const Shape2* shape = nullptr,
                             const BoundarySamples* samples = nullptr);

}  // namespace grassfire
