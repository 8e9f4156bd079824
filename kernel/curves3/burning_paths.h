// burning_paths.h -- sets of burning paths to export and draw (5.1.2, Fig. 5.2).
//
// Computes, from a BurningField (burning_field.h), the burning paths of chosen points: the
// polyline the fire followed to reach the point, traced back to where it started (a border
// point burning at its own f, or a source):
//  - from every vertex of the complex (the path of the vertex's own BT);
//  - from every node of a medial curve graph (medial_curves.h): the path of the node's own
//    BT, and the paths that end at the nodes (the arriving sides' paths);
//  - from given points of the complex, each with the cell (vertex, triangle or dangling
//    segment) to see it from: the path seen from that cell (on a singular curve the side
//    matters).
// Each path carries BT at its first point and its length; along a path BT decreases at
// unit rate, so BT = f(start) + length for the exact field, and for the baseline up to
// double rounding (its BT is the sum of its moves).
// Contract: a field over a validated complex; points lie in (or within rounding of) their
// cell. Complexity: O(total path points).
#pragma once

#include <cstdint>
#include <vector>

#include "burn3/burning_field.h"
#include "curves3/medial_curves.h"
#include "complex3/point_location.h"

namespace grassfire {

struct BurningPath {
  std::vector<Vec3d> points;  // points[0]: where the path ends (the chosen point)
  double bt = 0;              // BT at points[0] (+infinity: never burns, a single point)
  double length = 0;
};

struct CellPoint {
  enum class Kind : std::uint8_t { Vertex, Segment, Triangle };
  Kind kind = Kind::Triangle;  // a vertex (cell = vertex id), a dangling segment (cell =
  std::uint32_t cell = 0;      // edge id, parameter s) or a triangle (cell = triangle id)
  Vec3d p{};
  double s = 0;
};

std::vector<BurningPath> paths_from_vertices(const BurningField& field);
std::vector<BurningPath> paths_from_curve_nodes(const BurningField& field, const MedialCurves& curves);
// The paths that END on the curves (Fig. 5.2): at a node inside a triangle, its path; at a
// node on an edge of M, the path seen from each triangle of that edge whose fire runs into
// the edge (direction against the triangle's inward conormal at more than asin of
// arrive_cosine: the sides whose fire stops there; medial_curves.h step 1).
std::vector<BurningPath> paths_ending_on_curves(const BurningField& field, const MedialCurves& curves,
                                                double arrive_cosine = 0.5);
std::vector<BurningPath> paths_from_points(const BurningField& field, const std::vector<CellPoint>& points);

// A located point of the complex (complex3/point_location.h) as the cell to see it from:
// a vertex; a point of a dangling segment; a point of a triangle; a point of an edge with
// triangles, seen from the triangle whose side time completes the link rule there (the
// (k-1)-th earliest of k >= 3 sheets, the earliest of one or two), whose path is the
// point's own.
CellPoint cell_point(const BurningField& field, const ComplexPoint& x);

}  // namespace grassfire
