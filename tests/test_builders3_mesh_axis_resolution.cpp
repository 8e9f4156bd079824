// The resolution rule of the mesh axis (axis_resolution.h, mesh_axis.h step 7): the
// components of the pruned axis below the sampling's resolution, which multiply along a
// sharp wedge as the sampling is refined, are dropped once the rounds show they do not
// converge; rounds that converge without the rule are left alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "complex3/medial_complex.h"
#include "complex3/simplicial_homology.h"
#include "geometry3/synthetic_meshes.h"
#include "io/mesh_io.h"
#include "medial3/mesh/axis_resolution.h"
#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_samples.h"
#include "medial3/mesh/mesh_solid.h"

#include "test_mesh_axis_support.h"

using namespace grassfire;

using grassfire::testing::project_mesh;

namespace {

// The thin lens: a cap of the unit sphere closed by its disc, the rim a wedge of 10 degrees
// (its inradius 0.0076 against a mean edge length of 0.02).
TriangleMesh3 thin_lens() { return lens_mesh(10, 4, 48); }

}  // namespace

TEST_CASE("lens meshes: a closed manifold solid with a sharp rim", "[mesh_axis][resolution]") {
  for (double angle : {10.0, 30.0, 60.0}) {
    const TriangleMesh3 lens = lens_mesh(angle, 3, 16);
    CAPTURE(angle);
    CHECK(solid_topology(lens).betti == BettiNumbers{1, 0, 0});
    CHECK(lens.triangles.size() == 2 * (16 + 2 * 16 * 2));  // cap: a fan and two bands; the disc the same
  }
}

TEST_CASE("unresolved components: whole components whose every vertex is unresolved", "[mesh_axis][resolution]") {
  // Two triangles sharing the side 1-2 (vertices 0..3), a segment 4-5, an isolated vertex 6.
  PolygonRings rings;
  for (std::uint32_t v : {0u, 1u, 2u}) rings.vertex.push_back(v);
  rings.close();
  for (std::uint32_t v : {1u, 3u, 2u}) rings.vertex.push_back(v);
  rings.close();
  const std::vector<std::array<std::uint32_t, 2>> segments = {{4, 5}};
  // Vertex 3 alone is resolved: its component stays, the segment and vertex 6 go.
  const UnresolvedComponents u = unresolved_components(7, rings, segments, [](std::uint32_t v) { return v != 3; });
  CHECK(u.components == 2);
  CHECK(u.vertex_dropped == std::vector<bool>{false, false, false, false, true, true, true});
  // Every vertex resolved: nothing goes; every vertex unresolved: all three components.
  CHECK(unresolved_components(7, rings, segments, [](std::uint32_t) { return false; }).components == 0);
  CHECK(unresolved_components(7, rings, segments, [](std::uint32_t) { return true; }).components == 3);
}

TEST_CASE("resolution test against its definition: R(x) < (lambda / 2) h in rationals", "[mesh_axis][resolution]") {
  // Every inner Voronoi vertex of the thin lens sampled at two spacings: the exact squared
  // radius (exact_point) against ((lambda / 2) h)^2, h the least spacing of the triangles
  // the vertex's four samples lie on, in the mesh's units.
  const TriangleMesh3 lens = thin_lens();
  const SolidLocator solid(lens);
  for (double divide : {1.0, 4.0}) {
    std::vector<double> spacing(lens.triangles.size(), mean_edge_length(lens) / divide);
    spacing[0] /= 2;  // one finer triangle: h differs between samples
    const InnerVoronoi vor = inner_voronoi(sample_surface(lens, spacing), solid);
    const std::vector<double> density = sample_spacing(vor.samples, spacing);
    std::vector<double> least(vor.samples.lattice.size(), INFINITY);
    for (std::size_t t = 0; t < lens.triangles.size(); ++t)
      for (std::uint32_t i = vor.samples.offset[t]; i < vor.samples.offset[t + 1]; ++i)
        least[vor.samples.on_triangle[i]] = std::min(least[vor.samples.on_triangle[i]], spacing[t]);
    for (const double lambda : {2.0, 1.0}) {
      const ResolutionTest test(vor, density, lambda);
      std::size_t unresolved = 0;
      for (std::uint32_t x = 0; x < vor.vertices.size(); ++x) {
        mpq_class r2;
        exact_point(vor.samples, vor.vertices[x].centre, &r2);
        double h = INFINITY;
        for (std::uint32_t s : vor.vertices[x].centre.tetrahedron) h = std::min(h, least[s]);
        const mpq_class threshold = mpq_class(lambda / 2) * mpq_class(h);
        const bool expected = r2 < threshold * threshold;
        CHECK(test.unresolved(x) == expected);
        unresolved += expected;
      }
      CAPTURE(divide, lambda);
      CHECK(unresolved > 0);  // the lens is thinner than h near its rim
      // At the first spacing everywhere for lambda = 2 (inradius 0.0076 < h), not at h / 4.
      if (divide > 1 || lambda < 2) CHECK(unresolved < vor.vertices.size());
      else CHECK(unresolved == vor.vertices.size());
    }
    CHECK_FALSE(ResolutionTest(vor, density, 0).unresolved(0));  // no separation test: no rule
  }
}

