// union_alpha_complex.h -- the power diagram of a union of balls, its dual (alpha) complex
// at alpha = 0, and the vertices of the union's boundary; all exact.
//
// Computes, for balls B_i = (c_i, r_i) with power functions pow_i(x) = |x - c_i|^2 - r_i^2:
//  - the regular triangulation (CGAL Regular_triangulation_3 on the exact centres and
//    weights r_i^2; regular_triangulation.cpp), as plain combinatorics;
//  - per simplex sigma its power centre z (the point of aff(sigma) with equal power to its
//    balls), that power w, and rho = min of pow_sigma over the dual face F_sigma, which is
//    w when z lies in F_sigma and else the minimum of rho over the cofaces (the
//    alpha-shape recursion of Edelsbrunner 1995, with F_sigma bounded by the half-spaces of
//    its link vertices). The dual complex K = {sigma : rho < 0} collects the simplices whose
//    dual face meets the interior of the union, which is {min pow < 0} plus the points
//    with min pow = 0 whose balls surround them (interior_of_union below: eight balls of
//    radius sqrt 3 on the cube corners cover the centre although none contains it in its
//    interior). So balls that touch only at tangency points (a ball internally tangent to
//    another, two balls touching from outside) add nothing, as the medial axis requires,
//    and K is homotopy equivalent to the interior of the union (Edelsbrunner 1995).
//  - the vertices of the boundary of the union: for each triangle t = (i, j, k) the points
//    z_t +- sqrt(s) n_t (n_t = (c_j - c_i) x (c_k - c_i), s = -w_t / |n_t|^2) where the three
//    spheres meet, kept when they lie on the dual power edge of t (no other ball contains
//    them) and the balls through them do not surround them; a point found from several
//    triangles (on four or more spheres) is kept once.
// Contract: balls with positive squared radii (std::invalid_argument otherwise), at least
// one ball. Complexity: O(n log n) for the triangulation (expected) and for sorting the
// simplices and their facets (the face/coface index), then O(1) exact work per simplex
// (power centres over the integers, union_alpha_complex.cpp).
// Section: 2.1.1 (union of balls: Attali-Montanvert; Amenta-Kolluri 2001).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "geometry3/ball_set.h"
#include "number/multiquadratic.h"

namespace grassfire {

// The finite simplices of the regular triangulation, as sorted ball ids, each list sorted.
struct RegularTriangulation {
  int dimension = -1;
  std::vector<std::uint32_t> vertices;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  bool exact_double_kernel = false;  // every input value was a double: CGAL Epick sufficed
};
RegularTriangulation regular_triangulation(const BallSet& balls);

// The baseline of the benchmarks: CGAL's Regular_triangulation_3 construction alone on the
// same weighted points (same kernel choice); returns its number of finite cells.
std::size_t cgal_regular_triangulation_cells(const BallSet& balls);

// Seeded random balls for tests and benchmarks: n centres uniform on a grid of 4096 steps
// in [0, 1.6 n^(1/3)]^3 and radii uniform in [0.8, 1.2) (all dyadic, so exact as doubles):
// one ball per volume 4.1, so the balls overlap into one body with tunnels and voids.
BallSet random_ball_set(std::size_t n, unsigned seed);

// CGAL Fixed_alpha_shape_3 at alpha = 0 (closed convention: rho <= 0), as sorted simplices
// (vertices as {i, -}, padded with UINT32_MAX), for cross-checking; triangulations of
// dimension 3 only (empty otherwise).
std::vector<std::array<std::uint32_t, 4>> cgal_alpha_complex(const BallSet& balls);

struct PowerSimplex {
  std::array<std::uint32_t, 4> balls{};  // sorted; the first dim + 1 are used
  int dim = 0;
  std::vector<std::uint32_t> cofaces;    // finite simplices of dimension dim + 1
  std::array<Interval, 3> approx_centre;  // enclosures of z and w
  Interval approx_power;
  bool exact = false;                    // centre and power below are set
  ExactPoint3 centre;                    // power centre z
  mpq_class power;                       // w = pow_i(z) for the balls i of the simplex
  std::uint32_t rho_simplex = 0;         // rho (min of the power over the dual face) = its w
};

class AlphaComplex {
 public:
  AlphaComplex(const BallSet& balls, const RegularTriangulation& rt);

