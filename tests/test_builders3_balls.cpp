// Exact medial axes of unions of balls (Amenta-Kolluri 2001): hand-derived structures,
// the definition-level check, Betti numbers against the union's, degenerate inputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>

#include "complex3/simplicial_homology.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "medial3/balls/union_of_balls_reference.h"
#include "complex3/medial_complex.h"
#include "io/mesh_io.h"

using namespace grassfire;

namespace {

BallSet make_balls(const std::vector<std::array<long, 4>>& b, const std::string& name = "balls") {
  BallSet s;
  s.source = name;
  for (const auto& x : b) {
    s.centers.push_back({x[0], x[1], x[2]});
    s.squared_radii.push_back(x[3]);
    s.approx_centers.push_back({double(x[0]), double(x[1]), double(x[2])});
    s.approx_radii.push_back(std::sqrt(double(x[3])));
  }
  return s;
}

// Seeded random balls with dyadic coordinates in [0, side]^3 and radii in [r0, r0 + dr).
BallSet random_balls(std::size_t n, unsigned seed, double side, double r0, double dr) {
  std::mt19937 rng(seed);
  auto uniform = [&](double scale) { return scale * static_cast<double>(rng() % 4096) / 4096.0; };
  BallSet s;
  s.source = "random(" + std::to_string(n) + ", seed " + std::to_string(seed) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = uniform(side), y = uniform(side), z = uniform(side), r = r0 + uniform(dr);
    s.centers.push_back({mpq_class(x), mpq_class(y), mpq_class(z)});
    s.squared_radii.push_back(mpq_class(r) * mpq_class(r));
    s.approx_centers.push_back({x, y, z});
    s.approx_radii.push_back(r);
  }
  return s;
}

UnionOfBallsAxis checked(const BallSet& b, bool definition = true) {
  UnionOfBallsOptions options;
  options.polygon_samples = definition;
  UnionOfBallsAxis a = union_of_balls_axis(b, options);
  if (definition) {
    const DefinitionCheck c = check_union_axis(b, a);
    INFO(b.source << ": " << c.first_failure);
    CHECK(c.failures == 0);
    CHECK(c.points > 0);
  }
  CHECK(betti_numbers(a.complex) == a.union_betti);
  MedialComplex mc(a.complex);
  mc.validate();
  return a;
}


}  // namespace

TEST_CASE("one ball: the axis is its centre", "[builders3]") {
  const UnionOfBallsAxis a = checked(make_balls({{1, 2, 3, 5}}));
  REQUIRE(a.complex.vertices.size() == 1);
  CHECK(a.complex.triangles.empty());
  CHECK(a.complex.vertices[0].x == 1);
  CHECK(a.complex.radius_squared[0] == 5);
  CHECK(a.vertex_info[0].exact);
}

TEST_CASE("two overlapping equal balls: the segment of the centres, no disk", "[builders3]") {
  // The spheres meet in a circle, a concave crease of the union: points of the bisector
  // disk have that circle's nearest point as their only nearest point, so only the
  // segment c1 c2 (whose points see the whole circle) is medial.
  const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 4}, {2, 0, 0, 4}}));
  CHECK(a.complex.vertices.size() == 2);
  CHECK(a.complex.segments.size() == 1);
  CHECK(a.complex.triangles.empty());
  CHECK(a.boundary.empty());
  for (const mpq_class& r : a.complex.radius_squared) CHECK(r == 4);
  CHECK(a.singular_simplices[1] == 1);
}

TEST_CASE("tangent, nested and disjoint balls", "[builders3]") {
  SECTION("externally tangent: two centres, two components") {
    const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 1}, {2, 0, 0, 1}}));
    CHECK(a.complex.vertices.size() == 2);
    CHECK(a.complex.segments.empty());
    CHECK(a.union_betti == BettiNumbers{2, 0, 0});
  }
  SECTION("a ball strictly inside another: the big centre only") {
    const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 9}, {1, 0, 0, 1}}));
    REQUIRE(a.complex.vertices.size() == 1);
    CHECK(a.complex.vertices[0].x == 0);
    CHECK(a.complex.radius_squared[0] == 9);
  }
  SECTION("internally tangent: still the big centre only") {
    const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 9}, {2, 0, 0, 1}}));
    CHECK(a.complex.vertices.size() == 1);
    CHECK(a.complex.segments.empty());
  }
  SECTION("three disjoint balls: three centres") {
    const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 1}, {5, 0, 0, 1}, {0, 7, 1, 2}}));
    CHECK(a.complex.vertices.size() == 3);
    CHECK(a.union_betti == BettiNumbers{3, 0, 0});
  }
}

TEST_CASE("three balls with collinear centres: two segments", "[builders3]") {
  const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 4}, {2, 0, 0, 4}, {4, 0, 0, 4}}));
  CHECK(a.triangulation_dimension == 1);
  CHECK(a.complex.vertices.size() == 3);
  CHECK(a.complex.segments.size() == 2);
  CHECK(a.complex.triangles.empty());
}

