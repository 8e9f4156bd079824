// 3D formats: .ma, OFF, PLY, OBJ, ball lists; round trips and malformed files.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "complex3/medial_complex.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_export.h"
#include "io/complex_ma.h"
#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "number/exact_sum.h"
#include "support.h"

using namespace grassfire;
using grassfire::testing::error_of;

namespace {

std::string data(const std::string& name) { return std::string(GF_TEST_DATA) + "/3d/" + name; }

std::string temp_path(const std::string& name) { return grassfire::testing::temp_path("grassfire_complex3_" + name); }

// Each file must be rejected by `read` with a message containing the expected text.
template <class Read>
void check_rejections(const std::vector<std::pair<std::string, std::string>>& cases, Read read) {
  for (const auto& [file, expected] : cases) {
    CAPTURE(file);
    CHECK_THAT(error_of([&] { read(data(file)); }), Catch::Contains(expected));
  }
}

}  // namespace

TEST_CASE("exact decimals", "[complex3]") {
  CHECK(*parse_exact_decimal("0.1") == make_rational(1, 10));
  CHECK(*parse_exact_decimal("-2.5e-3") == make_rational(-1, 400));
  CHECK(*parse_exact_decimal("3E2") == 300);
  CHECK(*parse_exact_decimal(".5") == make_rational(1, 2));
  for (const char* bad : {"nan", "inf", "1e", "--1", "0x10", "", ".", "1.2.3"}) CHECK_FALSE(parse_exact_decimal(bad));
  CHECK(*exact_decimal_string(make_rational(-1, 400)) == "-0.0025");
  CHECK(*exact_decimal_string(mpq_class(12)) == "12");
  CHECK_FALSE(exact_decimal_string(make_rational(1, 3)));
}

TEST_CASE(".ma: reading a small axis with a hair, faces imply their edges", "[complex3]") {
  const RawComplex raw = read_ma(data("two_triangles_segment.ma"));
  CHECK(raw.vertices.size() == 5);
  CHECK(raw.triangles.size() == 2);
  REQUIRE(raw.segments.size() == 1);
  CHECK(raw.segments[0] == std::array<std::uint32_t, 2>{3, 4});
  CHECK(raw.radius_squared[4] == make_rational(1, 100));  // r = 0.1 exactly, squared
  CHECK(raw.vertices[3].z == make_rational(1, 2));
  const MedialComplex mc(raw);
  mc.validate();
  CHECK(mc.count(EdgeStratum::Dangling) == 1);
  CHECK(mc.count(EdgeStratum::Manifold) == 1);
  CHECK(mc.count(EdgeStratum::Border) == 4);
  CHECK(mc.vertex(4).kind == VertexKind::SegmentEnd);
  CHECK(mc.vertex(3).kind == VertexKind::SingularPoint);  // a border point with a hair
  CHECK(mc.ignition_at_vertex(4) == Approx(0.1));
}

TEST_CASE(".ma: write then read returns the same exact complex", "[complex3]") {
  for (const RawComplex& raw : {board_fin({4, 2}), tetrahedron_with_flap(), read_ma(data("two_triangles_segment.ma"))}) {
    std::ostringstream os;
    CHECK(write_ma(raw, os));  // decimal coordinates and decimal radii: exact
    const RawComplex back = parse_ma(os.str(), "round trip");
    REQUIRE(back.vertices.size() == raw.vertices.size());
    for (std::size_t v = 0; v < raw.vertices.size(); ++v) {
      CHECK(back.vertices[v].x == raw.vertices[v].x);
      CHECK(back.vertices[v].y == raw.vertices[v].y);
      CHECK(back.vertices[v].z == raw.vertices[v].z);
      CHECK(back.radius_squared[v] == raw.radius_squared[v]);
    }
    CHECK(back.triangles == raw.triangles);
    CHECK(back.segments.size() == raw.segments.size());
    const MedialComplex mc(back);
    mc.validate();
  }
  // Rational points of the circle (book pages) are not decimals: written as nearest doubles.
  BookOptions o;
  o.pages = 3;
  o.cells_per_unit = 1;
  std::ostringstream os;
  CHECK_FALSE(write_ma(book(o), os));
}

