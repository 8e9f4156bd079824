// The interval filters of the union-of-balls axis change no decision: the filtered
// boundary vertices equal the definition-level (all exact) ones, vertex for vertex and in
// order, on seeded random ball sets, on degenerate sets (cospherical, equal radii, tangent
// and contained balls) and on data/balls.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "complex3/builders/union_alpha_complex.h"
#include "complex3/exact_predicates3.h"
#include "io/mesh_io.h"

using namespace grassfire;

namespace {

void add_ball(BallSet* s, const mpq_class& x, const mpq_class& y, const mpq_class& z, const mpq_class& r2) {
  s->centers.push_back({x, y, z});
  s->squared_radii.push_back(r2);
  s->approx_centers.push_back({x.get_d(), y.get_d(), z.get_d()});
  s->approx_radii.push_back(std::sqrt(r2.get_d()));
}

// Balls on an integer grid: equal radii make every cube of centres cospherical; r2 = 1/4
// at spacing 1 makes neighbours tangent, r2 = 3 covers each cube's centre exactly.
BallSet grid_balls(int side, const mpq_class& r2) {
  BallSet s;
  s.source = "grid(" + std::to_string(side) + ", r2 " + r2.get_str() + ")";
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) add_ball(&s, x, y, z, r2);
  return s;
}

// Random dyadic balls on a coarse grid (many ties), plus balls contained in others.
BallSet coarse_random_balls(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  BallSet s;
  s.source = "coarse random(" + std::to_string(n) + ", seed " + std::to_string(seed) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    const mpq_class x(rng() % 9, 2), y(rng() % 9, 2), z(rng() % 9, 2), r(2 + rng() % 3, 2);
    add_ball(&s, x, y, z, r * r);
    if (i % 5 == 0) add_ball(&s, x, y, z + mpq_class(1, 4), r * r / 4);  // inside ball i
  }
  return s;
}

void require_same_boundary(const BallSet& b) {
  INFO(b.source);
  const AlphaComplex k(b, regular_triangulation(b));
  RadicalTable ta, tb;
  const std::vector<BoundaryVertex> fast = boundary_vertices(b, k, &ta, true);
  const std::vector<BoundaryVertex> slow = boundary_vertices(b, k, &tb, false);
  REQUIRE(fast.size() == slow.size());
  for (std::size_t i = 0; i < fast.size(); ++i) {
    CHECK(fast[i].balls == slow[i].balls);
    CHECK(fast[i].side == slow[i].side);
    const auto a = boundary_vertex_key(fast[i]), c = boundary_vertex_key(slow[i]);
    for (int m = 0; m < 3; ++m) CHECK(compare_lex(a[m], c[m]) == 0);
  }
}

}  // namespace

TEST_CASE("filtered boundary vertices equal the exact ones on random ball sets", "[builders3]") {
  for (unsigned seed = 1; seed <= 12; ++seed) require_same_boundary(random_ball_set(60 + 10 * seed, seed));
  for (unsigned seed = 1; seed <= 8; ++seed) require_same_boundary(coarse_random_balls(40, seed));
}

TEST_CASE("filtered boundary vertices equal the exact ones on degenerate ball sets", "[builders3]") {
  require_same_boundary(grid_balls(3, 1));                 // overlapping, cospherical cubes
  require_same_boundary(grid_balls(3, mpq_class(1, 4)));   // tangent neighbours
  require_same_boundary(grid_balls(2, 3));                 // balls meeting at the cube centre
  require_same_boundary(grid_balls(3, mpq_class(9, 16)));  // spheres meet in rational points
}

TEST_CASE("filtered boundary vertices equal the exact ones on data/balls", "[builders3]") {
  require_same_boundary(read_ball_list(std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin"));
}
