// sampled_geometry.h -- the exact values behind a Voronoi axis of boundary samples.
//
// Computes: R at a node (circumradius of its Delaunay triangle) and the length of an
// edge (distance between two circumcentres) exactly, as square roots of rationals, and
// certified MPFR enclosures of both. A circumcentre of three double points is kept in
// integer form: every double is m * 2^e, so after scaling by the smallest exponent the
// centre is (CX / D, CY / D) * 2^E with integers CX, CY, D. Enclosures then need only
// integer products, one square root and one division (no rational canonicalisation),
// which is what makes the refinement stage of burn-time comparisons cheap.
// Contract: the three points of every node triangle are not collinear.
// Complexity: O(1) big-integer operations per value; circumcentres are memoised.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "medial2/medial_graph.h"

namespace grassfire {

// The circumcentre (CX / D, CY / D) * 2^E of three double points, and the vector
// (X / D, Y / D) * 2^E from the first point to it.
struct IntegerCircumcenter {
  mpz_class cx, cy, x, y, d;
  long exponent = 0;
};
IntegerCircumcenter integer_circumcenter(const Point2& a, const Point2& b, const Point2& c);

class SampledVoronoiGeometry : public MedialGeometry {
 public:
  SampledVoronoiGeometry(std::vector<Point2> samples, std::vector<std::array<std::uint32_t, 3>> node_triangles,
                         std::vector<std::pair<std::uint32_t, std::uint32_t>> edge_ends);

  ExactSum exact_radius(std::uint32_t node) const override;
  ExactSum exact_length(std::uint32_t edge) const override;
  void enclose_radius(std::uint32_t node, mpfr_ptr lo, mpfr_ptr hi) const override;
  void enclose_length(std::uint32_t edge, mpfr_ptr lo, mpfr_ptr hi) const override;
  LongInterval enclose_radius_long(std::uint32_t node) const override;
  LongInterval enclose_length_long(std::uint32_t edge) const override;
  std::string description() const override;

  const std::vector<Point2>& samples() const { return samples_; }
  const std::array<std::uint32_t, 3>& node_triangle(std::uint32_t node) const { return triangles_[node]; }

 private:
  const IntegerCircumcenter& center(std::uint32_t node) const;
  // length^2 = num / den^2 * 4^scale, for radius (node) or edge.
  struct SquaredLength {
    mpz_class num, den;
    long scale;
  };
  SquaredLength squared_radius(std::uint32_t node) const;
  SquaredLength squared_length(std::uint32_t edge) const;

  std::vector<Point2> samples_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends_;
  struct LongCircle {
    LongInterval x, y, radius;
    std::uint8_t state = 0;  // 0 not computed, 1 valid, 2 degenerate (use the exact path)
  };
  const LongCircle& long_circle_of(std::uint32_t node) const;

  // By node, on demand: the burning engine asks for few of them (near-ties only).
  mutable std::unordered_map<std::uint32_t, IntegerCircumcenter> centers_;
  mutable std::unordered_map<std::uint32_t, LongCircle> long_circles_;
};

}  // namespace grassfire
