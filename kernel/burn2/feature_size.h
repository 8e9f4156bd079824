// feature_size.h -- the local significance measures of 2.2.1 at the nodes of a medial
// graph: the separation angle and the feature size r(x) of the lambda-medial axis
// (Chazal and Lieutier 2005).
//
// Computes, per node x with closest boundary points p_1..p_k (burn2/closest_points.h), all
// at distance R from x:
//  - separation angle theta(x): the largest angle between two rays x -> p_i, x -> p_j
//    (2.2.1: with more than two closest points, the largest of all), in [0, pi]; as the
//    chord |p_i - p_j| = 2 R sin(theta / 2) grows with the angle, theta = 2 asin(c / 2R)
//    for the longest chord c;
//  - feature size r(x): the radius of the smallest circle enclosing the closest points.
//    Points on a circle around x that fit in a half-plane through x are enclosed by the
//    circle on their longest chord, r = c / 2 = R sin(theta / 2); otherwise x lies in
//    their convex hull and r = R. A node with a single closest point (a convex polygon
//    vertex, R = 0) has theta = 0 and r = 0.
// Certification: enclosures throughout (Arb for asin); where a half-plane test is too
// close to call, the enclosure is the hull of both cases (they agree at the boundary,
// where the longest chord is a diameter).
// Contract: cp = closest_points(g, ...). Complexity: O(sum of k^2) over the nodes.
#pragma once

#include <vector>

#include "burn2/closest_points.h"
#include "medial2/medial_graph.h"

namespace grassfire {

struct LocalFeatureMeasures {
  std::vector<Interval> separation_angle;  // per node, radians
  std::vector<Interval> feature_size;      // per node, r(x)
};

LocalFeatureMeasures local_feature_measures(const MedialGraph& g, const ClosestPoints& cp);

}  // namespace grassfire
