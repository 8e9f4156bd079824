// Meshes as people have them (docs/formats.md): STL binary and ASCII, welding of exactly
// repeated vertices, dropping of degenerate and repeated faces (with counts), and the
// refusal, naming the file's faces, of what remains open, non-manifold or self-intersecting.
// The STL files are written by tests/data/stl/make_stl.py.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <set>

#include "medial3/mesh/mesh_checks.h"
#include "medial3/mesh/mesh_embedding.h"
#include "complex3/complex_intersections.h"
#include "geometry3/exact_predicates3.h"
#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "io/mesh_input.h"
#include "support.h"

using namespace grassfire;
using grassfire::testing::error_of;

namespace {

std::string stl(const std::string& name) { return std::string(GF_TEST_DATA) + "/stl/" + name; }

using Corners = std::array<std::array<double, 3>, 3>;

// The triangles as point triples, rotated to start at their smallest corner (orientation
// kept), sorted: equal for meshes that are the same surface whatever their numbering.
std::vector<Corners> geometry(const TriangleMesh3& m) {
  std::vector<Corners> g;
  for (const auto& t : m.triangles) {
    Corners c{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    g.push_back(c);
  }
  std::sort(g.begin(), g.end());
  return g;
}

// Definition-level welding: every vertex compared with every earlier one (quadratic), the
// triangles kept when their three welded corners differ and their set is new; then only the
// used first copies, in file order.
TriangleMesh3 weld_by_definition(const TriangleMesh3& in, MeshCleanup& counts) {
  const std::size_t n = in.vertices.size();
  std::vector<std::uint32_t> first(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    first[v] = v;
    for (std::uint32_t u = 0; u < v; ++u)
      if (in.vertices[u] == in.vertices[v]) {
        first[v] = u;
        ++counts.welded_vertices;
        break;
      }
  }
  std::vector<std::array<std::uint32_t, 3>> kept;
  std::vector<std::set<std::uint32_t>> sets;
  for (const auto& t : in.triangles) {
    const std::array<std::uint32_t, 3> w{first[t[0]], first[t[1]], first[t[2]]};
    const std::set<std::uint32_t> s(w.begin(), w.end());
    if (s.size() < 3) ++counts.degenerate_faces;
    else if (std::find(sets.begin(), sets.end(), s) != sets.end()) ++counts.repeated_faces;
    else kept.push_back(w), sets.push_back(s);
  }
  TriangleMesh3 out;
  std::map<std::uint32_t, std::uint32_t> index;
  for (std::uint32_t v = 0; v < n; ++v) {
    if (first[v] != v) continue;
    const bool used = std::any_of(kept.begin(), kept.end(), [&](const auto& t) { return t[0] == v || t[1] == v || t[2] == v; });
    if (!used) {
      ++counts.unused_vertices;
      continue;
    }
    index[v] = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.push_back(in.vertices[v]);
  }
  for (const auto& t : kept) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return out;
}

}  // namespace

TEST_CASE("STL: ASCII (upper case) and binary (header 'solid ...') tetrahedra are the OFF tetrahedron", "[stl]") {
  const TriangleMesh3 off = read_triangle_mesh(std::string(GF_TEST_DATA) + "/3d/tetrahedron.off");
  std::ifstream binary(stl("tetrahedron_binary.stl"), std::ios::binary);
  std::string first_word(5, ' ');
  binary.read(&first_word[0], 5);
  REQUIRE(first_word == "solid");  // the size rule, not the first word, must make it binary
  for (const char* f : {"tetrahedron_ascii.stl", "tetrahedron_binary.stl"}) {
    CAPTURE(f);
    const TriangleMesh3 m = read_triangle_mesh(stl(f));
    CHECK(m.vertices.size() == 4);
    CHECK(geometry(m) == geometry(off));
    CHECK(m.cleanup.file_vertices == 12);
    CHECK(m.cleanup.file_faces == 4);
    CHECK(m.cleanup.welded_vertices == 8);
    CHECK_NOTHROW(require_closed_manifold(m));
  }
}

TEST_CASE("STL: a Thingi10K-like soup is welded, its repeated and degenerate facets dropped and counted", "[stl]") {
  const TriangleMesh3 cube = read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/cube.off");
  for (const char* f : {"cube_soup.stl", "cube_soup_ascii.stl"}) {
    CAPTURE(f);
    const TriangleMesh3 m = read_triangle_mesh(stl(f));
    // 14 facets, 42 corners on 8 points: 34 welded; facet 12 repeats facet 3; facet 13 has
    // two equal corners.
    CHECK(m.cleanup.file_faces == 14);
    CHECK(m.cleanup.file_vertices == 42);
    CHECK(m.cleanup.welded_vertices == 34);
    CHECK(m.cleanup.repeated_faces == 1);
    CHECK(m.cleanup.degenerate_faces == 1);
    CHECK(m.cleanup.unused_vertices == 0);
    CHECK(geometry(m) == geometry(cube));
    CHECK(m.triangle_origin == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    CHECK(describe_cleanup(m.cleanup) == "welded 34 repeated vertices, dropped 1 degenerate face, 1 repeated face");
    CHECK_NOTHROW(require_closed_manifold(m));
    CHECK(mesh_orientation(m) == 1);
  }
}

TEST_CASE("medial3d reports what the reader welded and dropped, on stderr and in the JSON", "[stl]") {
  const std::string json = testing::temp_path("soup.json");
  const auto r = testing::run_cli("medial3d " + stl("cube_soup.stl") + " --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("cube_soup.stl: welded 34 repeated vertices, dropped 1 degenerate face, 1 repeated face"));
  std::ifstream in(json);
  const nlohmann::json report = nlohmann::json::parse(in);
  CHECK(report["mesh_input"]["welded_vertices"] == 34);
  CHECK(report["mesh_input"]["repeated_faces"] == 1);
  CHECK(report["mesh_input"]["degenerate_faces"] == 1);
  CHECK(report["mesh_input"]["triangles"] == 12);
  // The same solid as cube.off: the same exact axis.
  const auto off = testing::run_cli("medial3d " + std::string(GF_PROJECT_DATA) + "/meshes/cube.off");
  const std::string counts = r.output.substr(r.output.find("(convex)"), r.output.find("Betti") - r.output.find("(convex)"));
  CHECK_THAT(off.output, Catch::Contains(counts));
  std::remove(json.c_str());
}

TEST_CASE("welding agrees with the quadratic definition on random soups", "[stl]") {
  std::mt19937 rng(20240610);
  for (int round = 0; round < 200; ++round) {
    TriangleMesh3 m;
    m.source = "random";
    const int points = 3 + static_cast<int>(rng() % 12), corners = 3 * (1 + static_cast<int>(rng() % 20));
    std::vector<std::array<double, 3>> pool;
    for (int i = 0; i < points; ++i) pool.push_back({double(rng() % 3), double(rng() % 2) - 0.0, i % 4 == 0 ? -0.0 : 0.0});
    for (int i = 0; i < corners; ++i) m.vertices.push_back(pool[rng() % pool.size()]);
    for (std::uint32_t f = 0; 3 * f < m.vertices.size(); ++f) append_polygon_face(m, {3 * f, 3 * f + 1, 3 * f + 2});
    MeshCleanup expected;
    const TriangleMesh3 reference = weld_by_definition(m, expected);
    const std::vector<std::array<double, 3>> file_points = m.vertices;
    weld_and_drop(m);
    CAPTURE(round);
    CHECK(m.vertices == reference.vertices);
    CHECK(m.triangles == reference.triangles);
    CHECK(m.cleanup.welded_vertices == expected.welded_vertices);
    CHECK(m.cleanup.degenerate_faces == expected.degenerate_faces);
    CHECK(m.cleanup.repeated_faces == expected.repeated_faces);
    CHECK(m.cleanup.unused_vertices == expected.unused_vertices);
    for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {  // the origin is the first copy in the file
      const std::uint32_t origin = m.vertex_origin[v];
      CHECK(file_points[origin] == m.vertices[v]);
      CHECK(std::find(file_points.begin(), file_points.begin() + origin, m.vertices[v]) == file_points.begin() + origin);
    }
  }
}

TEST_CASE("an OFF mesh with an exactly repeated vertex is welded, not refused", "[stl]") {
  const TriangleMesh3 m = read_triangle_mesh(std::string(GF_TEST_DATA) + "/3d/cube_repeated_vertex.off");
  CHECK(m.cleanup.welded_vertices == 1);
  CHECK(m.vertices.size() == 8);
  CHECK_NOTHROW(require_closed_manifold(m));
}

TEST_CASE("STL: what remains open, non-manifold or self-intersecting is refused, naming the faces", "[stl]") {
  // open_cube.stl lacks facet 11 (2 1 6) of cube.off; facets 1, 5 and 10 share its edges.
  const std::vector<std::pair<std::string, std::regex>> cases = {
      {"open_cube.stl", std::regex(".*open_cube\\.stl: edge \\(\\d+, \\d+\\) from \\(.*\\) to \\(.*\\) of face (1|5|10) "
                                   "has one triangle \\(the mesh is not closed\\)")},
      {"pinched_cubes.stl", std::regex(".*pinched_cubes\\.stl: vertex \\d+ at \\(1, 1, 1\\) is non-manifold.*")},
      {"crossing_tetrahedra.stl", std::regex(".*crossing_tetrahedra\\.stl: face [0-3] and face [4-7] intersect "
                                             "\\(the mesh is self-intersecting\\)")},
      {"zero_area.stl", std::regex(".*zero_area\\.stl: face 5 has zero area.*")},
  };
  for (const auto& [file, expected] : cases) {
    const std::string message = error_of([&] { require_closed_manifold(read_triangle_mesh(stl(file))); });
    INFO(message);
    CHECK(std::regex_match(message, expected));
  }
}

TEST_CASE("the mesh crossing test agrees with the complex embedding test on random triangles", "[stl]") {
  // Triangles on the 3x3x3 grid share vertices, edges and planes often; the two tests are
  // independent (CGAL Epick segment/triangle predicates against exact integer cone tests).
  std::mt19937 rng(7);
  TriangleMesh3 grid;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) grid.vertices.push_back({double(x), double(y), double(z)});
  int crossing = 0;
  for (int round = 0; round < 400; ++round) {
    TriangleMesh3 m = grid;
    std::set<std::set<std::uint32_t>> sets;
    while (m.triangles.size() < 2 + rng() % 4) {
      const std::array<std::uint32_t, 3> t{std::uint32_t(rng() % 27), std::uint32_t(rng() % 27), std::uint32_t(rng() % 27)};
      if (collinear(exact_point(m.vertices[t[0]]), exact_point(m.vertices[t[1]]), exact_point(m.vertices[t[2]]))) continue;
      if (sets.insert({t.begin(), t.end()}).second) m.triangles.push_back(t);
    }
    const bool by_mesh = first_crossing(m).has_value();
    CAPTURE(round);
    CHECK(by_mesh == first_improper_intersection(mesh_as_complex(m)).has_value());
    crossing += by_mesh;
  }
  CHECK(crossing > 50);  // both outcomes are exercised
  CHECK(crossing < 350);
}

TEST_CASE("a flat pillow folds onto itself and is refused", "[stl]") {
  // A unit square covered twice with different diagonals: closed, manifold, zero volume;
  // the two covers meet along edges only, so only the fold test sees the overlap.
  TriangleMesh3 m;
  m.source = "pillow.off";
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 0, 3}, {1, 3, 2}};
  CHECK_THAT(error_of([&] { require_closed_manifold(m); }),
             Catch::Contains("pillow.off: face") && Catch::Contains("fold onto each other"));
}

