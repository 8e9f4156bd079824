// curve_distance.h -- Hausdorff distance between two medial curve graphs (5.1.3).
//
// Computes: the directed distance from graph A to graph B, the largest over points of A of
// the distance to the nearest point of B (A's edges sampled every `step`, and A's nodes;
// B's edges as segments), and the symmetric Hausdorff distance, the larger of the two
// directions. A graph without edges is its nodes. Doubles; the sampling under-estimates
// the directed distance by at most step / 2.
// Contract: both graphs have at least one node; step > 0.
// Complexity: O(|B| log |B|) to build an AABB tree of B's segments, then O(log |B|)
// expected per sample of A.
#pragma once

#include "curves3/medial_curves.h"

namespace grassfire {

double directed_curve_distance(const MedialCurves& a, const MedialCurves& b, double step);
double curve_hausdorff(const MedialCurves& a, const MedialCurves& b, double step);

}  // namespace grassfire
