// The repair of defective meshes (medial3/mesh/mesh_repair.h): generated defective
// meshes with known answers, a project mesh with injected defects, and the command line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_checks.h"
#include "medial3/mesh/mesh_repair.h"
#include "medial3/mesh/mesh_solid.h"
#include "geometry3/synthetic_meshes.h"
#include "io/mesh_io.h"
#include "support.h"

using namespace grassfire;

namespace {

TriangleMesh3 united(TriangleMesh3 a, const TriangleMesh3& b, const std::string& name) {
  const auto n = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  a.source = name;
  return a;
}

TriangleMesh3 shifted(TriangleMesh3 m, double dx) {
  for (auto& p : m.vertices) p[0] += dx;
  return m;
}

std::set<std::array<std::array<double, 3>, 3>> triangle_set(const TriangleMesh3& m) {
  std::set<std::array<std::array<double, 3>, 3>> s;
  for (const auto& t : m.triangles) {
    std::array<std::array<double, 3>, 3> corners{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    std::sort(corners.begin(), corners.end());
    s.insert(corners);
  }
  return s;
}

bool same_betti(const BettiNumbers& b, long b0, long b1, long b2) { return b.b0 == b0 && b.b1 == b1 && b.b2 == b2; }

// The repaired mesh passes the exact solid checks, and its axis has the expected Betti
// numbers (the mesh builder checks them against the solid's: a mismatch throws).
void require_axis_betti(const TriangleMesh3& repaired, long b0, long b1, long b2) {
  REQUIRE_NOTHROW(require_closed_manifold(repaired));
  const SolidTopology solid = solid_topology(repaired);
  CHECK(same_betti(solid.betti, b0, b1, b2));
  const MeshAxis axis = mesh_medial_axis(repaired);
  CHECK(same_betti(axis.axis_betti, b0, b1, b2));
}

// An alpha wrap into one shell within alpha of the input, then require_axis_betti.
void require_wrapped_axis(const MeshRepair& r, double alpha, long b0, long b1, long b2) {
  CHECK(r.method == "alpha_wrap");
  CHECK(r.repaired_shells == 1);
  CHECK(r.hausdorff < alpha);
  require_axis_betti(r.mesh, b0, b1, b2);
}

}  // namespace

TEST_CASE("mesh repair: two overlapping spheres become one solid ball", "[mesh_repair]") {
  const TriangleMesh3 spheres =
      united(sphere_mesh({0, 0, 0}, 1, 2), sphere_mesh({1, 0, 0}, 1, 2), "two-spheres.off");
  const MeshDefects d = mesh_defects(spheres);
  CHECK(d.shells == 2);
  CHECK(d.self_intersecting_pairs > 0);
  CHECK(d.border_edges + d.non_manifold_edges + d.non_manifold_vertices == 0);
  CHECK_THROWS_WITH(require_solid(spheres), Catch::Contains("two-spheres.off") && Catch::Contains("intersect") &&
                                                Catch::Contains("--repair") && Catch::Contains("self-intersecting pair"));
  MeshRepairOptions o;
  o.alpha = 0.15;  // coarse: a small wrap for a quick axis
  const MeshRepair r = repair_mesh(spheres, o);
  CHECK(r.method == "alpha_wrap");
  CHECK(r.repaired_shells == 1);
  CHECK(r.offset == Approx(r.diagonal / 300));
  // The wrap is within about offset of the outer surface; the inner caps (inside the other
  // ball) are up to the radius 1 from it.
  CHECK(r.repaired_to_input < o.alpha);
  CHECK(r.input_to_repaired > 0.9);
  CHECK(r.input_to_repaired < 1.1);
  CHECK(solid_topology(r.mesh).shells[0].genus == 0);
  require_axis_betti(r.mesh, 1, 0, 0);
}

TEST_CASE("mesh repair: a torus with a pinched vertex is wrapped into a solid torus", "[mesh_repair]") {
  const TriangleMesh3 pinched = pinched_torus_mesh(2, 0.8, 24, 12);
  const MeshDefects d = mesh_defects(pinched);
  CHECK(d.non_manifold_vertices == 1);
  CHECK(d.border_edges == 0);
  CHECK(d.shells == 1);
  CHECK_THROWS_WITH(require_solid(pinched), Catch::Contains("pinched torus") && Catch::Contains("non-manifold") &&
                                                Catch::Contains("--repair"));
  MeshRepairOptions o;
  o.alpha = 0.3;
  o.offset = 0.05;  // the pinch becomes a neck of radius about 0.05
  require_wrapped_axis(repair_mesh(pinched, o), o.alpha, 1, 1, 0);
}

TEST_CASE("mesh repair: a closed mesh with a missing triangle is filled exactly", "[mesh_repair]") {
  const TriangleMesh3 torus = torus_mesh(2, 0.7, 24, 12);
  TriangleMesh3 open = torus;
  open.source = "open-torus.off";
  open.triangles.erase(open.triangles.begin() + 17);
  const MeshDefects d = mesh_defects(open);
  CHECK(d.border_edges == 3);
  CHECK(d.self_intersecting_pairs == 0);
  CHECK_THROWS_WITH(require_solid(open), Catch::Contains("open-torus.off") && Catch::Contains("not closed") &&
                                             Catch::Contains("3 border edges") && Catch::Contains("--repair"));
  const MeshRepair r = repair_mesh(open);
  CHECK(r.method == "fill");
  CHECK(r.filled_holes == 1);
  CHECK(r.added_triangles == 1);
  CHECK(triangle_set(r.mesh) == triangle_set(torus));  // the missing triangle itself
  // Nothing moved; the new triangle is as far from the rest as its points are from the
  // hole's border (the largest: its incentre's inradius-like distance, > 0).
  CHECK(r.input_to_repaired == Approx(0).margin(r.hausdorff_error));
  CHECK(r.repaired_to_input > 0);
  CHECK(r.repaired_to_input < 0.5);
  CHECK(mesh_orientation(r.mesh) == 1);
  require_axis_betti(r.mesh, 1, 1, 0);
}

TEST_CASE("mesh repair: a duplicated shell is welded back, a shifted copy is wrapped", "[mesh_repair]") {
  const TriangleMesh3 sphere = sphere_mesh({0, 0, 0}, 1, 2);
  const TriangleMesh3 twice = united(sphere, sphere, "twice.off");
  const MeshDefects d = mesh_defects(twice);
  CHECK(d.duplicate_vertices == sphere.vertices.size());
  CHECK(d.shells == 2);
  CHECK_THROWS_WITH(require_solid(twice), Catch::Contains("twice.off") && Catch::Contains("duplicate vertices"));
  const MeshRepair welded = repair_mesh(twice);
  CHECK(welded.method == "weld");
  CHECK(triangle_set(welded.mesh) == triangle_set(sphere));
  CHECK(welded.hausdorff == 0);

  const TriangleMesh3 overlapping = united(sphere, shifted(sphere, 0.01), "overlapping.off");
  MeshRepairOptions o;
  o.alpha = 0.15;
  const MeshRepair wrapped = repair_mesh(overlapping, o);
  CHECK(wrapped.defects.self_intersecting_pairs > 0);
  require_wrapped_axis(wrapped, o.alpha, 1, 0, 0);
}

TEST_CASE("mesh repair: a valid mesh is left alone", "[mesh_repair]") {
  const TriangleMesh3 torus = torus_mesh(2, 0.7, 24, 12);
  CHECK_NOTHROW(require_solid(torus));
  const MeshRepair r = repair_mesh(torus);
  CHECK(r.method == "none");
  CHECK(!r.defects.any());
  CHECK(describe_defects(r.defects) == "none");
  CHECK(r.mesh.triangles == torus.triangles);
}

TEST_CASE("mesh repair: a project mesh with injected defects", "[mesh_repair]") {
  const TriangleMesh3 joint = read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/joint.off");
  REQUIRE_NOTHROW(require_closed_manifold(joint));
  // A missing triangle: filled back exactly.
  TriangleMesh3 open = joint;
  open.triangles.erase(open.triangles.begin() + 100);
  const MeshRepair filled = repair_mesh(open);
  CHECK(filled.method == "fill");
  CHECK(triangle_set(filled.mesh) == triangle_set(joint));
  CHECK(filled.input_to_repaired == Approx(0).margin(filled.hausdorff_error));
  // One vertex pushed through the opposite side: self-intersecting; wrapped into one solid.
  TriangleMesh3 dented = joint;
  const double diagonal = filled.diagonal;
  dented.vertices[0][0] += 0.3 * diagonal;
  const MeshDefects d = mesh_defects(dented);
  INFO(describe_defects(d));
  CHECK(d.self_intersecting_pairs > 0);
  CHECK_THROWS_WITH(require_solid(dented), Catch::Contains("joint.off") && Catch::Contains("--repair"));
  // An overlapping copy (a second shell through the first).
  const TriangleMesh3 two = united(joint, shifted(joint, 0.2 * diagonal), "two-joints.off");
  MeshRepairOptions o;
  o.alpha = diagonal / 30;
  const MeshRepair wrapped = repair_mesh(two, o);
  CHECK(wrapped.defects.shells == 2);
  CHECK(wrapped.method == "alpha_wrap");
  CHECK(wrapped.repaired_shells == 1);
  // The wrap follows the input to about alpha (1.13 alpha at most in study_mesh_repair).
  CHECK(wrapped.repaired_to_input < 1.5 * o.alpha);
  CHECK(solid_topology(wrapped.mesh).betti.b0 == 1);
}

TEST_CASE("medial3d --repair: refusal names the file and the option, and the report", "[mesh_repair][cli]") {
  using testing::run_cli;
  const std::string path = testing::temp_path("pinched_torus.off");
  write_off(pinched_torus_mesh(2, 0.8, 24, 12), path);
  const auto refused = run_cli("medial3d " + path);
  INFO(refused.output);
  CHECK(refused.code == 1);
  CHECK(refused.output.find(path) != std::string::npos);
  CHECK(refused.output.find("non-manifold") != std::string::npos);
  CHECK(refused.output.find("--repair") != std::string::npos);
  const std::string json = testing::temp_path("pinched_repair.json");
  const auto ok = run_cli("medial3d " + path + " --repair --repair-alpha 0.3 --repair-offset 0.05 --json " + json);
  INFO(ok.output);
  REQUIRE(ok.code == 0);
  CHECK(ok.output.find("repaired by alpha_wrap") != std::string::npos);
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in);
  CHECK(report["repair"]["method"] == "alpha_wrap");
  CHECK(report["repair"]["alpha"] == 0.3);
  CHECK(report["repair"]["offset"] == 0.05);
  CHECK(report["repair"]["defects"]["non_manifold_vertices"] == 1);
  CHECK(report["repair"]["hausdorff"]["distance"].get<double>() < 0.3);
  CHECK(report["axis"]["betti"] == nlohmann::json::array({1, 1, 0}));
  const auto usage = run_cli("medial3d " + path + " --repair-alpha 0.3");
  CHECK(usage.code != 0);
  CHECK(usage.output.find("need --repair") != std::string::npos);
  const auto burn = run_cli("complex " + path + " --repair --repair-alpha 0.3 --repair-offset 0.05");
  INFO(burn.output);
  CHECK(burn.code == 0);
  CHECK(burn.output.find("repaired by alpha_wrap") != std::string::npos);
}

TEST_CASE("medial3d --max-samples: a refusal over the limit names the option and the axis is built within it", "[mesh_axis][cli]") {
  using testing::run_cli;
  const std::string path = testing::temp_path("thin_torus.off");
  write_off(torus_mesh(2, 0.02, 24, 3), path);  // its axis needs a round of 5,040 samples
  const auto refused = run_cli("medial3d " + path + " --max-samples 1000");
  INFO(refused.output);
  CHECK(refused.code == 1);
  CHECK(refused.output.find(path) != std::string::npos);
  CHECK(refused.output.find("over the limit of 1000 (medial3d --max-samples)") != std::string::npos);
  CHECK(refused.output.find("no axis") != std::string::npos);
  const auto ok = run_cli("medial3d " + path);
  INFO(ok.output);
  CHECK(ok.code == 0);
  CHECK(ok.output.find("Betti [1,1,0]") != std::string::npos);
  const auto bad = run_cli("medial3d " + path + " --max-samples 10");
  CHECK(bad.code != 0);
  CHECK(bad.output.find("--max-samples") != std::string::npos);
}