TEST_CASE(".ma: malformed files are rejected naming file, line and problem", "[complex3]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bad_counts.ma", "bad_counts.ma:1: header says 3 vertices, the file has 2"},
      {"bad_nan.ma", "bad_nan.ma:3: 'nan' is not a finite decimal number"},
      {"bad_index.ma", "bad_index.ma:5: vertex index 3 out of range (3 vertices)"},
      {"bad_quad.ma", "bad_quad.ma:6: face with 4 vertices; .ma faces must be triangles"},
      {"bad_radius.ma", "bad_radius.ma:3: negative radius -1"},
      {"bad_empty.ma", "bad_empty.ma: empty file"},
      {"bad_tag.ma", "bad_tag.ma:5: unknown line tag 'q'"},
  };
  check_rejections(cases, [](const std::string& path) { read_ma(path); });
  CHECK_THAT(error_of([&] { MedialComplex mc(read_ma(data("bad_degenerate.ma"))); }),
             Catch::Contains("bad_degenerate.ma: triangle 0 is degenerate"));
  CHECK_THAT(error_of([&] { read_ma(data("does_not_exist.ma")); }), Catch::Contains("cannot open"));
}

TEST_CASE("meshes: OFF, OBJ, ASCII and binary PLY read the same tetrahedron", "[complex3]") {
  const TriangleMesh3 off = read_triangle_mesh(data("tetrahedron.off"));
  for (const char* other : {"tetrahedron.obj", "tetrahedron_ascii.ply", "tetrahedron_binary.ply"}) {
    CAPTURE(other);
    const TriangleMesh3 m = read_triangle_mesh(data(other));
    CHECK(m.vertices == off.vertices);
    CHECK(m.triangles == off.triangles);
  }
  const MedialComplex mc(mesh_as_complex(off));
  mc.validate();
  CHECK(mc.count(VertexKind::Interior) == 4);
}

TEST_CASE("meshes: polygonal faces become fans, OFF family headers are read", "[complex3]") {
  // A unit square as one quad in each format: two triangles (0 1 2) and (0 2 3).
  const std::vector<std::array<std::uint32_t, 3>> fan{{0, 1, 2}, {0, 2, 3}};
  for (const char* f : {"quad.off", "quad.obj", "quad.ply"}) {
    CAPTURE(f);
    const TriangleMesh3 m = read_triangle_mesh(data(f));
    CHECK(m.vertices.size() == 4);
    CHECK(m.triangles == fan);
  }
  // COFF (per-vertex colours, as CGAL's cactus.off): a pentagon with colours after its indices.
  const TriangleMesh3 c = read_triangle_mesh(data("pentagon_colours.off"));
  CHECK(c.vertices.size() == 5);
  CHECK(c.vertices[1] == std::array<double, 3>{1, 0, 0});
  CHECK(c.triangles == std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
  TriangleMesh3 m;
  CHECK(append_polygon_face(m, {0, 1}) == PolygonFace::Degenerate);
  CHECK(append_polygon_face(m, {0, 1, 1, 0}) == PolygonFace::Degenerate);
  CHECK(append_polygon_face(m, {0, 1, 2, 1}) == PolygonFace::RepeatsVertex);
  CHECK(m.triangles.empty());
  CHECK(m.cleanup.degenerate_faces == 2);
  // Consecutive repeats (what welding makes of a zero-length edge) are merged.
  CHECK(append_polygon_face(m, {4, 5, 5, 6, 4}) == PolygonFace::Added);
  CHECK(m.triangles == std::vector<std::array<std::uint32_t, 3>>{{4, 5, 6}});
  CHECK(m.triangle_origin == std::vector<std::uint32_t>{3});  // the fourth face of the file
  CHECK(m.cleanup.file_faces == 4);
}

TEST_CASE("meshes: write then read is the identity", "[complex3]") {
  TriangleMesh3 m;
  m.source = "generated";
  m.vertices = {{0.1, 1e-17, -3.25}, {1.0 / 3, 2, 0}, {0, 0, 7.5}, {12345.678, -0.5, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 3, 2}};
  for (const char* ext : {"off", "obj", "ply"}) {
    const std::string path = temp_path(std::string("mesh.") + ext);
    if (std::string(ext) == "off") write_off(m, path);
    if (std::string(ext) == "obj") write_obj(m, path);
    if (std::string(ext) == "ply") write_ply(m, path);
    const TriangleMesh3 back = read_triangle_mesh(path);
    CHECK(back.vertices == m.vertices);
    CHECK(back.triangles == m.triangles);
    std::remove(path.c_str());
  }
}

TEST_CASE("meshes: malformed files are rejected", "[complex3]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bad_two.off", "bad_two.off:6: face with 2 vertices; at least 3 are required"},
      {"bad_repeat.off", "bad_repeat.off:7: face repeats a vertex (not next to itself)"},
      {"bad_4d.off", "bad_4d.off:1: not an OFF file"},
      {"bad_nan.off", "bad_nan.off:4: 'NaN' is not a finite number"},
      {"bad_index.off", "bad_index.off:6: vertex index '5' out of range"},
      {"bad_short.off", "file ends early"},
      {"bad_empty.off", "empty mesh"},
      {"bad_two.obj", "bad_two.obj:4: face with 2 vertices"},
      {"bad_index.obj", "bad_index.obj:4: vertex reference out of range"},
      {"bad_repeat.ply", "bad_repeat.ply: empty mesh (no vertices or no triangles left after the repairs: dropped 1 "
                         "degenerate face, 3 unused vertices)"},
      {"bad_inf.ply", "vertex 1: coordinate is NaN or infinite"},
      {"bad_no_z.ply", "vertex element lacks x, y or z"},
      {"bad_big_endian.ply", "unsupported PLY format 'binary_big_endian'"},
      {"bad_truncated_binary.ply", "face 3: file ends early"},
      {"two_triangles_segment.ma", "unknown mesh extension 'ma' (expected .off, .ply, .obj or .stl)"},
  };
  check_rejections(cases, [](const std::string& path) { read_triangle_mesh(path); });
}

