// CGAL Surface_mesh_shortest_path with start times against closed forms (flat grid, cube
// surface) and against the discrete baseline; Loop-refined benchmark meshes.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/geodesic_smsp.h"
#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "geometry3/refined_mesh.h"
#include "io/mesh_io.h"
#include "test_complex3_support.h"
#include "test_sheets_support.h"

using namespace grassfire;

namespace {

TriangleMesh3 as_mesh(const RawComplex& raw) {
  TriangleMesh3 m;
  m.source = raw.source;
  for (const ExactPoint3& p : raw.vertices) m.vertices.push_back(to_double(p));
  m.triangles = raw.triangles;
  return m;
}

// Vertex u as a point of the first face that holds it.
MeshPoint at_vertex(const TriangleMesh3& mesh, std::uint32_t u) {
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (mesh.triangles[f][i] == u) {
        MeshPoint p{f, {0, 0, 0}};
        p.barycentric[i] = 1;
        return p;
      }
  FAIL("vertex on no face");
  return {};
}

TriangleMesh3 cube() { return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/cube.off"); }

}  // namespace

TEST_CASE("CGAL geodesics: straight distances plus start times on a flat grid", "[burn3][smsp]") {
  const TriangleMesh3 grid = as_mesh(testing::grid_sheet({{"####", "####", "####"}, 2}));  // [0,4]x[0,3]
  SmspGeodesics g(grid);
  // Inside a face, at a vertex, inside a border edge, inside an interior edge (CGAL 5.5.1
  // roots edge sources at their mirror image along the edge, issue #6681: 2.4 -> 2.1).
  const std::array<double, 3> s1 = {1.3, 1.1, 0}, s2 = {3, 2, 0}, s3 = {2.4, 0, 0}, s4 = {1.2, 2.7, 0};
  g.add_source(g.locate(s1), 0.5);
  g.add_source(g.locate(s2), 0.0);
  g.add_source(g.locate(s3), 0.5);
  g.add_source(g.locate(s4), 0.75);
  g.build();
  CHECK(g.tree_count() == 3);  // one tree per distinct start time
  for (double x = 0; x <= 4; x += 0.37)
    for (double y = 0; y <= 3; y += 0.29) {
      const std::array<double, 3> p = {x, y, 0};
      const double expected = std::min({0.5 + std::hypot(x - s1[0], y - s1[1]), std::hypot(x - s2[0], y - s2[1]),
                                        0.5 + std::hypot(x - s3[0], y - s3[1]), 0.75 + std::hypot(x - s4[0], y - s4[1])});
      CAPTURE(x, y);
      CHECK(g.distance(g.locate(p)) == Approx(expected).epsilon(1e-12).margin(1e-11));
    }
  // A located point reproduces its position through its barycentric weights.
  const MeshPoint m = g.locate({1.3, 1.1, 0});
  double px = 0;
  for (int i = 0; i < 3; ++i) px += m.barycentric[i] * grid.vertices[grid.triangles[m.face][i]][0];
  CHECK(px == Approx(1.3).epsilon(1e-14));
}

TEST_CASE("CGAL geodesics: unfolded distances on the cube surface", "[burn3][smsp]") {
  SmspGeodesics g(cube());  // [-1, 1]^3
  g.add_source(g.locate({0, 0, -1}), 0);  // centre of the bottom face
  g.build();
  auto at = [&](double x, double y, double z) { return g.distance(g.locate({x, y, z})); };
  CHECK(at(1, 0, 0.3) == Approx(2.3).epsilon(1e-12));                          // up the side x = 1
  CHECK(at(1, 0.5, 0.25) == Approx(std::hypot(2.25, 0.5)).epsilon(1e-12));     // unfolded across the edge
  CHECK(at(0.5, 0, 1) == Approx(3.5).epsilon(1e-12));                          // over the side to the top
  CHECK(at(0, 0, 1) == Approx(4).epsilon(1e-12));
  SmspGeodesics corner(cube());
  corner.add_source(corner.locate({-1, -1, -1}), 0);  // a source at a vertex
  corner.build();
  CHECK(corner.distance(corner.locate({1, 1, 1})) == Approx(std::sqrt(20.0)).epsilon(1e-12));
  CHECK(corner.distance(corner.locate({1, -1, -1})) == Approx(2).epsilon(1e-12));
  // Two sources with start times: min over t0 + distance.
  SmspGeodesics two(cube());
  two.add_source(two.locate({0, 0, -1}), 0);
  two.add_source(two.locate({0, 0, 1}), 0.5);
  two.build();
  CHECK(two.distance(two.locate({1, 0, 0})) == Approx(2).epsilon(1e-12));
  CHECK(two.distance(two.locate({1, 0, 0.5})) == Approx(2).epsilon(1e-12));
  CHECK(two.distance(two.locate({1, 0, 0.8})) == Approx(1.7).epsilon(1e-12));
}

TEST_CASE("Loop-refined meshes: closed, no coplanar neighbours, deterministic", "[burn3][smsp]") {
  CHECK(loop_levels_for(12, 1000) == 3);
  CHECK(loop_levels_for(12, 10000) == 5);
  CHECK(loop_levels_for(12, 100000) == 7);
  CHECK(loop_levels_for(44, 1000) == 2);
  const TriangleMesh3 a = refined_mesh(cube(), 1000), b = refined_mesh(cube(), 1000);
  CHECK(a.triangles.size() == 768);
  CHECK(a.vertices == b.vertices);
  CHECK(a.triangles == b.triangles);
  CHECK(coplanar_neighbour_pairs(cube()) == 6);  // each square face is two coplanar triangles
  CHECK(coplanar_neighbour_pairs(a) == 0);
  const MedialComplex mc = testing::built(mesh_as_complex(a));
  CHECK(mc.count(EdgeStratum::Border) == 0);  // closed
  CHECK(mc.count(EdgeStratum::Singular) == 0);
  CHECK(mc.sheets().size() == 1);
  for (const char* name : {"octahedron.off", "tripod.off", "cross.off"}) {
    const TriangleMesh3 m = refined_mesh(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name), 1000);
    CAPTURE(name, m.triangles.size());
    CHECK(coplanar_neighbour_pairs(m) == 0);
    CHECK(m.triangles.size() >= 500);
    CHECK(m.triangles.size() <= 2000);
  }
}

