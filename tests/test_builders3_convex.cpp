// Exact medial axes of convex polyhedra (2.1.1): hand-derived structures, the
// definition-level check, exact volumes, Betti numbers, rejection of bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "io/halfspace_list.h"
#include "complex3/simplicial_homology.h"
#include "complex3/medial_complex.h"
#include "io/complex_text.h"
#include "io/mesh_io.h"

using namespace grassfire;

namespace {

ConvexPolyhedron box(long x, long y, long z) {
  ConvexPolyhedron p;
  p.source = "box";
  for (int axis = 0; axis < 3; ++axis)
    for (int s : {-1, 1}) {
      std::array<mpq_class, 3> n{0, 0, 0};
      n[axis] = s;
      p.planes.push_back({n[0], n[1], n[2], axis == 0 ? x : axis == 1 ? y : z});
    }
  return p;
}

ConvexAxis checked_axis(const ConvexPolyhedron& p) {
  ConvexAxis a = convex_polyhedron_axis(p);
  const DefinitionCheck c = check_convex_axis(a);
  INFO(c.first_failure);
  CHECK(c.failures == 0);
  CHECK(c.points == a.complex.vertices.size() + a.complex.triangles.size());
  CHECK(a.volume == a.cell_volume_sum);
  CHECK(betti_numbers(a.complex) == BettiNumbers{1, 0, 0});  // a convex body is contractible
  MedialComplex mc(a.complex);
  mc.validate();
  return a;
}

const mpq_class* radius_squared_at(const RawComplex& r, const ExactPoint3& p) {
  for (std::size_t v = 0; v < r.vertices.size(); ++v)
    if (r.vertices[v].x == p.x && r.vertices[v].y == p.y && r.vertices[v].z == p.z) return &r.radius_squared[v];
  return nullptr;
}


TriangleMesh3 data_mesh(const std::string& name) { return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name); }

}  // namespace

TEST_CASE("cube: 12 roof triangles from the centre to the edges", "[builders3]") {
  const ConvexAxis a = checked_axis(box(1, 1, 1));
  CHECK(a.exact);
  CHECK(a.complex.vertices.size() == 9);
  CHECK(a.complex.triangles.size() == 12);
  CHECK(a.polygons == 12);
  CHECK(a.complex.segments.empty());
  REQUIRE(radius_squared_at(a.complex, {0, 0, 0}));
  CHECK(*radius_squared_at(a.complex, {0, 0, 0}) == 1);
  CHECK(*radius_squared_at(a.complex, {1, -1, 1}) == 0);
  // 12 cube edges are the border (one triangle), 8 centre-corner edges carry three sheets.
  CHECK(edge_degree_histogram(a.complex) == std::map<std::size_t, std::size_t>{{1, 12}, {3, 8}});
  CHECK(a.volume == 8);
}

TEST_CASE("box 2 x 2 x 4: a central segment, four quads and eight roof triangles", "[builders3]") {
  const ConvexAxis a = checked_axis(box(1, 1, 2));
  CHECK(a.complex.vertices.size() == 10);
  CHECK(a.polygons == 12);
  CHECK(a.complex.triangles.size() == 16);  // quads split in two
  CHECK(*radius_squared_at(a.complex, {0, 0, 1}) == 1);
  CHECK(*radius_squared_at(a.complex, {0, 0, -1}) == 1);
  // The segment (0,0,-1)-(0,0,1) joins four sheets (x = +-y).
  CHECK(edge_degree_histogram(a.complex)[4] == 1);
}

TEST_CASE("scaled and translated box: same combinatorics, R^2 scaled", "[builders3]") {
  ConvexPolyhedron p = box(1, 2, 3);
  const ConvexAxis a = checked_axis(p);
  for (HalfSpace& h : p.planes) h.d = 3 * h.d + h.a * 5 - h.b * 7 + h.c * 2;  // x -> 3x + (5, -7, 2)
  const ConvexAxis b = checked_axis(p);
  CHECK(a.complex.vertices.size() == b.complex.vertices.size());
  CHECK(a.complex.triangles.size() == b.complex.triangles.size());
  CHECK(edge_degree_histogram(a.complex) == edge_degree_histogram(b.complex));
  mpq_class max_a = 0, max_b = 0;
  for (const mpq_class& r : a.complex.radius_squared) max_a = std::max(max_a, r);
  for (const mpq_class& r : b.complex.radius_squared) max_b = std::max(max_b, r);
  CHECK(max_b == 9 * max_a);
}

TEST_CASE("octahedron mesh: normals (1,1,1)/sqrt 3 give an exact axis", "[builders3]") {
  const ConvexAxis a = checked_axis(convex_polyhedron_from_mesh(data_mesh("octahedron.off")));
  CHECK(a.exact);
  CHECK(a.s == 3);
  CHECK(a.complex.vertices.size() == 7);
  CHECK(a.complex.triangles.size() == 12);
  CHECK(*radius_squared_at(a.complex, {0, 0, 0}) == mpq_class(4, 3));  // inradius 2/sqrt(3)
  // Centre-to-corner edges join the four faces around an octahedron vertex.
  CHECK(edge_degree_histogram(a.complex) == std::map<std::size_t, std::size_t>{{1, 12}, {4, 6}});
}

