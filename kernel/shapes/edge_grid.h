// edge_grid.h -- an exact uniform grid over the edges of polygonal rings: the candidate
// pairs of edges that may meet, and the edges that cross a horizontal ray.
//
// Computes: a registration of every ring edge in grid cells such that every point of the
// edge lies in a cell the edge is registered in. Hence two edges that meet share a cell,
// and enumerating the pairs inside each cell finds every meeting pair (validate_shape).
// Method: square half-open cells [i s, (i+1) s) x [j s, (j+1) s) with s a power of two,
// anchored at the origin, so the cell index floor(x / s) of a double is computed exactly
// (division by a power of two is exact unless it underflows, and an underflowed quotient
// still has the right floor once its sign is taken from x). An edge whose bounding box
// spans at most two columns or two rows is registered in every cell of its box. A longer
// edge is registered column by column, in the rows between the rows of its heights at the
// column's two sides; those rows are found exactly by orientation tests of cell corners
// against the edge, so a long diagonal edge costs O(length / s) cells, not O(length^2).
// s is the power of two at or above twice the mean edge extent (and large enough that the
// grid has at most 2^31 columns and rows, and that every cell index is below 2^52).
// Contract: finite coordinates; rings have at least 2 vertices (closing edge implicit).
// Complexity: O(E + R log R) to build for E edges and R registrations (R = O(E) when
// edge lengths are comparable); candidate pairs cost the sum over cells of the squared
// number of edges in the cell; a ray costs the edges registered in the rest of its row.
// Section: the input side of the 2D pipeline (dissertation 3.3.2 needs a simple boundary).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry2/predicates2.h"
#include "geometry2/shape2.h"

namespace grassfire {

class EdgeGrid {
 public:
  // Edge g of the grid is edge `index` of ring `ring`: from vertex index to index + 1 (mod n).
  struct EdgeId {
    std::uint32_t ring;
    std::uint32_t index;
  };

  EdgeGrid(const std::vector<Ring>& rings, OrientationStats* stats = nullptr);

  std::size_t edge_count() const { return edges_.size(); }
  EdgeId edge(std::uint32_t g) const;
  double cell_size() const { return cell_size_; }
  std::size_t registrations() const { return entries_.size(); }

  // Calls visit(g1, g2), g1 < g2, for pairs of edges whose bounding boxes overlap and that
  // share a cell: every pair of edges that meet is visited at least once, a pair of
  // short (box-registered) edges exactly once.
  void for_each_candidate_pair(const std::function<void(std::uint32_t, std::uint32_t)>& visit) const;

  // Adds winding_step(q, a, b) to winding[r] for every edge ab of ring r != skip_ring that
  // crosses the ray from q towards +x. Contract: q lies on no edge of those rings, and
  // winding has one entry per ring.
  void add_ray_windings(const Point2& q, std::uint32_t skip_ring, std::vector<long>& winding,
                        OrientationStats* stats = nullptr) const;

 private:
  struct Segment {
    Point2 a, b;
  };
  struct Entry {
    std::uint64_t key;  // row-major cell key: (row - min_row) << 32 | (column - min_column)
    std::uint32_t edge;
  };

  std::int64_t cell_of(double x) const;
  std::uint64_t key(std::int64_t column, std::int64_t row) const;
  void register_box(std::uint32_t g);
  void register_by_columns(std::uint32_t g, OrientationStats* stats);
  std::int64_t row_at(const Segment& e, double x, std::int64_t lo, std::int64_t hi, OrientationStats* stats) const;
  bool counted_here(std::uint32_t g1, std::uint32_t g2, std::uint64_t cell_key) const;

  std::vector<Segment> edges_;
  std::vector<std::uint32_t> ring_of_edge_;
  std::vector<std::uint32_t> ring_start_;  // first edge of each ring
  std::vector<bool> box_registered_;
  std::vector<Entry> entries_;  // sorted by (key, edge)
  double cell_size_ = 1.0;
  std::int64_t min_column_ = 0, max_column_ = 0, min_row_ = 0, max_row_ = 0;
};

}  // namespace grassfire
