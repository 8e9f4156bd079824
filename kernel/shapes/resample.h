// resample.h -- uniform arc-length samples of the boundary of a shape, the point set whose
// Voronoi diagram approximates the medial axis (dissertation 2.1.2, 3.3.2).
//
// Computes: for every ring r, m_r >= 8 sample points in ring order. How positions are
// computed, all in double precision: ring r has vertices p_0 .. p_{n-1} (the closing edge
// is p_{n-1} p_0), edge lengths len_i = hypot(p_{i+1} - p_i), prefix sums C_0 = 0,
// C_{i+1} = C_i + len_i, and length L = C_n. Sample k (0 <= k < m_r) has arc length
// t_k = (L * k) / m_r; it lies on the last edge i with C_i <= t_k, at
// s_k = p_i + f (p_{i+1} - p_i), f = min(1, (t_k - C_i) / (C_{i+1} - C_i)) (f = 0 if that
// difference is 0, possible only on the last edge), coordinate by coordinate.
// So s_0 = p_0 exactly, and consecutive samples are L / m_r apart along the ring (up to
// rounding), across vertices.
// Sample counts:
//   - by total N (resample_by_count): ring r gets m_r = max(8, floor(N L_r / L)), L the sum
//     of the ring lengths; then one sample at a time, rings with the largest fractional
//     part of N L_r / L gain a sample while the total is below N, and rings above 8 with
//     the largest surplus m_r - N L_r / L lose one while it is above N (the minimum of 8
//     can push it above). The total is exactly N; N >= 8 * rings is required.
//   - by spacing h (resample_by_spacing): m_r = max(8, ceil(L_r / h)), so samples are at
//     most h apart along each ring.
// Errors: std::invalid_argument for a bad N or h, or more than 10^9 samples in total;
// std::runtime_error (naming the shape, ring and samples) when two samples coincide as
// doubles (e.g. N huge for a tiny ring): the returned samples are always pairwise distinct.
// Contract: a validated shape (shapes/validate_shape.h).
// Complexity: O(n + M log M) for n vertices and M samples (the distinctness check sorts).
#pragma once

#include <cstddef>
#include <vector>

#include "geometry2/shape2.h"

namespace grassfire {

constexpr std::size_t kMinSamplesPerRing = 8;
constexpr std::size_t kMaxSamples = 1000000000;

// Per ring, its samples in ring order; samples[r][0] is vertex 0 of ring r. Consecutive
// samples of ring r are ring_length(ring r) / samples[r].size() apart along the ring.
using BoundarySamples = std::vector<std::vector<Point2>>;

BoundarySamples resample_by_count(const Shape2& shape, std::size_t total);
BoundarySamples resample_by_spacing(const Shape2& shape, double spacing);

// Perimeter of a ring as the double sum of std::hypot edge lengths, the L_r above.
double ring_length(const Ring& ring);

}  // namespace grassfire