TEST_CASE("CGAL geodesics and the discrete baseline agree on a curved closed mesh", "[burn3][smsp]") {
  const TriangleMesh3 mesh = loop_subdivided(cube(), 2);  // 192 faces, curved
  const MedialComplex mc = testing::built(mesh_as_complex(mesh));
  const ComplexLocator locator(mc);
  // Sources at vertex 5 (t0 = 0) and inside face 40 at weights (1/4, 1/2, 1/4) (t0 = 1/4).
  const std::array<double, 3> w = {0.25, 0.5, 0.25};
  ExactPoint3 c{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const auto& p = mesh.vertices[mesh.triangles[40][i]];
    c = c + mpq_class(w[i]) * ExactPoint3{mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])};
  }
  const std::vector<PointSource> sources = {{locator.locate(mc.vertex(5).exact), 0},
                                            {locator.locate(c), mpq_class(1, 4)}};
  REQUIRE(sgn(sources[1].location.snap_squared) == 0);
  SmspGeodesics g(mesh);
  g.add_source(at_vertex(mesh, 5), 0);
  g.add_source({40, w}, 0.25);
  g.build();
  DiscreteBurningOptions o;
  o.spacing = 0.02;
  o.sources = sources;
  const DiscreteBurning d = burn_discrete(mc, o);
  double worst = 0;
  for (std::uint32_t u = 0; u < mc.vertex_count(); ++u) {
    const double exact = g.distance(at_vertex(mesh, u));
    CHECK(d.vertex_bt[u] >= exact - 1e-9);  // the baseline is an upper bound
    worst = std::max(worst, d.vertex_bt[u] - exact);
  }
  CAPTURE(worst);
  CHECK(worst < 0.05);
}