TEST_CASE("ball lists", "[complex3]") {
  const BallSet b = read_ball_list(data("three_balls.cin"));
  REQUIRE(b.centers.size() == 3);
  CHECK(b.centers[1].x == make_rational(3, 2));
  CHECK(b.squared_radii[2] == make_rational(9, 4));
  CHECK(b.approx_radii[2] == 1.5);
  CHECK_THAT(error_of([&] { read_ball_list(data("bad_negative.cin")); }), Catch::Contains("bad_negative.cin:2: squared radius -0.5"));
  CHECK_THAT(error_of([&] { read_ball_list(data("bad_nan.cin")); }), Catch::Contains("bad_nan.cin:2"));
  const BallSet caffeine = read_ball_list(std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin");
  CHECK(caffeine.centers.size() == 23);
}

TEST_CASE("PLY and VTK export with scalars", "[complex3]") {
  const MedialComplex mc(read_ma(data("two_triangles_segment.ma")));
  std::vector<double> r, bt;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) r.push_back(mc.vertex(v).radius), bt.push_back(v == 0 ? 1.0 / 0.0 : v);
  const std::string ply = temp_path("export.ply"), vtk = temp_path("export.vtk");
  write_complex_ply(mc, {{"R", r}, {"BT", bt}}, ply);
  write_complex_vtk(mc, {{"R", r}, {"BT", bt}}, vtk);
  // The PLY reads back as a mesh (extra properties and the edge element are skipped; the
  // end of the hair is on no triangle and is dropped as unused).
  const TriangleMesh3 back = read_triangle_mesh(ply);
  CHECK(back.triangles.size() == 2);
  CHECK(back.vertices.size() == 4);
  CHECK(back.cleanup.unused_vertices == 1);
  std::ifstream in(vtk);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK_THAT(ss.str(), Catch::Contains("LINES 1 3\n2 3 4"));
  CHECK_THAT(ss.str(), Catch::Contains("SCALARS BT double 1\nLOOKUP_TABLE default\ninf\n1\n"));
  CHECK_THAT(error_of([&] { write_complex_vtk(mc, {{"B T", bt}}, vtk); }), Catch::Contains("must be letters"));
  std::remove(ply.c_str());
  std::remove(vtk.c_str());
}