TEST_CASE("three balls meeting in two points: the triangle of the centres", "[builders3]") {
  // Circumradius^2 of the centres is 169/36 < 6: the three spheres meet in two mirror
  // points; every point of the triangle is equidistant from them.
  const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 6}, {4, 0, 0, 6}, {2, 3, 0, 6}}));
  CHECK(a.boundary.size() == 2);
  CHECK(a.complex.vertices.size() == 3);
  CHECK(a.complex.triangles.size() == 1);
  CHECK(a.complex.border_rules.size() == 3);  // R(x) = |x - v| along the three sides
  for (const AxisVertexInfo& i : a.vertex_info) CHECK(i.exact);
}

TEST_CASE("three balls around a hole: a cycle of segments", "[builders3]") {
  // Sides 8, sqrt 52, sqrt 52, all below 2 r = 2 sqrt 18: the balls overlap in pairs; the
  // circumradius^2 169/9 exceeds r^2 = 18: no common point, the union is a ring (b1 = 1).
  const UnionOfBallsAxis a = checked(make_balls({{0, 0, 0, 18}, {8, 0, 0, 18}, {4, 6, 0, 18}}));
  CHECK(a.union_betti == BettiNumbers{1, 1, 0});
  CHECK(a.complex.segments.size() == 3);
  CHECK(a.complex.triangles.empty());
}

TEST_CASE("four balls on a regular tetrahedron: six triangles from the centre", "[builders3]") {
  // The boundary vertices v_l (on the spheres other than l) are cospherical about the
  // origin q; the Voronoi edges run from q through the centres, so the axis is the cone
  // from q over the six edges of the tetrahedron.
  const UnionOfBallsAxis a = checked(make_balls({{1, 1, 1, 4}, {1, -1, -1, 4}, {-1, 1, -1, 4}, {-1, -1, 1, 4}}));
  CHECK(a.alpha_simplices[3] == 1);
  CHECK(a.boundary.size() == 4);
  CHECK(a.complex.vertices.size() == 5);
  CHECK(a.complex.triangles.size() == 6);
  CHECK(edge_degree_histogram(a.complex) == std::map<std::size_t, std::size_t>{{1, 6}, {3, 4}});
  bool origin = false;
  for (std::size_t v = 0; v < a.complex.vertices.size(); ++v)
    origin |= a.complex.vertices[v].x == 0 && a.complex.vertices[v].y == 0 && a.complex.vertices[v].z == 0;
  CHECK(origin);  // found exactly, though it is computed from irrational bisectors
}

TEST_CASE("caffeine: definition check and Betti numbers", "[builders3]") {
  const BallSet b = read_ball_list(std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin");
  const UnionOfBallsAxis a = checked(b);
  // Atoms overlap in pairs only (no three spheres meet): the axis is the bond graph, 24
  // segments between the 23 centres, with the two rings of caffeine as its cycles.
  CHECK(a.balls == 23);
  CHECK(a.complex.vertices.size() == 23);
  CHECK(a.complex.segments.size() == 24);
  CHECK(a.complex.triangles.empty());
  CHECK(a.union_betti == BettiNumbers{1, 2, 0});
}

TEST_CASE("random ball sets: definition check, Betti numbers, CGAL alpha shape", "[builders3]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const BallSet b = random_balls(12, seed, 6.0, 1.0, 1.0);
    const UnionOfBallsAxis a = checked(b);
    // Generic input: the open dual complex equals the closed one, which is CGAL's alpha
    // shape at alpha = 0 (Fixed_alpha_shape_3), simplex for simplex.
    const AlphaComplex k(b, regular_triangulation(b));
    REQUIRE(k.dimension() == 3);
    std::vector<std::array<std::uint32_t, 4>> closed;
    for (std::uint32_t s = 0; s < k.simplices().size(); ++s) {
      CHECK(k.in_complex(s) == k.in_closed_complex(s));
      if (k.in_closed_complex(s)) closed.push_back(k.simplices()[s].balls);
    }
    std::sort(closed.begin(), closed.end());
    CHECK(closed == cgal_alpha_complex(b));
  }
  for (unsigned seed : {7u, 8u}) {
    const UnionOfBallsAxis a = checked(random_balls(150, seed, 12.0, 1.0, 1.0), false);
    CHECK(a.complex.triangles.size() > 0);
  }
}

TEST_CASE("bad ball sets are rejected", "[builders3]") {
  BallSet empty;
  empty.source = "empty.balls";
  CHECK_THROWS_WITH(union_of_balls_axis(empty), Catch::Contains("empty.balls") && Catch::Contains("no balls"));
  BallSet negative = make_balls({{0, 0, 0, 1}, {1, 0, 0, 1}}, "neg.balls");
  negative.squared_radii[1] = -1;
  CHECK_THROWS_WITH(union_of_balls_axis(negative), Catch::Contains("neg.balls") && Catch::Contains("ball 1"));
}
