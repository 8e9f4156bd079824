// burning_paths.h -- sets of burning paths to export and draw (5.1.2, Fig. 5.2).
//
// Computes, from a BurningField (burning_field.h), the burning paths of chosen points: the
// polyline the fire followed to reach the point, traced back to where it started (a border
// point burning at its own f, or a source):
//  - from every vertex of the complex (the path of the vertex's own BT);
//  - from every node of a medial curve graph (medial_curves.h): the path of the node's own
//    BT, and the paths that end at the nodes (the arriving sides' paths);
//  - from given points of the complex, each with the cell (triangle or dangling segment)
//    holding it: the path seen from that cell (on a singular curve the side matters).
// Each path carries BT at its first point and its length; along a path BT decreases at
// unit rate, so BT = f(start) + length for the exact field, and for the baseline up to
// double rounding (its BT is the sum of its moves).
// Contract: a field over a validated complex; points lie in (or within rounding of) their
// cell. Complexity: O(total path points).
#pragma once

#include <cstdint>
#include <vector>

#include "burn3/burning_field.h"
#include "burn3/medial_curves.h"

namespace grassfire {

struct BurningPath {
  std::vector<Vec3d> points;  // points[0]: where the path ends (the chosen point)
  double bt = 0;              // BT at points[0] (+infinity: never burns, a single point)
  double length = 0;
};

struct CellPoint {
  bool on_segment = false;  // a dangling segment (cell = edge id, parameter s) or
  std::uint32_t cell = 0;   // a triangle (cell = triangle id, point p)
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

// The nearest point of the complex to q (its triangles and dangling segments; isolated
// vertices are skipped), in doubles: the located point and the cell holding it. For
// drawing and for --points in paths3d; `distance` says how far q was.
CellPoint nearest_cell_point(const MedialComplex& mc, const Vec3d& q, double* distance);

}  // namespace grassfire
