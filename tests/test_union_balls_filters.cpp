// The interval filters of the union-of-balls axis change no decision: the filtered
// boundary vertices equal the definition-level (all exact) ones, vertex for vertex and in
// order, on seeded random ball sets, on degenerate sets (cospherical, equal radii, tangent
// and contained balls) and on data/balls.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>

#include "medial3/balls/union_alpha_complex.h"
#include "geometry3/exact_predicates3.h"
#include "io/mesh_io.h"
#include "union_axis_digest.h"

using namespace grassfire;
using grassfire::testing::union_coarse_balls;
using grassfire::testing::union_grid_balls;

namespace {

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
  for (unsigned seed = 1; seed <= 8; ++seed) require_same_boundary(union_coarse_balls(40, seed));
}

TEST_CASE("filtered boundary vertices equal the exact ones on degenerate ball sets", "[builders3]") {
  require_same_boundary(union_grid_balls(3, 1));                 // overlapping, cospherical cubes
  require_same_boundary(union_grid_balls(3, mpq_class(1, 4)));   // tangent neighbours
  require_same_boundary(union_grid_balls(2, 3));                 // balls meeting at the cube centre
  require_same_boundary(union_grid_balls(3, mpq_class(9, 16)));  // spheres meet in rational points
}

TEST_CASE("filtered boundary vertices equal the exact ones on data/balls", "[builders3]") {
  require_same_boundary(read_ball_list(std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin"));
}
