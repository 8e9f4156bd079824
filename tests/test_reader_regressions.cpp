// One regression test per reader bug found by tests/fuzz/fuzz_readers (docs/formats.md).
// Each test feeds the reader a reduced form of the input that failed, and checks the clear
// message that is now given instead.
#include <catch2/catch.hpp>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "io/halfspace_list.h"
#include "complex3/medial_complex.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "io/complex_text.h"
#include "io/disk_list.h"
#include "io/mesh_io.h"
#include "io/shape_json.h"
#include "io/shape_wkt.h"
#include "support.h"

using namespace grassfire;
using grassfire::testing::error_of;

TEST_CASE("regression: a megabyte-long word is shown shortened in every reader's message", "[fuzz]") {
  // Before: the messages quoted the whole word (fuzz: 'longer than 1000 characters').
  const std::string word(100000, '[');
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"OFF\n" + word + " 1 0\n", "in.off:2: count '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...' (100000 characters) is not"},
      {"v 0 0 " + word + "\n", "in.obj:1: '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...' (100000 characters) is not a finite number"},
      {"ply\nformat ascii 1.0\nelement " + word + " 1\nproperty float x\nend_header\n",
       "in.ply:5: [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[... (100000 characters) 0: file ends early"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "element " + word + " 1\nproperty float x\nend_header\n0 0 0\n",
       "in.ply:10: [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[... (100000 characters) 0: file ends early"},
      {"solid x\n" + word + "\n", "in.stl:2: ASCII STL: expected 'facet' or 'endsolid', found '[[[["},
  };
  for (const auto& [text, expected] : cases) {
    const std::string source = expected.substr(0, expected.find(':'));
    const std::string message = error_of([&] { parse_triangle_mesh(text, source); });
    CAPTURE(source);
    CHECK_THAT(message, Catch::StartsWith(expected));
    CHECK(message.size() < 200);
  }
  CHECK(error_of([&] { parse_ma("1 0 0\nv 0 0 0 " + word + "\n", "in.ma"); }) ==
        "in.ma:2: '[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[...' (100000 characters) is not a finite decimal number");
  CHECK(error_of([&] { parse_disk_list("0 0 " + word + "\n", "in.txt"); }).size() < 200);
  CHECK(error_of([&] { parse_shape_wkt("POLYGON ((0 " + word + "))", "in.wkt"); }).size() < 200);
  CHECK(error_of([&] { parse_ball_list("0 0 0 " + word + "\n", "in.cin"); }).size() < 200);
}

TEST_CASE("regression: nlohmann's echo of the JSON input is shortened", "[fuzz]") {
  // Before: "last read: '<the whole token>'" and "number overflow parsing '<digits>'".
  const std::string digits(5000, '9');
  CHECK(error_of([&] { parse_shape_json("{\"points\":[{\"x\":1" + digits + "e99999}]}", "in.json"); }) ==
        "in.json:1:5023: invalid JSON: number overflow parsing '1999999999999999999999999999999999999999...' "
        "(5007 characters)");
  const std::string key = error_of([&] { parse_shape_json("{\"" + std::string(3000, 'a'), "in.json"); });
  CHECK_THAT(key, Catch::StartsWith("in.json:1:3003: invalid JSON: syntax error while parsing object key"));
  CHECK(key.size() < 250);
  const std::string member = error_of([&] { parse_shape_json("{\"points\":[{\"x\":\"" + digits + "\",\"y\":0}]}", "in.json"); });
  CHECK_THAT(member, Catch::StartsWith("in.json: points[0].x is not a number (\"99999"));
  CHECK(member.size() < 200);
}

TEST_CASE("regression: a long unknown member name of a grassfire-complex document is shortened", "[fuzz]") {
  // Before: "unknown member" quoted the whole name (fuzz: 'longer than 1000 characters').
  const std::string name(5000, 'a');
  const std::string head = R"({"format": "grassfire-complex", "version": 1, "vertices": [[0, 0, 0]])";
  CHECK(error_of([&] { parse_complex_json(head + ", \"" + name + "\": 1}", "in.json"); }) ==
        "in.json: aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa... (5000 characters): unknown member (a typo? the members are "
        "format, version, vertices, radius_squared, triangles, segments, border, source, comment)");
  CHECK(error_of([&] { parse_complex_json(head + R"(, "border": [{"edge": [0, 0], ")" + name + "\": 1}]}", "in.json"); }) ==
        "in.json: border[0]: unknown member \"aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa... (5000 characters)\"");
}

