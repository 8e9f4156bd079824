// Regression tests of the convex polyhedron builder, one per bug, named after it; then
// seeded random cuts of the cube, which the proof checks also run.
#include <catch2/catch.hpp>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "complex3/medial_complex.h"

using namespace grassfire;

namespace {

ConvexPolyhedron cube_with_cuts(const std::vector<HalfSpace>& cuts) {
  ConvexPolyhedron p;
  p.source = "cut cube";
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {1, -1}) {
      mpq_class n[3] = {0, 0, 0};
      n[axis] = sign;
      p.planes.push_back({n[0], n[1], n[2], 2});
    }
  p.planes.insert(p.planes.end(), cuts.begin(), cuts.end());
  return p;
}

void require_valid(const ConvexAxis& a) {
  const DefinitionCheck c = check_convex_axis(a);
  INFO(c.first_failure);
  REQUIRE(c.failures == 0);
  REQUIRE(c.points == a.complex.vertices.size() + a.complex.triangles.size());
  REQUIRE(a.volume == a.cell_volume_sum);
  MedialComplex mc(a.complex);
  mc.validate();
}

}  // namespace

TEST_CASE("regression: a redundant input plane shifted the facet numbers past the end (crash)", "[builders3]") {
  // x <= 2 is implied by 4x + 3z <= 6 and 4x - 3z <= 7 (8x <= 13). The builder numbered the
  // faces of the polyhedron by input plane but the facets by face order, so clip_order read
  // facet 8 of 8 and crashed in GMP.
  const ConvexPolyhedron p = cube_with_cuts({{0, 3, -4, 9}, {4, 0, 3, 6}, {4, 0, -3, 7}});
  const ConvexAxis a = convex_polyhedron_axis(p);
  require_valid(a);
  CHECK(a.exact);
  CHECK(a.redundant_planes == 1);
  CHECK(a.polygons == 21);
  CHECK(a.complex.triangles.size() == 42);
  CHECK(a.volume == mpq_class(16607, 384));
  // Metamorphic: without the redundant plane the axis is the same.
  ConvexPolyhedron q = p;
  q.planes.erase(q.planes.begin());  // x <= 2
  const ConvexAxis b = convex_polyhedron_axis(q);
  CHECK(b.redundant_planes == 0);
  CHECK(b.polygons == a.polygons);
  CHECK(b.complex.triangles.size() == a.complex.triangles.size());
  CHECK(b.volume == a.volume);
}

TEST_CASE("seeded random cuts of the cube with Pythagorean normals: exact and valid by definition", "[builders3]") {
  // 40 seeds of random_cut_cube (1-4 cuts with normals of rational length); a 300-seed run
  // under AddressSanitizer found no failure after the fix above.
  for (std::uint32_t seed = 0; seed < 40; ++seed) {
    CAPTURE(seed);
    const ConvexAxis a = convex_polyhedron_axis(random_cut_cube(seed));
    CHECK(a.exact);
    require_valid(a);
  }
}