  std::size_t ball_count() const { return ball_count_; }
  int dimension() const { return dimension_; }
  std::size_t hidden_balls() const { return hidden_; }
  const std::vector<PowerSimplex>& simplices() const { return simplices_; }
  // The simplex with its exact power centre and power (computed on first use).
  const PowerSimplex& exact(std::uint32_t s) const;
  const std::vector<std::uint32_t>& of_dimension(int d) const { return by_dim_[d]; }
  bool in_complex(std::uint32_t s) const { return in_complex_[s]; }
  bool in_closed_complex(std::uint32_t s) const { return rho_sign_[s] <= 0; }
  int power_sign(std::uint32_t s) const;  // exact sign of w
  std::size_t exact_simplices() const { return exact_count_; }  // filter failures
  // Certified enclosures of ball i's centre and squared radius.
  const std::array<Interval, 3>& approx_ball(std::uint32_t i) const { return approx_ball_[i]; }
  const Interval& approx_weight(std::uint32_t i) const { return approx_weight_[i]; }
  // In K, dimension < 3 and no coface in K: a maximal lower-dimensional simplex.
  bool is_singular(std::uint32_t s) const;
  // The simplex with these sorted balls (dim + 1 of them), or UINT32_MAX.
  std::uint32_t find(const std::array<std::uint32_t, 4>& balls, int dim) const;

 private:
  void add_simplices(const RegularTriangulation& rt);
  void approximate_centres();
  void compute_rho();
  // Exact signs, after an interval filter: pow_j(z_s) - w_s, and w_a - w_b.
  int link_sign(std::uint32_t s, std::uint32_t j) const;
  int compare_powers(std::uint32_t a, std::uint32_t b) const;

  const BallSet* balls_;
  std::vector<std::array<Interval, 3>> approx_ball_;
  std::vector<Interval> approx_weight_;
  std::vector<bool> canonical_ball_;  // centre and squared radius in GMP's canonical form
  mutable std::size_t exact_count_ = 0;
  std::vector<int> rho_sign_;
  std::vector<bool> in_complex_;
  std::size_t ball_count_ = 0, hidden_ = 0;
  int dimension_ = -1;
  mutable std::vector<PowerSimplex> simplices_;
  std::array<std::vector<std::uint32_t>, 4> by_dim_;
  // Per dimension, (sorted balls, simplex) sorted by balls: find() is a binary search, and
  // the cofaces come from one sort of the facets (no hash of every facet).
  std::array<std::vector<std::pair<std::array<std::uint32_t, 4>, std::uint32_t>>, 4> index_;
};

// pow_i(x) = |x - c_i|^2 - r_i^2.
mpq_class power(const BallSet& b, std::uint32_t i, const ExactPoint3& x);

// For p with min_i pow_i(p) = 0 (on some spheres, in no open ball): whether p is an
// interior point of the union, i.e. the centres c_i of the balls through p surround it
// (0 in the interior of conv{c_i - p}; otherwise a direction d with d . (c_i - p) <= 0 for
// all of them leaves every ball). Exact; O(n) interval powers from the BallSet's approx_*
// (when present) pick the spheres that may pass through p, exact powers decide; then
// O(k^3) for the k spheres through p.
bool interior_of_union(const BallSet& b, const ExactPoint3& p);

struct BoundaryVertex {
  std::array<std::uint32_t, 3> balls{};  // the triangle whose spheres meet here
  int side = 1;                          // the point is z + side sqrt(s) n
  ExactPoint3 z, n;
  mpq_class s;
  bool rational = false;                 // sqrt(s) rational: the point is `point`
  ExactPoint3 point;
  std::uint32_t radical = 0;             // else sqrt(s) is this radical of the table
  std::array<Interval, 3> approx;
  // Exact coordinates in the field of the table.
  std::array<RadicalNumber, 3> coordinates(const RadicalTable& t) const;
};

// The exact identity of a boundary vertex, whichever triangle it was found from: the point
// when rational; else (z, (s |n|^2, 0, 0), side n / |first nonzero coordinate of n|), since
// the point is z + sqrt(s |n|^2) times the unit direction of side n.
std::array<ExactPoint3, 3> boundary_vertex_key(const BoundaryVertex& v);

// With `filtered`, a triangle both of whose points an interval filter certainly places
// inside the ball of a coface's extra vertex (off the dual edge) is skipped before any
// exact construction, and for the others each point-versus-ball test is asked of the
// filter first; exact tests decide what it leaves, so the output is the same as without
// the filter (the definition-level path, kept for the tests).
std::vector<BoundaryVertex> boundary_vertices(const BallSet& b, const AlphaComplex& k, RadicalTable* table,
                                              bool filtered = true);

// Exact sign of a + sign * b * sqrt(s) for rationals (s >= 0).
int sign_with_root(const mpq_class& a, int side, const mpq_class& b, const mpq_class& s);

}  // namespace grassfire