TEST_CASE("regression: a number of 10^5 digits is refused at once instead of slowing exact arithmetic", "[fuzz]") {
  // Before: a .ma coordinate of 146,872 digits took 40 s in MedialComplex (fuzz: hang).
  CHECK(parse_exact_decimal(std::string(1000, '7')).has_value());
  CHECK_FALSE(parse_exact_decimal(std::string(1001, '7')).has_value());
  CHECK_FALSE(parse_exact_decimal("0." + std::string(1000, '7')).has_value());
  const std::string text = "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 " + std::string(150000, '9') + " 0 1\nf 0 1 2\n";
  CHECK(error_of([&] { MedialComplex mc(parse_ma(text, "long.ma")); }) ==
        "long.ma:4: '9999999999999999999999999999999999999999...' (150000 characters) is not a finite decimal number");
  CHECK_FALSE(parse_exact_decimal(std::string(1001, '1')).has_value());
  CHECK(error_of([&] { parse_disk_list("0 0 " + std::string(1001, '1') + "\n", "in.txt"); }) ==
        "in.txt:1: r = '1111111111111111111111111111111111111111...' (1001 characters) is not a decimal number (at "
        "most 1000 digits, an optional point and an exponent of at most 300)");
}

TEST_CASE("regression: binary bytes in a token are shown escaped, and each message says what is wrong", "[fuzz]") {
  // Before: raw 0x01 and 0xff bytes in messages; "vertex index '1.5' out of range" for an
  // index that is not an integer; PLY "vertex index out of range" without the index.
  CHECK(error_of([] { parse_triangle_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 \x01\xff\n", "in.off"); }) ==
        "in.off:6: '\\x01\\xff' is not a vertex index");
  CHECK(error_of([] { parse_triangle_mesh("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n", "in.off"); }) ==
        "in.off:6: '1.5' is not a vertex index");
  CHECK(error_of([] {
          parse_triangle_mesh("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                              "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                              "in.ply");
        }) == "in.ply: face 0: vertex index 7 out of range (3 vertices)");
}

TEST_CASE("regression: a redundant half-space anywhere but last crashed the convex axis", "[fuzz]") {
  // Before: the facets kept their input index as label, so after a redundant plane the clip
  // order indexed past the facet list (segfault, or GMP aborting on a garbage size).
  const std::string cube = "1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 -1 0 1\n0 0 1 1\n0 0 -1 1\n";
  const ConvexAxis reference = convex_polyhedron_axis(parse_halfspaces(cube, "cube.hs"));
  for (const std::string extra : {"1 0 0 2\n", "0 0 1 1\n", "2 0 0 2\n", "1 1 0 2\n", "1 1 1 3\n"}) {
    for (std::size_t at = 0; at <= 6; ++at) {
      std::string text;
      std::size_t line = 0, pos = 0;
      for (; line < at; ++line) pos = cube.find('\n', pos) + 1;
      text = cube.substr(0, pos) + extra + cube.substr(pos);
      CAPTURE(extra, at);
      const ConvexAxis a = convex_polyhedron_axis(parse_halfspaces(text, "redundant.hs"));
      CHECK(a.redundant_planes == 1);
      CHECK(a.complex.vertices.size() == reference.complex.vertices.size());
      CHECK(a.complex.triangles.size() == reference.complex.triangles.size());
      CHECK(check_convex_axis(a).failures == 0);
    }
  }
}

TEST_CASE("regression: a ball coordinate beyond the range of doubles crashed the union-of-balls axis", "[fuzz]") {
  // Before: -1e309 is a finite decimal, but its nearest double is -inf, and GMP raised
  // SIGFPE converting it back (mpq_set_d) in the regular triangulation.
  CHECK(error_of([] { parse_ball_list("0 0 0 1\n1.5 0 0 0.25\n0 2 -1e309 2.25\n", "far.cin"); }) ==
        "far.cin:3: '-1e309' is beyond the range of doubles");
  CHECK(error_of([] { parse_ball_list("0 0 0 1e309\n", "far.cin"); }) == "far.cin:1: '1e309' is beyond the range of doubles");
  CHECK(parse_ball_list("0 0 0 1.7976931348623157e308\n", "edge.cin").centers.size() == 1);
}

TEST_CASE("regression: half-spaces near the range of doubles gave an internal error in the convex axis", "[fuzz]") {
  // Before: with an offset of 1e308 the double enclosures of the cell predicates overflowed to
  // infinities and NaN, which the filter took as decided ("a facet cell reaches the bounding
  // box"). Now such an enclosure decides nothing and the exact fallback does. A box that long
  // has the combinatorics of any long box: compare with one of length 10^6.
  const auto box = [](const std::string& far) {
    return "1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 -1 0 1\n0 0 1 " + far + "\n0 0 -1 1\n";
  };
  const ConvexAxis reference = convex_polyhedron_axis(parse_halfspaces(box("1e6"), "long.hs"));
  for (const std::string far : {"1e300", "1e308", "1.7976931348623157e308"}) {
    CAPTURE(far);
    const ConvexAxis a = convex_polyhedron_axis(parse_halfspaces(box(far), "far.hs"));
    CHECK(a.complex.vertices.size() == reference.complex.vertices.size());
    CHECK(a.complex.triangles.size() == reference.complex.triangles.size());
    CHECK(check_convex_axis(a).failures == 0);
  }
}