TEST_CASE("STL: malformed files get one message naming the file and the problem", "[stl]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bad_size.stl", "bad_size.stl: binary STL: the header announces 5 facets, which take 84 + 50 * 5 = 334 bytes, "
                       "but the file has 284 bytes"},
      {"bad_nan.stl", "bad_nan.stl: facet 1: vertex coordinate is NaN or infinite"},
      {"bad_ascii.stl", "bad_ascii.stl:7: ASCII STL: 'endloop' is not a finite number"},  // line 6 has two numbers
  };
  for (const auto& [file, expected] : cases) CHECK(error_of([&] { read_triangle_mesh(stl(file)); }) == stl("") + expected);
  CHECK_THAT(error_of([] { parse_stl("solid x\nfacet normal 0 0 1\n", "short.stl"); }),
             Catch::Contains("short.stl:2: ASCII STL: file ends early: expected 'outer'"));
  CHECK_THAT(error_of([] { parse_stl("hello", "tiny.stl"); }), Catch::Contains("tiny.stl: not an STL file"));
  // A binary header announcing 10^9 facets in a 100-byte file: refused before allocating.
  std::string huge(100, '\0');
  huge[80] = '\x00', huge[81] = '\xca', huge[82] = '\x9a', huge[83] = '\x3b';
  CHECK_THAT(error_of([&] { parse_stl(huge, "huge.stl"); }), Catch::Contains("announces 1000000000 facets"));
}
