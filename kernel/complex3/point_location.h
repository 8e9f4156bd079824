// point_location.h -- where a point of R^3 lies on a medial complex, exactly.
//
// Computes: for a rational point q, the nearest point x of the complex (its triangles,
// dangling segments and isolated vertices, all closed), as the cell whose relative
// interior holds x: a vertex, the inside of an edge (with its exact parameter), or the
// inside of a triangle (with its exact barycentric coordinates), and the exact squared
// distance |q - x|^2 (0 exactly when q lies on the complex). Every coordinate of the
// nearest point of a closed triangle or segment to a rational point is rational (it is a
// projection), so the location is exact: no tolerance anywhere.
// Method: a certified filter and exact evaluation. The cells' bounding boxes (interval
// enclosures of their vertices) sit in a bounding volume hierarchy (box_tree3.h), searched
// best first from q: per cell met, an interval lower bound on the squared distance from q
// to its box, then an interval enclosure of the squared distance to the cell itself
// (closest_point3.h; when its region tests are not certified, the box bound and the
// distance to a vertex); the search stops when every box left is certifiably farther than
// the smallest upper bound. The cells whose lower bound does not exceed that upper bound
// (usually one) are evaluated exactly (closest point on a triangle by the region tests of
// Ericson, Real-Time Collision Detection 5.1.5, in rationals), in order of their lower
// bound, until the lower bound exceeds the best exact distance. Ties (two distinct nearest
// points) go to the cell that comes first: triangles by index, then segments, then
// isolated vertices. locate_by_scan is the definition-level reference (every cell's box
// bound, no tree) that tests and bench_complex_build compare with.
// Contract: a validated MedialComplex with at least one vertex, which outlives the locator.
// Complexity: construction O(cells log cells); a query O(log cells + m) interval
// operations for the m cells near the nearest distance, plus O(k) exact closest-point
// evaluations for the k cells that the filter cannot exclude (k = 1 unless q is nearly
// equidistant from several cells); locate_by_scan O(cells).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "geometry3/box_tree3.h"
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
  ~ComplexLocator();
  ComplexPoint locate(const ExactPoint3& q) const;
  // The same answer by scanning every cell (the reference).
  ComplexPoint locate_by_scan(const ExactPoint3& q) const;
  const MedialComplex& complex() const { return mc_; }

 private:
  struct Cell {
    std::uint8_t dimension;  // 0 isolated vertex, 1 segment, 2 triangle
    std::uint32_t id;        // vertex, edge or triangle id
    std::array<Interval, 3> box;
  };
  ComplexPoint closest_in(const Cell& c, const ExactPoint3& q) const;
  std::uint32_t corner(const Cell& c) const;
  Interval enclosed_distance(const Cell& c, const std::array<Interval, 3>& qi, double box_lower) const;
  ComplexPoint nearest_of(std::vector<std::pair<double, std::size_t>>& order, const ExactPoint3& q) const;

  const MedialComplex& mc_;
  std::vector<std::array<Interval, 3>> vertex_box_;  // enclosure of every vertex
  std::vector<Cell> cells_;
  std::unique_ptr<BoxTree3> tree_;
};

// The point of an edge at exact parameter s (0 <= s <= 1), normalised: a vertex at the
// ends, else the edge interior. The point of a triangle at exact barycentric weights
// (summing to 1, each >= 0), normalised to the cell holding it.
ComplexPoint point_on_edge(const MedialComplex& mc, std::uint32_t e, const mpq_class& s);
ComplexPoint point_in_triangle(const MedialComplex& mc, std::uint32_t t, const std::array<mpq_class, 3>& w);

// The triangles whose closure holds x (a vertex: its triangles; an edge: its triangles).
std::vector<std::uint32_t> triangles_containing(const MedialComplex& mc, const ComplexPoint& x);

}  // namespace grassfire