TEST_CASE("a thin lens gets its axis by the resolution rule, and without it the rounds diverge", "[mesh_axis][resolution]") {
  const TriangleMesh3 lens = thin_lens();
  const MeshAxis a = mesh_medial_axis(lens);
  CHECK(a.solid.betti == BettiNumbers{1, 0, 0});
  CHECK(a.axis_betti == BettiNumbers{1, 0, 0});
  CHECK(betti_numbers(a.complex) == BettiNumbers{1, 0, 0});  // simplicial homology of the triangles
  MedialComplex(a.complex).validate();
  const MeshAxisRound& accepted = a.rounds[a.axis_round];
  CHECK(accepted.resolution_rule);
  CHECK(accepted.all_components_betti.b0 == 1 + static_cast<long>(accepted.unresolved_components));
  CHECK(accepted.samples < 100000);
  // The rounds before: more components at every finer sampling, none of them resolved.
  REQUIRE(a.axis_round >= 2);
  for (std::size_t i = 0; i < a.axis_round; ++i) {
    CAPTURE(i);
    CHECK(a.rounds[i].all_components_betti.b0 > 1);
    CHECK(a.rounds[i].unresolved_components == static_cast<std::size_t>(a.rounds[i].all_components_betti.b0));
    if (i > 0) CHECK(a.rounds[i].all_components_betti.b0 > a.rounds[i - 1].all_components_betti.b0);
  }
  const nlohmann::json j = mesh_axis_json(a);
  CHECK(j["rounds"][a.axis_round]["resolution_rule"] == true);
  CHECK(j["rounds"][a.axis_round]["unresolved_components"] == accepted.unresolved_components);
  CHECK(j["rounds"][0]["all_components_betti"][0] == a.rounds[0].all_components_betti.b0);
  CHECK(j["resolution_rule"] == true);
  CHECK(j["dropped_components"] == accepted.unresolved_components);
  // Without the rule the same rounds run into the limit.
  MeshAxisOptions off;
  off.resolution_rule = false;
  off.max_samples = 100000;
  CHECK_THROWS_AS(mesh_medial_axis(lens, off), MeshAxisTopologyError);
}

TEST_CASE("the resolution rule leaves rounds that converge without it alone", "[mesh_axis][resolution]") {
  // joint.off's first round has two components, its second the solid's Betti numbers.
  for (const char* name : {"joint.off", "tripod.off", "cross.off", "double-torus-example.off"}) {
    CAPTURE(name);
    const TriangleMesh3 mesh = project_mesh(name);
    MeshAxisOptions off;
    off.resolution_rule = false;
    const MeshAxis a = mesh_medial_axis(mesh), b = mesh_medial_axis(mesh, off);
    REQUIRE(a.rounds.size() == b.rounds.size());
    for (std::size_t i = 0; i < a.rounds.size(); ++i) {
      CHECK_FALSE(a.rounds[i].resolution_rule);
      CHECK(a.rounds[i].samples == b.rounds[i].samples);
      CHECK(a.rounds[i].betti == b.rounds[i].betti);
    }
    CHECK(a.axis_round == b.axis_round);
    CHECK(a.complex.vertices.size() == b.complex.vertices.size());
    CHECK(a.complex.triangles == b.complex.triangles);
    CHECK(a.complex.segments == b.complex.segments);
    CHECK(a.complex.radius_squared == b.complex.radius_squared);
  }
}
