// discrete_query.h -- the discrete baseline's burning time at any point of the complex.
//
// Computes: an upper bound on BT at a point x of the complex from a finished
// DiscreteBurning (docs/design.md 5), by one more step of the baseline's own rule at x, as if x
// were a graph point joined to the graph points of its closed triangles:
//  - x at a vertex, or exactly at a Steiner point: that point's discrete BT;
//  - x inside a triangle t: the first arrival, min over the graph points y on t's boundary
//    (vertices and Steiner points) and the sources s in closed t of BT(y) + |x - y| and
//    t0(s) + |x - s| (an interior point burns at its first arrival);
//  - x inside an edge e: per element of the link of x (along e from either side; through
//    each triangle of e) the first arrival, from the nearest graph points on e on either
//    side and from the sources on e, and across each triangle from the graph points on its
//    two other edges and the sources in it off e; then the link rule
//    (MedialComplex::edge_link_burns: on a singular edge with k sheets the (k-1)-th sector
//    arrival or the first arrival along e); on a border edge min(f(x), first arrival);
//  - a source located exactly at x: at most its t0.
// Why an upper bound: each arrival is the time of a straight, non-crossing path from a
// burned point, and the discrete BT of the graph points is itself an upper bound (up to
// double rounding; discrete_burning.h), so by Definition 9 x burns no later.
// Contract: `sources` are the ones the burning ran with; x is a located point (its point
// lies on the complex; snap_squared, the distance of what was located, is not used).
// Complexity: O(graph points on the boundary of the triangles holding x + sources).
#pragma once

#include <vector>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/point_sources.h"
#include "complex3/point_location.h"

namespace grassfire {

double discrete_burning_time_at(const MedialComplex& mc, const DiscreteBurning& d,
                                const std::vector<PointSource>& sources, const ComplexPoint& x);

}  // namespace grassfire
