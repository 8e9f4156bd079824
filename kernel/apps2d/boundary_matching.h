// boundary_matching.h -- boundary signatures of a planar shape and a dynamic-programming
// correspondence of two closed boundaries guided by them (3.5.3, Fig. 3.9).
//
// Computes:
//  - BoundarySignature: uniform arc-length samples of the outer boundary
//    (shapes/resample.h) with one value per sample. Signatures: the discrete curvature
//    (turning angle at the sample over the mean length of its two chords; Fig. 3.9a), the
//    local feature size LFS (distance from the sample to the nearest point of the medial
//    axis, apps2d/axis_correspondence.h; Fig. 3.9b), and boundary eccentricity BE (3.5.3;
//    Fig. 3.9c,d) from burn2/boundary_eccentricity.h: BE is defined per sample of a
//    sampled axis, so the axis is built from `refine` times more samples than the
//    signature keeps (every refine-th, the same points as boundary_samples); a sample
//    closest to no medial node takes the value of the nearest sample that has one, in
//    ring order (counted in `filled`).
//  - match_signatures: a correspondence between samples a_0..a_{n-1} of one closed curve
//    and b_0..b_{m-1} of another, both in the same orientation. For every start offset o
//    of b (cyclic alignment: a_0 is matched to b_o), a monotone lattice path from (0, o)
//    to (n-1, o+m-1) (indices of b mod m) with steps (1,1), (1,0), (0,1) minimising
//        sum over the path's cells (i, j) of |a'_i - b'_j|  +  stretch * (number of (1,0)
//        and (0,1) steps),
//    where a' and b' are the signatures divided by their maxima (normalised to [0, 1],
//    so that shapes of different size compare; `normalise = false` keeps raw values) and
//    `stretch` penalises one curve advancing while the other waits. The best offset wins;
//    ties go to the smallest offset and, along the path, to the diagonal step, so a curve
//    matched with itself gives the identity (offset 0, the diagonal).
//  - match_signatures_reference: the definition: every monotone path for every offset
//    enumerated (Delannoy many), for tests on tiny inputs.
// Exactness: values and costs are doubles (measurement: a correspondence, no geometric
// decision); the tie rules above make the result deterministic.
// Contract: a and b non-empty, finite, and for normalisation with a positive maximum.
// Complexity: match_signatures O(n m^2) time, O(n m) memory; the reference O(m D(n, m)).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "geometry2/shape2.h"

namespace grassfire {

struct BoundarySignature {
  std::vector<Point2> points;  // samples of the outer ring in order (counter-clockwise)
  std::vector<double> values;  // one per sample
  std::size_t filled = 0;      // values taken from a neighbour (BE: no medial point)
};

// `samples` uniform arc-length samples of the outer ring, with empty values.
BoundarySignature boundary_samples(const Shape2& shape, std::size_t samples);
// Discrete curvature at every sample (positive where the boundary turns left: convex).
std::vector<double> curvature_signature(const std::vector<Point2>& closed_curve);
// Distance from every point to the nearest point of the medial graph (the axis of the shape).
std::vector<double> local_feature_size(const std::vector<Point2>& points, const MedialGraph& axis);
// Boundary eccentricity at `samples` boundary samples (see above). The shape must be simply
// connected (3.5.3); std::invalid_argument otherwise, naming the shape.
BoundarySignature eccentricity_signature(const Shape2& shape, std::size_t samples, std::size_t refine = 5);
// Indices of the local maxima of a cyclic signature: values at least as large as every
// other within `window` samples on either side (the first of equal neighbours only).
std::vector<std::uint32_t> signature_maxima(const std::vector<double>& values, std::size_t window);

struct MatchOptions {
  double stretch = 0.05;  // cost of one non-diagonal step, in normalised signature units
  bool normalise = true;
};

struct BoundaryMatch {
  std::uint32_t offset = 0;  // the sample of b matched to a_0
  // The path as pairs (i, j): sample i of a corresponds to sample j of b (j already taken
  // mod m, i.e. an index into b), from (0, offset) to (n - 1, offset + m - 1 mod m).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> path;
  double cost = 0;
  std::uint64_t stretch_steps = 0;
};

BoundaryMatch match_signatures(const std::vector<double>& a, const std::vector<double>& b,
                               const MatchOptions& options = {});
BoundaryMatch match_signatures_reference(const std::vector<double>& a, const std::vector<double>& b,
                                         const MatchOptions& options = {});

// For each sample i of a, the sample of b it is matched to first along the path.
std::vector<std::uint32_t> correspondence_of(const BoundaryMatch& m, std::size_t n);

}  // namespace grassfire
