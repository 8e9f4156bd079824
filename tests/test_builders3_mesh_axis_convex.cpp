// The mesh axis of convex polyhedra against their exact medial axis (convex_polyhedron_axis.h):
// the same Betti numbers, and Hausdorff distance within the sampling bound of the
// construction (mesh_axis.h step 4 and 6). The bound: a Voronoi vertex is the centre of an
// empty ball through samples at spacing h, so the kept axis lies within about h of the
// true one (extra <= h); the separation test prunes a sheet where its two touching samples
// are closer than lambda h, i.e. where 2 R sin(alpha / 2) < lambda h (alpha the object
// angle), so the true axis is found wherever R >= lambda h (missing_core <= h), and the
// band left out along the convex edges and corners is within lambda h / sin(alpha / 2)
// along a sheet, at most 2 lambda h on these solids (the octahedron's corners: 1.5 lambda h;
// the cube's: sqrt(3/2) lambda h). h is the finest spacing of the axis' round.
#include <catch2/catch.hpp>

#include <cmath>

#include "complex3/builders/convex_polyhedron_axis.h"
#include "complex3/builders/mesh_axis.h"
#include "complex3/builders/synthetic_meshes.h"
#include "complex3/complex_distance.h"
#include "complex3/medial_complex.h"
#include "io/mesh_io.h"

using namespace grassfire;

namespace {

TriangleMesh3 project_mesh(const std::string& name) { return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name); }

std::vector<double> radii(const RawComplex& c) {
  std::vector<double> r;
  for (const mpq_class& r2 : c.radius_squared) r.push_back(std::sqrt(r2.get_d()));
  return r;
}

struct Agreement {
  double h = 0, extra = 0, missing = 0, missing_core = 0;
};

Agreement compare_with_exact_axis(const TriangleMesh3& mesh, double samples_per_edge) {
  CAPTURE(mesh.source, samples_per_edge);
  MeshAxisOptions options;
  options.samples_per_edge = samples_per_edge;
  const MeshAxis a = mesh_medial_axis(mesh, options);
  const ConvexAxis exact = convex_polyhedron_axis(convex_polyhedron_from_mesh(mesh));
  CHECK(a.axis_betti == BettiNumbers{1, 0, 0});
  CHECK(betti_numbers(exact.complex) == BettiNumbers{1, 0, 0});
  CHECK(a.complex.triangles.size() > 0);  // sheets, not a point
  MedialComplex(a.complex).validate();
  Agreement g;
  g.h = a.rounds[a.axis_round].spacing;
  const double step = g.h / 8, lambda = MeshAxisOptions{}.separation;
  g.extra = directed_complex_distance(a.complex, exact.complex, step);
  g.missing = directed_complex_distance(exact.complex, a.complex, step);
  g.missing_core = directed_complex_distance(exact.complex, radii(exact.complex), lambda * g.h, a.complex, step);
  CAPTURE(g.h, g.extra, g.missing, g.missing_core);
  CHECK(g.extra <= g.h);
  CHECK(g.missing_core <= g.h);
  CHECK(g.missing <= 2 * lambda * g.h + step);
  return g;
}

}  // namespace

TEST_CASE("complex distance: hand-made complexes", "[mesh_axis][convex]") {
  RawComplex square;  // the unit square in z = 0
  square.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  RawComplex lifted = square;  // the same square at z = 1/2, and one far vertex
  for (ExactPoint3& v : lifted.vertices) v.z = mpq_class(1, 2);
  CHECK(complex_hausdorff(square, lifted, 0.01) == Approx(0.5));
  lifted.vertices.push_back({3, 0, mpq_class(1, 2)});
  CHECK(directed_complex_distance(lifted, square, 0.01) == Approx(std::sqrt(4 + 0.25)));
  CHECK(directed_complex_distance(square, lifted, 0.01) == Approx(0.5));
  // Only the points where the per-vertex value is at least 1: the far vertex alone.
  CHECK(directed_complex_distance(lifted, {0, 0, 0, 0, 2}, 1, square, 0.01) == Approx(std::sqrt(4.25)));
  CHECK(directed_complex_distance(lifted, {0, 0, 0, 0, 0}, 1, square, 0.01) == 0);
}

TEST_CASE("mesh axes of convex polyhedra agree with the exact convex axis", "[mesh_axis][convex]") {
  // Before the pole-support part of the thickness rule the octahedron's mesh axis was one
  // vertex at every density tried here (its sheets' samples are 1.15 R apart, below the
  // separation threshold once R < 2 h / 1.15).
  for (const char* name : {"cube.off", "octahedron.off"}) {
    const TriangleMesh3 mesh = project_mesh(name);
    const Agreement coarse = compare_with_exact_axis(mesh, 1);
    const Agreement fine = compare_with_exact_axis(mesh, 8);
    CHECK(fine.missing < coarse.missing);
  }
  for (std::uint32_t seed : {1u, 2u}) compare_with_exact_axis(random_convex_hull_mesh(seed, 16), 1);
}
