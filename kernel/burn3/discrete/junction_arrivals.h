// junction_arrivals.h -- fire arrivals along a singular curve, per sheet, and kinks (4.2.1).
//
// Computes: for every graph point of the discrete baseline that lies on a given chain of
// singular edges (vertices and Steiner points), its arclength t from the chain's start,
// its burn time, and the first arrival time through each sheet-side that meets the curve
// (sides are named by a caller's labelling of triangles, e.g. back / front / fin on the
// board and fin); and the kinks: the points where the order of arrival of two labelled
// sides changes (the pair of sheets on which BT is continuous changes there, Fig. 4.4),
// located by linear interpolation of the arrival difference between neighbouring points.
// Contract: `chain` is a path of edges given from its start vertex, in order; labels are
// small non-negative integers (< 8). Complexity: O(points on the chain * sides).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "burn3/discrete/discrete_burning.h"

namespace grassfire {

struct CurvePointArrivals {
  double t = 0.0;          // arclength from the chain's start
  Vec3d position{};
  double bt = 0.0;
  std::array<double, 8> side_arrival;  // per label; kInfinity when no arrival before burning
};

std::vector<CurvePointArrivals> arrivals_along_curve(const MedialComplex& mc, const DiscreteBurning& d,
                                                     std::uint32_t start_vertex, const std::vector<std::uint32_t>& chain,
                                                     const std::function<int(std::uint32_t triangle)>& label);

// Arclengths where arrival(a) - arrival(b) changes sign (both arrivals finite on both sides).
std::vector<double> kinks_along_curve(const std::vector<CurvePointArrivals>& points, int a, int b);

// The singular edges met walking from `start` along singular edges (first unused one at
// each vertex), in order: the curve N of the board and fin from c.
std::vector<std::uint32_t> singular_curve_from(const MedialComplex& mc, std::uint32_t start);

}  // namespace grassfire
