// union_of_balls_reference.h -- the medial axis of a union of balls, checked against its
// definition: exact distances to the union's boundary by brute force.
//
// Computes, independently of the regular triangulation:
//  - the vertices of the boundary of U by brute force over all triples of balls (a point
//    on three spheres outside every other ball), compared with the builder's list;
//  - for a point x given exactly (homogeneous coordinates over the builder's radicals),
//    the distance to the boundary of U as the minimum over all boundary features: the
//    vertices; on each circle S_i ∩ S_j the point nearest to x (in x's meridian half-plane
//    about the axis c_i c_j; the whole circle when x is on the axis); on each sphere the
//    radial point c_i + r_i (x - c_i)/|x - c_i| (the whole sphere when x = c_i); each
//    point counted only when no other ball contains it (pow_l >= 0);
//  - whether x is a medial point: the claimed radius R(x) is attained, nothing is closer,
//    and two or more distinct boundary points (or a continuum) attain it.
// Every comparison is exact: squared distances are of the form a + b sqrt(c) over the
// field of x (number/multiquadratic.h: sign_plus_root, sign_two_roots), and an interval filter
// skips features that are certainly farther.
// Contract: the axis was built from these balls. Complexity: O(n^2 + |V|) features per
// point, O(n) exact tests for each feature within the filter's reach; meant for tests on
// sets of up to a few dozen balls.
#pragma once

#include <string>

#include "medial3/convex/convex_polyhedron_axis.h"  // DefinitionCheck
#include "medial3/balls/union_of_balls_axis.h"

namespace grassfire {

// Brute-force boundary vertices equal the builder's (as labelled exact points).
bool same_boundary_vertices(const BallSet& balls, const UnionOfBallsAxis& axis, std::string* why);

// Checks every vertex of the axis and every polygon sample: each lies in the union and
// has R(x) equal to its distance to the boundary, attained at two or more points.
DefinitionCheck check_union_axis(const BallSet& balls, const UnionOfBallsAxis& axis);

}  // namespace grassfire
