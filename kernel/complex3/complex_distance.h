// complex_distance.h -- Hausdorff distance between two embedded 2-complexes in R^3, as a
// measurement (how far a sampled medial axis is from an exact one; 2.1.2).
//
// Computes: the directed distance from A to B, the largest over points x of |A| of the
// distance from x to |B| (|.| the union of the triangles, segments and vertices), and the
// symmetric Hausdorff distance, the larger of the two directions. A is sampled: its
// vertices, its segments every `step`, its triangles on a barycentric grid of spacing at
// most `step`; the distance from a sample to |B| is exact up to rounding (CGAL AABB trees
// on the double coordinates of B). So the directed value is a lower bound of the true one,
// short of it by at most step (the distance to |B| is 1-Lipschitz).
// Doubles: a measurement for tests and studies, never a combinatorial decision.
// Optionally each point of A carries a weight w(x) in [0, 1] (interpolated from per-vertex
// values) and only points with w(x) >= w_min count: the directed distance from the part of
// A where w is large (e.g. the exact axis where its sheets are resolvable at a spacing).
// Contract: B has at least one vertex; step > 0.
// Complexity: O(S log |B|) for S samples of A (about area / step^2).
#pragma once

#include <functional>
#include <vector>

#include "complex3/raw_complex.h"

namespace grassfire {

double directed_complex_distance(const RawComplex& a, const RawComplex& b, double step);
double complex_hausdorff(const RawComplex& a, const RawComplex& b, double step);
// The directed distance over the points of A whose interpolated per-vertex value
// (vertex_value, one per vertex of A) is at least `at_least`; 0 when there is none.
double directed_complex_distance(const RawComplex& a, const std::vector<double>& vertex_value, double at_least,
                                 const RawComplex& b, double step);

}  // namespace grassfire
