// burn3_reference.h -- slow definition-level references for the burning time in 3D.
//
// Computes:
//  - planar_convex_sheet_burning: on a manifold M, BT(x) = min over y in dM of
//    d(x, y) + f(y) (4.2.3, the remark after Definition 10). For a single planar convex
//    sheet d is the Euclidean distance, and along each border edge d + f is convex in the
//    edge parameter (f linear, or the distance to a point), so a ternary search per edge
//    finds the minimum to ~1e-12: a brute force over every border edge. It also returns
//    the foot y attaining the minimum.
//  - summarize_error: the deviation of the discrete baseline from a reference function
//    over its graph points (vertices and Steiner points) in a region, with the counts a
//    caller asserts: points considered, compared, and where one side only is infinite
//    (a failure: summarize_error never drops such a point silently).
// Contract: planar_convex_sheet_burning needs a complex with one planar convex sheet and x
// in it (checked: std::invalid_argument otherwise, except convexity, which is the
// caller's). Complexity: O(border edges * 200) per query; summarize_error O(points).
#pragma once

#include <cstdint>
#include <functional>

#include "burn3/discrete/discrete_burning.h"
#include "complex3/medial_complex.h"

namespace grassfire {

struct SheetBurningTime {
  double time = 0.0;  // min over the border of d(x, y) + f(y)
  Vec3d foot{};       // a border point y attaining it
  std::uint32_t foot_edge = 0;
};
SheetBurningTime planar_convex_sheet_burning(const MedialComplex& mc, const Vec3d& x);
double planar_convex_sheet_burning_time(const MedialComplex& mc, const Vec3d& x);

struct ErrorSummary {
  std::uint64_t considered = 0;          // graph points inside the region
  std::uint64_t points = 0;              // compared: both values finite
  std::uint64_t both_infinite = 0;       // agree: nothing burns there
  std::uint64_t one_sided_infinite = 0;  // disagree: one value finite, the other infinite
  double max_error = 0.0;    // max |BT_discrete - BT| over the compared points
  double mean_error = 0.0;   // mean |BT_discrete - BT|
  double min_error = 0.0;    // min (BT_discrete - BT): >= -rounding for an upper bound
  Vec3d worst_point{};
};

ErrorSummary summarize_error(const MedialComplex& mc, const DiscreteBurning& d,
                             const std::function<double(const Vec3d&)>& reference,
                             const std::function<bool(const Vec3d&)>& inside);

}  // namespace grassfire
