// Mesh solidity checks and the medial3d command (good and bad inputs).
#include <catch2/catch.hpp>

#include <fstream>

#include "medial3/mesh/mesh_checks.h"
#include "complex3/simplicial_homology.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "complex3/medial_complex.h"
#include "io/mesh_io.h"
#include "support.h"

using namespace grassfire;

namespace {

TriangleMesh3 project_mesh(const std::string& name) { return read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/" + name); }
std::string test_file(const std::string& name) { return std::string(GF_TEST_DATA) + "/builders3/" + name; }

bool exists(const std::string& path) { return std::ifstream(path).good(); }

TriangleMesh3 two_tetrahedra_sharing_a_vertex() {
  TriangleMesh3 m;
  m.source = "pinched.off";
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}};
  return m;
}

}  // namespace

TEST_CASE("meshes that do not bound a solid are rejected, naming the file and the edge", "[builders3]") {
  const TriangleMesh3 cube = project_mesh("cube.off");
  TriangleMesh3 open = cube;
  open.triangles.pop_back();
  CHECK_THROWS_WITH(require_closed_manifold(open), Catch::Contains("cube.off") && Catch::Contains("edge (") &&
                                                 Catch::Contains("not closed"));
  TriangleMesh3 flipped = cube;
  std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
  CHECK_THROWS_WITH(require_closed_manifold(flipped), Catch::Contains("same direction"));
  TriangleMesh3 duplicate = cube;
  duplicate.vertices.push_back(duplicate.vertices[0]);
  duplicate.triangles[0][0] = 8;
  CHECK_THROWS_WITH(require_closed_manifold(duplicate), Catch::Contains("duplicate vertices 0 and 8 (same position (-1, -1, -1))"));
  TriangleMesh3 unused = cube;
  unused.vertices.push_back({5, 5, 5});
  CHECK_THROWS_WITH(require_closed_manifold(unused), Catch::Contains("vertex 8 at (5, 5, 5) is not used"));
  CHECK_THROWS_WITH(require_closed_manifold(two_tetrahedra_sharing_a_vertex()),
                    Catch::Contains("pinched.off") && Catch::Contains("vertex 0 at (0, 0, 0) is non-manifold"));
  CHECK_NOTHROW(require_closed_manifold(cube));
  CHECK(mesh_orientation(cube) == 1);
}

TEST_CASE("medial3d: outputs for good input, errors and no output for bad input", "[builders3]") {
  using testing::run_cli;
  const std::string out = testing::temp_path("gf_medial3d_out");
  std::remove((out + ".ma").c_str());
  std::remove((out + ".json").c_str());
  const auto ok = run_cli("medial3d " + std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin --ma " + out + ".ma --json " + out + ".json");
  INFO(ok.output);
  CHECK(ok.code == 0);
  CHECK(ok.output.find("24 segments") != std::string::npos);
  CHECK(exists(out + ".ma"));
  CHECK(exists(out + ".json"));
  CHECK(run_cli("medial3d " + test_file("cube.hs")).output.find("12 triangles") != std::string::npos);
  CHECK(run_cli("medial3d " + std::string(GF_PROJECT_DATA) + "/meshes/tripod.off --kind mesh --samples 2").code == 0);
  std::remove((out + ".ma").c_str());
  std::remove((out + ".json").c_str());
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"empty.balls", "no balls"},
      {"negative.balls", "negative.balls"},
      {"nan.balls", "nan.balls"},
      {"open_cube.off --kind mesh", "not closed"},
      {"open_cube.off", "not closed"},
      {"dented_cube.off --kind convex", "not convex"},
      {"missing.balls", "missing.balls"},
  };
  for (const auto& [args, message] : bad) {
    const auto r = run_cli("medial3d " + test_file(args) + " --ma " + out + ".ma --json " + out + ".json");
    INFO(args << ": " << r.output);
    CHECK(r.code != 0);
    CHECK(r.output.find(message) != std::string::npos);
    CHECK_FALSE(exists(out + ".ma"));
    CHECK_FALSE(exists(out + ".json"));
  }
}
