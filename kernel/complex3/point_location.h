// point_location.h -- where a point of R^3 lies on a medial complex, exactly.
//
// Computes: for a rational point q, the nearest point x of the complex (its triangles,
// dangling segments and isolated vertices, all closed), as the cell whose relative
// interior holds x: a vertex, the inside of an edge (with its exact parameter), or the
// inside of a triangle (with its exact barycentric coordinates), and the exact squared
// distance |q - x|^2 (0 exactly when q lies on the complex). Every coordinate of the
// nearest point of a closed triangle or segment to a rational point is rational (it is a
// projection), so the location is exact: no tolerance anywhere.
// Method: a certified filter and exact evaluation. Per cell, an interval lower bound on
// the squared distance from q to the cell's bounding box and an interval upper bound on
// the squared distance to one of its vertices; cells whose lower bound exceeds the
// smallest upper bound cannot hold the nearest point. The others are evaluated exactly
// (closest point on a triangle by the region tests of Ericson, Real-Time Collision
// Detection 5.1.5, in rationals), in order of their lower bound, until the lower bound
// exceeds the best exact distance. Ties (two distinct nearest points) go to the cell that
// comes first: triangles by index, then segments, then isolated vertices.
// Contract: a validated MedialComplex with at least one vertex.
// Complexity: construction O(cells); a query O(cells) interval operations plus O(k) exact
// closest-point evaluations for the k cells that the filter cannot exclude.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <vector>

#include "complex3/medial_complex.h"
#include "number/interval.h"

namespace grassfire {

struct ComplexPoint {
  enum class Kind : std::uint8_t { Vertex, Edge, Triangle };
  Kind kind = Kind::Vertex;
  std::uint32_t id = 0;                  // vertex, edge or triangle id
  ExactPoint3 point;                     // the point of the complex
  mpq_class parameter;                   // Edge: point = (1 - s) v[0] + s v[1], 0 < s < 1
  std::array<mpq_class, 3> barycentric;  // Triangle: weights of t.v[0..2], each > 0
  mpq_class snap_squared;                // squared distance from the located point; 0 on M
  Vec3d approx() const { return to_double(point); }
  double snap() const;                   // sqrt(snap_squared), correctly rounded up to 1 ulp
};

class ComplexLocator {
 public:
  explicit ComplexLocator(const MedialComplex& mc);
  ComplexPoint locate(const ExactPoint3& q) const;
  const MedialComplex& complex() const { return mc_; }

 private:
  struct Cell {
    std::uint8_t dimension;  // 0 isolated vertex, 1 segment, 2 triangle
    std::uint32_t id;        // vertex, edge or triangle id
    std::array<Interval, 3> box;
  };
  ComplexPoint closest_in(const Cell& c, const ExactPoint3& q) const;

  const MedialComplex& mc_;
  std::vector<Cell> cells_;
};

// The point of an edge at exact parameter s (0 <= s <= 1), normalised: a vertex at the
// ends, else the edge interior. The point of a triangle at exact barycentric weights
// (summing to 1, each >= 0), normalised to the cell holding it.
ComplexPoint point_on_edge(const MedialComplex& mc, std::uint32_t e, const mpq_class& s);
ComplexPoint point_in_triangle(const MedialComplex& mc, std::uint32_t t, const std::array<mpq_class, 3>& w);

// The triangles whose closure holds x (a vertex: its triangles; an edge: its triangles).
std::vector<std::uint32_t> triangles_containing(const MedialComplex& mc, const ComplexPoint& x);

}  // namespace grassfire