TEST_CASE("cube mesh gives the same axis as the cube half-spaces", "[builders3]") {
  const ConvexAxis a = checked_axis(convex_polyhedron_from_mesh(data_mesh("cube.off")));
  CHECK(a.complex.vertices.size() == 9);
  CHECK(a.complex.triangles.size() == 12);
}

TEST_CASE("tetrahedra: six triangles from the incentre to the edges", "[builders3]") {
  SECTION("Pythagorean normal (2,3,6)/7: incentre (1/3,1/3,1/3), r = 1/3") {
    ConvexPolyhedron p;
    p.source = "tetrahedron";
    p.planes = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}, {2, 3, 6, 6}};
    const ConvexAxis a = checked_axis(p);
    CHECK(a.exact);
    CHECK(a.complex.vertices.size() == 5);
    CHECK(a.complex.triangles.size() == 6);
    const mpq_class third(1, 3);
    REQUIRE(radius_squared_at(a.complex, {third, third, third}));
    CHECK(*radius_squared_at(a.complex, {third, third, third}) == mpq_class(1, 9));
  }
  SECTION("regular tetrahedron as a mesh (s = 3)") {
    TriangleMesh3 m;
    m.source = "regular tetrahedron";
    m.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    const ConvexAxis a = checked_axis(convex_polyhedron_from_mesh(m));
    CHECK(a.exact);
    CHECK(a.complex.vertices.size() == 5);
    CHECK(a.complex.triangles.size() == 6);
    CHECK(*radius_squared_at(a.complex, {0, 0, 0}) == mpq_class(1, 3));
  }
}

TEST_CASE("mixed square classes: certified approximate mode", "[builders3]") {
  // The corner tetrahedron: normals (-1,0,0), (0,-1,0), (0,0,-1) and (1,1,1)/sqrt 3.
  ConvexPolyhedron p;
  p.source = "corner tetrahedron";
  p.planes = {{-1, 0, 0, 0}, {0, -1, 0, 0}, {0, 0, -1, 0}, {1, 1, 1, 1}};
  const ConvexAxis a = checked_axis(p);
  CHECK_FALSE(a.exact);
  CHECK(a.distance_bound > 0);
  CHECK(a.distance_bound < 1e-6);  // default: 24 bits
  CHECK(a.complex.vertices.size() == 5);
  CHECK(a.complex.triangles.size() == 6);
  for (const ExactPoint3& u : a.u) CHECK(dot(u, u) == 1);  // rational unit normals
  ConvexAxisOptions fine;
  fine.approximation_bits = 40;
  const ConvexAxis b = convex_polyhedron_axis(p, fine);
  CHECK(b.distance_bound < 1e-10);
  CHECK(b.complex.triangles.size() == 6);
  CHECK(check_convex_axis(b).failures == 0);
}

TEST_CASE("half-space file format", "[builders3]") {
  const ConvexPolyhedron p = parse_halfspaces("# unit cube\n1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 -1 0 1 # y\n\n0 0 1 1\n0 0 -1 1.0\n", "cube.txt");
  CHECK(p.planes.size() == 6);
  CHECK(convex_polyhedron_axis(p).complex.triangles.size() == 12);
  CHECK_THROWS_WITH(parse_halfspaces("1 0 0\n", "bad.txt"), Catch::Contains("bad.txt:1"));
  CHECK_THROWS_WITH(parse_halfspaces("1 0 0 nan\n", "bad.txt"), Catch::Contains("bad.txt:1"));
  CHECK_THROWS_WITH(parse_halfspaces("0 0 0 1\n", "bad.txt"), Catch::Contains("normal"));
  CHECK_THROWS_AS(parse_halfspaces("# nothing\n", "empty.txt"), ComplexFormatError);
}

TEST_CASE("bad polyhedra are rejected with their reason", "[builders3]") {
  ConvexPolyhedron open = box(1, 1, 1);
  open.planes.pop_back();
  CHECK_THROWS_WITH(convex_polyhedron_axis(open), Catch::Contains("fewer than 4") || Catch::Contains("unbounded"));
  open.planes.push_back({1, 1, 0, 5});  // still open towards -z
  CHECK_THROWS_WITH(convex_polyhedron_axis(open), Catch::Contains("unbounded"));
  ConvexPolyhedron empty = box(1, 1, 1);
  empty.planes.push_back({-1, 0, 0, -2});  // x >= 2
  CHECK_THROWS_WITH(convex_polyhedron_axis(empty), Catch::Contains("no common interior"));
  ConvexPolyhedron redundant = box(1, 1, 1);
  redundant.planes.push_back({1, 1, 1, 10});
  CHECK(convex_polyhedron_axis(redundant).redundant_planes == 1);
}

TEST_CASE("non-convex and open meshes are rejected naming the file", "[builders3]") {
  TriangleMesh3 cube = data_mesh("cube.off");
  TriangleMesh3 dented = cube;
  dented.vertices[6] = {0.5, 0.5, 0.5};  // pull the corner (1,1,1) inwards
  CHECK_THROWS_WITH(convex_polyhedron_from_mesh(dented), Catch::Contains("cube.off") && Catch::Contains("not convex"));
  TriangleMesh3 open = cube;
  open.triangles.pop_back();
  CHECK_THROWS_WITH(convex_polyhedron_from_mesh(open), Catch::Contains("not closed") && Catch::Contains("edge ("));
  TriangleMesh3 flipped = cube;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  CHECK_THROWS_WITH(convex_polyhedron_from_mesh(flipped), Catch::Contains("orientation"));
}
