// shape_locator.h -- exact location of rational points and segments relative to a shape.
//
// Computes: whether a LazyPoint (an input double point or a circumcentre) lies strictly
// inside, on the boundary of, or outside a polygon with holes; whether a segment between
// two such points meets the boundary. Used to keep the Voronoi vertices inside the shape
// and the Voronoi edges that do not leave it (2.1.2, 3.3.2).
// Method: a uniform grid of about one cell per boundary edge; every cell has a reference
// point, moved off the boundary and off every vertex's horizontal line, whose inside/
// outside status is computed exactly by a sweep along its row (crossing parity). A query
// point's status is its cell reference point's status, flipped by the number of boundary
// edges registered in the cell that cross the segment from the query to the reference
// point. Crossings are counted with exact orientations and the half-open rule (a vertex
// on the segment's line counts as lying on its left), which is a consistent symbolic
// perturbation of the segment, so the parity is right whenever the query point is not on
// the boundary; boundary points are detected exactly first.
// Contract: a validated Shape2 (geometry2/shape2.h). Complexity: O(E + cells) to build; a
// query costs the number of edges in its cell (O(1) for evenly spread boundaries).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry2/lazy_point.h"
#include "geometry2/shape2.h"

namespace grassfire {

class ShapeLocator {
 public:
  // `expected_queries` sizes the grid (about one cell per boundary edge, or per 4 queries
  // when there are many more queries than edges, so a query rarely meets an edge).
  explicit ShapeLocator(const Shape2& shape, std::size_t expected_queries = 0);

  BoundedSide locate(const LazyPoint& p) const;
  // True when the closed segment pq meets the shape boundary.
  bool segment_meets_boundary(const LazyPoint& p, const LazyPoint& q) const;
  // Fast paths from enclosures alone: the status of every point of `box` when the box
  // lies in one cell that no boundary edge comes near (then the whole widened cell is on
  // one side of the boundary, that of its reference point); nullopt otherwise (use
  // locate). Likewise, false when the hull of two boxes lies in such cells only, which
  // proves that no segment between points of the boxes meets the boundary; nullopt
  // otherwise. O(1) and O(cells covered) with no exact arithmetic.
  std::optional<BoundedSide> locate_in_empty_cell(const IntervalPoint2& box) const;
  std::optional<bool> segment_meets_boundary_in_empty_cells(const IntervalPoint2& p, const IntervalPoint2& q) const;

  const OrientationStats& counters() const { return counters_; }
  std::size_t edge_count() const { return edges_.size(); }

 private:
  struct Edge {
    Point2 a, b;
  };
  struct Cell {
    int ix, iy;
  };
  Cell cell_of(double x, double y) const;
  std::uint32_t cell_index(int ix, int iy) const { return static_cast<std::uint32_t>(iy) * nx_ + ix; }
  void register_edges();
  void compute_reference_points();
  bool on_edge(const LazyPoint& p, const Edge& e) const;
  bool crosses(const LazyPoint& p, const LazyPoint& q, const Edge& e) const;
  bool segment_meets_edge(const LazyPoint& p, const LazyPoint& q, const Edge& e) const;

  std::vector<Edge> edges_;
  double x0_ = 0, y0_ = 0, dx_ = 1, dy_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_start_;  // CSR: edges of cell k are cell_edges_[cell_start_[k] .. k+1)
  std::vector<std::uint32_t> cell_edges_;
  std::vector<Point2> reference_;          // per cell
  std::vector<std::uint8_t> reference_inside_;
  // Per cell: 0 when a boundary edge is registered in it, else 1 + reference_inside_
  // (one byte per cell: the fast paths touch nothing else, which keeps them in cache).
  std::vector<std::uint8_t> empty_status_;
  mutable OrientationStats counters_;
};

}  // namespace grassfire
