// disk_union_geometry.h -- the boundary of a union of disks and the exact values behind
// its medial axis (2.1.1; see medial2/disks/disk_union_axis.h for the construction).
//
// Computes: (1) exact predicates on the corners of the boundary (the points where two
// boundary circles cross, 2.1.1's "singular points"): orientation, in-circle, coordinate
// and angular order, each an interval filter followed by the exact sign of a sum of
// square roots (number/exact_sum.h); (2) the MedialGeometry of the axis: R and edge
// lengths as exact sums or certified constants, positions exactly in a multiquadratic
// field (number/multiquadratic.h).
// A corner of circles i and j is  m + sqrt(sigma) v  with m the foot of the common chord
// on the line of centres, sigma = h^2 / |c_j - c_i|^2 (h the half chord) and v = +-(the
// centre line turned a quarter counter-clockwise); its coordinates lie in Q(sqrt sigma).
// Nodes are disk centres (R = r, rational) or Voronoi vertices of corners (R^2 in the
// field of its three defining corners; R itself a square root that may not denest).
// Contract: corner ids and node data come from disk_union_axis.
// Complexity: O(1) per predicate or value; exact values are built lazily and cached.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry2/lazy_point.h"
#include "medial2/disks/disks.h"
#include "medial2/medial_graph.h"
#include "number/ball.h"
#include "number/exact_sum.h"

namespace grassfire {

struct BallPoint {
  Ball x, y;
};

struct UnionCorner {
  std::array<std::uint32_t, 2> disk{};  // the two circles through the corner: i, j
  mpq_class mx, my, vx, vy, sigma;      // the corner is (mx, my) + sqrt(sigma) (vx, vy)
  // On circle disk[k], walking counter-clockwise: +1 when a boundary arc of that circle
  // starts at the corner, -1 when one ends there.
  std::array<int, 2> role{};
  IntervalPoint2 approx;
};

// A boundary arc: counter-clockwise on the circle of `disk` from corner `start` to `end`.
struct UnionArc {
  std::uint32_t disk = 0, start = 0, end = 0;
};

// The corner of circles i, j on the side s (+1: left of c_i -> c_j), or nullopt when the
// circles do not cross (tangent circles give sigma = 0: `tangent` is set).
std::optional<UnionCorner> circle_crossing(const std::vector<Disk>& disks, std::uint32_t i, std::uint32_t j, int s,
                                           bool* tangent = nullptr);
ExactSum corner_x(const UnionCorner& c);
ExactSum corner_y(const UnionCorner& c);

// Exact predicates on corners: an interval filter, then the exact sign.
class CornerPredicates {
 public:
  explicit CornerPredicates(const std::vector<UnionCorner>& corners) : c_(&corners) {}
  int orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  // > 0 when d is inside the circle through a, b, c (counter-clockwise), 0 on it.
  int in_circle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const;
  int compare_x(std::uint32_t a, std::uint32_t b) const;
  int compare_y(std::uint32_t a, std::uint32_t b) const;
  // Counter-clockwise angular order of corners a, b around the centre of `disk`,
  // starting from the direction +x: -1 when a comes first.
  int compare_angle(const Disk& disk, std::uint32_t a, std::uint32_t b) const;
  const NumberStats& stats() const { return stats_; }

 private:
  const std::vector<UnionCorner>* c_;
  mutable NumberStats stats_;
};

enum class UnionNodeKind : std::uint8_t { Center, Vertex };

struct UnionNodeData {
  UnionNodeKind kind = UnionNodeKind::Vertex;
  std::uint32_t disk = 0;               // Center: the disk whose centre it is
  std::vector<std::uint32_t> corners;   // its closest corners, sorted (a Center also has its arcs)
};

struct UnionEdgeData {
  std::uint32_t a = 0, b = 0;  // the two corners closest to every point of the edge
};

class DiskUnionGeometry : public MedialGeometry {
 public:
  DiskUnionGeometry(DiskList disks, std::vector<UnionCorner> corners, std::vector<UnionArc> arcs,
                    std::vector<UnionNodeData> nodes, std::vector<std::pair<std::uint32_t, std::uint32_t>> ends,
                    std::vector<UnionEdgeData> edges);

  ExactSum exact_radius(std::uint32_t node) const override;
  ExactSum exact_length(std::uint32_t edge) const override;
  std::string description() const override { return "exact medial axis of a union of disks"; }

  // Exact coordinates of a node (a Voronoi vertex: in the field of its corners).
  const std::array<ExactSum, 2>& exact_position(std::uint32_t node) const;
  // R^2 exactly, without constants.
  ExactSum exact_squared_radius(std::uint32_t node) const;
  // Certified double enclosures, for the graph.
  IntervalPoint2 position_enclosure(std::uint32_t node) const;
  Interval radius_enclosure(std::uint32_t node) const;
  Interval length_enclosure(std::uint32_t edge) const;

  const DiskList& disks() const { return disks_; }
  const std::vector<UnionCorner>& corners() const { return corners_; }
  const std::vector<UnionArc>& arcs() const { return arcs_; }
  const UnionNodeData& node_data(std::uint32_t n) const { return nodes_[n]; }
  const UnionEdgeData& edge_data(std::uint32_t e) const { return edges_[e]; }
  std::uint32_t node_count() const { return static_cast<std::uint32_t>(nodes_.size()); }

 private:
  DiskList disks_;
  std::vector<UnionCorner> corners_;
  std::vector<UnionArc> arcs_;
  std::vector<UnionNodeData> nodes_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_;
  std::vector<UnionEdgeData> edges_;
  BallPoint ball_position(std::uint32_t node) const;  // at the current Arb precision
  // The circumcentre of a Voronoi vertex and R^2, both in the field of its corners.
  void solve_vertex(std::uint32_t node) const;
  mutable std::vector<std::optional<std::array<ExactSum, 2>>> positions_;
  mutable std::vector<std::optional<ExactSum>> squared_radii_;
  mutable std::vector<std::optional<ExactSum>> radii_;
  mutable std::vector<std::optional<ExactSum>> lengths_;
};

}  // namespace grassfire
