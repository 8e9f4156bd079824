// Mesh axes (mesh_axis.h) under transformations that must not change them, on nested
// shells, and at the refinement cap through the program: exact rigid motions move the
// inner Voronoi complex exactly, relabelling the mesh changes nothing, rounded rotations keep the Betti
// numbers, a solid inside a cavity keeps both components and the cavity, and the program
// refuses (message, exit code, no file) when the cap is reached.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <random>
#include <tuple>

#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_samples.h"
#include "geometry3/synthetic_meshes.h"
#include "complex3/medial_complex.h"
#include "io/mesh_io.h"
#include "support.h"

using namespace grassfire;

namespace {

TriangleMesh3 project_mesh(const std::string& name) { return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name); }

// The axis vertices with their R^2, sorted: the axis as a point set, independent of the
// order in which the Delaunay triangulation enumerates its cells.
using WeightedVertex = std::tuple<mpq_class, mpq_class, mpq_class, mpq_class>;
std::vector<WeightedVertex> weighted_vertices(const RawComplex& c, const std::function<ExactPoint3(const ExactPoint3&)>& move) {
  std::vector<WeightedVertex> out;
  for (std::size_t v = 0; v < c.vertices.size(); ++v) {
    const ExactPoint3 p = move(c.vertices[v]);
    out.emplace_back(p.x, p.y, p.z, c.radius_squared[v]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

ExactPoint3 same(const ExactPoint3& p) { return p; }

void check_same_counts(const MeshAxis& a, const MeshAxis& b) {
  CHECK(b.axis_betti == a.axis_betti);
  CHECK(b.complex.vertices.size() == a.complex.vertices.size());
  CHECK(b.complex.triangles.size() == a.complex.triangles.size());
  CHECK(b.complex.segments.size() == a.complex.segments.size());
  CHECK(b.complex.border_rules.size() == a.complex.border_rules.size());
  CHECK(b.refinements() == a.refinements());
}

}  // namespace

TEST_CASE("mesh axis under an exact rigid motion: the inner Voronoi complex moves exactly", "[mesh_axis]") {
  // (x, y, z) -> (-y, x, z) + (1/2, -1/4, 1): a quarter turn and a dyadic translation,
  // exact on the sample lattice. The inner Voronoi complex V_in (every Voronoi vertex
  // inside, inner_voronoi.h) is a function of the sample set: it must be the same point set
  // moved, exactly, with the same R^2. The pruned axis is homotopy equivalent to it either
  // way (the Betti numbers are equal), but which cells a collapse removes follows the
  // sample order, which the rotation changes (the samples are numbered lexicographically):
  // only its topology is compared.
  const auto motion = [](const ExactPoint3& p) { return ExactPoint3{-p.y + mpq_class(1, 2), p.x - mpq_class(1, 4), p.z + 1}; };
  for (const TriangleMesh3& mesh : {torus_mesh(2, 0.5, 16, 8), project_mesh("double-torus-example.off")}) {
    CAPTURE(mesh.source);
    TriangleMesh3 moved = mesh;
    for (auto& p : moved.vertices) p = {-p[1] + 0.5, p[0] - 0.25, p[2] + 1};
    const double h = mean_edge_length(mesh);
    const InnerVoronoi va = inner_voronoi(sample_surface(mesh, h), SolidLocator(mesh));
    const InnerVoronoi vb = inner_voronoi(sample_surface(moved, h), SolidLocator(moved));
    REQUIRE(va.vertices.size() > 0);
    CHECK(vb.vertices.size() == va.vertices.size());
    CHECK(vb.polygons.size() == va.polygons.size());
    CHECK(vb.segments.size() == va.segments.size());
    std::vector<WeightedVertex> a, b;
    for (const auto& v : va.vertices) {
      mpq_class r2;
      const ExactPoint3 p = motion(exact_point(va.samples, v.centre, &r2));
      a.emplace_back(p.x, p.y, p.z, r2);
    }
    for (const auto& v : vb.vertices) {
      mpq_class r2;
      const ExactPoint3 p = exact_point(vb.samples, v.centre, &r2);
      b.emplace_back(p.x, p.y, p.z, r2);
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    CHECK(a == b);
    const MeshAxis axis_a = mesh_medial_axis(mesh), axis_b = mesh_medial_axis(moved);
    CHECK(axis_a.axis_betti == axis_a.solid.betti);
    CHECK(axis_b.axis_betti == axis_a.axis_betti);
    CHECK(axis_b.refinements() == axis_a.refinements());
  }
}

TEST_CASE("mesh axis under a rounded rotation: the Betti numbers stay", "[mesh_axis]") {
  // The rotation by the Pythagorean angle (cos, sin) = (3/5, 4/5) about (1, 1, 1)-ish axes
  // is not exact on doubles: the samples move by rounding, so only the topology is
  // invariant (the counts may differ).
  const TriangleMesh3 meshes[] = {torus_mesh(2, 0.5, 24, 12), project_mesh("double-torus-example.off"),
                                  plate_with_holes(5, 3, {{1, 1}, {3, 1}})};
  for (const TriangleMesh3& mesh : meshes) {
    CAPTURE(mesh.source);
    TriangleMesh3 turned = mesh;
    for (auto& p : turned.vertices) {
      const double x = 0.6 * p[0] - 0.8 * p[1], y = 0.8 * p[0] + 0.6 * p[1];
      p = {x, 0.6 * y - 0.8 * p[2], 0.8 * y + 0.6 * p[2]};
    }
    const MeshAxis a = mesh_medial_axis(turned);
    CHECK(a.solid.betti == solid_topology(mesh).betti);
    CHECK(a.axis_betti == a.solid.betti);
  }
}

TEST_CASE("mesh axis of a relabelled mesh: the same axis", "[mesh_axis]") {
  // Vertices renumbered and triangles shuffled (each keeps its corners in cyclic order):
  // the same surface, the same samples, the same axis as a point set.
  std::mt19937 rng(5);
  for (const TriangleMesh3& mesh : {torus_mesh(2, 0.5, 16, 8), project_mesh("double-torus-example.off")}) {
    CAPTURE(mesh.source);
    std::vector<std::uint32_t> to(mesh.vertices.size());
    std::iota(to.begin(), to.end(), 0u);
    std::shuffle(to.begin(), to.end(), rng);
    TriangleMesh3 relabelled = mesh;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) relabelled.vertices[to[v]] = mesh.vertices[v];
    for (auto& t : relabelled.triangles) {
      for (auto& v : t) v = to[v];
      std::rotate(t.begin(), t.begin() + rng() % 3, t.end());
    }
    std::shuffle(relabelled.triangles.begin(), relabelled.triangles.end(), rng);
    const MeshAxis a = mesh_medial_axis(mesh), b = mesh_medial_axis(relabelled);
    check_same_counts(a, b);
    CHECK(weighted_vertices(b.complex, same) == weighted_vertices(a.complex, same));
  }
}

TEST_CASE("mesh axis of nested shells: a solid in a cavity keeps both and the cavity", "[mesh_axis]") {
  // A 5^3 block hollowed to a 3^3 cavity with one voxel floating at its centre: two solids
  // (b0 = 2) and the cavity between them (b2 = 1). The axis keeps the cavity as a closed
  // surface around the inner solid's axis: the solid's Betti numbers, b2 included.
  std::vector<Voxel> nested = hollow_block_voxels(5);
  nested.push_back({2, 2, 2});
  const TriangleMesh3 mesh = voxel_mesh(nested, 1, "nested shells");
  const MeshAxis a = mesh_medial_axis(mesh);
  CHECK(a.solid.betti == BettiNumbers{2, 0, 1});
  CHECK(a.axis_betti == BettiNumbers{2, 0, 1});
  CHECK(betti_numbers(a.complex) == BettiNumbers{2, 0, 1});
  REQUIRE(a.solid.shells.size() == 3);
  int depths = 0;
  for (const MeshShell& s : a.solid.shells) depths += s.depth;
  CHECK(depths == 0 + 1 + 2);  // outer surface, cavity wall, inner solid
  MedialComplex(a.complex).validate();
}

TEST_CASE("medial3d at the refinement cap: one message, exit code 1, no output", "[mesh_axis]") {
  const std::string joint = std::string(GF_PROJECT_DATA) + "/meshes/joint.off";
  const std::string json = grassfire::testing::temp_path("gf_mesh_axis_cap.json");
  const std::string ma = grassfire::testing::temp_path("gf_mesh_axis_cap.ma");
  std::remove(json.c_str());
  std::remove(ma.c_str());
  const auto refused = grassfire::testing::run_cli("medial3d " + joint + " --refinements 0 --json " + json + " --ma " + ma);
  CHECK(refused.code != 0);
  CHECK_THAT(refused.output, Catch::Contains("joint.off") && Catch::Contains("the solid 1:2:0") &&
                                 Catch::Contains("after 0 refinements") && Catch::Contains("no axis is returned"));
  CHECK(!std::ifstream(json).good());
  CHECK(!std::ifstream(ma).good());
  // With the refinements allowed the same command succeeds and reports them.
  const auto built = grassfire::testing::run_cli("medial3d " + joint + " --quiet --json " + json);
  REQUIRE(built.code == 0);
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in);
  CHECK(report["solid_betti"] == nlohmann::json({1, 2, 0}));
  CHECK(report["axis_betti"] == nlohmann::json({1, 2, 0}));
  CHECK(report["refinements"].get<int>() >= 1);
  std::remove(json.c_str());
}
