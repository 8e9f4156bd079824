// planar_sheet_reference.h -- the burning time of one planar sheet, from its definition.
//
// Computes: on a complex that is one planar sheet (all triangles coplanar, any shape:
// non-convex, with holes, pinched at vertices), with any border rules,
//     BT(x) = min over border points y of d_sheet(x, y) + f(y)
// (4.2.3, the remark after Definition 10: on a manifold the burning time is the
// distance-plus-ignition minimum), d_sheet the length of the shortest path inside the
// closed sheet. Shortest paths in a polygonal domain are polygonal and bend only at
// reflex border vertices (interior angle > pi) or at pinch vertices, so:
//  - nodes: the reflex and pinch border vertices;
//  - visibility: a segment lies in the closed sheet iff a walk along it through the
//    triangles never leaves through a border edge; every step is an exact orientation
//    test on the rational plane coordinates of the sheet's frame (medial_complex.h);
//  - direct(x) = min over border edges e of min over the part of e visible from x of
//    |x - y| + f(y). Visibility along e changes only where the line from x through a
//    node visible from x meets e (a shadow boundary grazes a node), so e splits at those
//    rational parameters into pieces that are wholly visible or not (tested exactly at
//    each piece's midpoint and ends), and each visible piece gives a closed-form minimum
//    (border_edge_minimum.h);
//  - node values g = direct, relaxed over the visibility graph by |v - w| for n rounds of
//    Bellman-Ford (every shortest path has at most n - 1 bends);
//  - BT(x) = min(direct(x), min over nodes w visible from x of g(w) + |x - w|).
// Values are Arb balls at `bits` of precision: every printed value carries a certified
// enclosure (the combinatorics, visibility, is exact). +infinity where nothing ignites.
// Contract: one sheet, planar, no dangling segment, no singular edge, every vertex on a
// triangle (std::invalid_argument otherwise); query points lie on the sheet.
// Complexity: construction O(n^2 W + n B (n + 2) W) exact operations with n nodes, B
// border edges and W the triangles a walk visits; a query O(B (n + 2) W + n W).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "burn3/border_edge_minimum.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "number/ball.h"
#include "number/interval.h"

namespace grassfire {

class PlanarSheetReference {
 public:
  explicit PlanarSheetReference(const MedialComplex& mc, long bits = 128);

  // A certified enclosure of BT at x ([inf, inf] where nothing reaches it).
  Interval burning_time(const ComplexPoint& x) const;
  // The nodes (reflex and pinch border vertices), for tests.
  const std::vector<std::uint32_t>& nodes() const { return nodes_; }
  // Whether the segment between two points of the sheet lies in the closed sheet.
  bool visible(const ComplexPoint& a, const ComplexPoint& b) const;

 private:
  struct SheetPoint {
    std::array<mpq_class, 2> uv;  // in the sheet's frame
    ExactPoint3 p;
    std::vector<std::uint32_t> triangles;  // the closed triangles holding it
  };
  SheetPoint sheet_point(const ComplexPoint& x) const;
  SheetPoint vertex_point(std::uint32_t v) const;
  bool visible(const SheetPoint& from, const SheetPoint& to) const;
  bool is_node(std::uint32_t v) const;
  // min over border points visible from x of |x - y| + f(y); nullopt when none ignites.
  std::optional<Ball> direct(const SheetPoint& x, const std::vector<char>& node_visible) const;
  std::optional<Ball> evaluate(const SheetPoint& x) const;

  const MedialComplex& mc_;
  long bits_;
  std::vector<std::array<mpq_class, 2>> uv_;     // per vertex
  std::vector<std::array<std::uint32_t, 3>> ccw_;  // per triangle, counter-clockwise in uv
  std::vector<std::uint32_t> border_;            // border edges
  std::vector<IgnitedEdge> ignited_;             // per border edge
  std::vector<std::uint32_t> nodes_;
  std::vector<std::optional<Ball>> node_value_;  // g
};

}  // namespace grassfire
