// The grassfire-complex JSON format: exact reading, round trips, malformed documents.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>

#include "complex3/medial_complex.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_json.h"
#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "number/exact_sum.h"
#include "support.h"
#include "test_complex3_support.h"

using namespace grassfire;
using grassfire::testing::error_of;

namespace {

std::string data(const std::string& name) { return std::string(GF_TEST_DATA) + "/3d/" + name; }

void require_same(const RawComplex& a, const RawComplex& b) {
  REQUIRE(a.vertices.size() == b.vertices.size());
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    REQUIRE(a.vertices[v] == b.vertices[v]);
    REQUIRE(a.radius_squared[v] == b.radius_squared[v]);
  }
  REQUIRE(a.triangles == b.triangles);
  REQUIRE(a.segments == b.segments);
  REQUIRE(a.border_rules.size() == b.border_rules.size());
  for (std::size_t i = 0; i < a.border_rules.size(); ++i) {
    REQUIRE(a.border_rules[i].edge == b.border_rules[i].edge);
    REQUIRE(a.border_rules[i].rule == b.border_rules[i].rule);
    if (a.border_rules[i].rule == IgnitionRule::DistanceToPoint) REQUIRE(a.border_rules[i].point == b.border_rules[i].point);
  }
}

const char* kHead = R"({"format": "grassfire-complex", "version": 1, )";

}  // namespace

TEST_CASE("complex JSON: numbers are the exact decimals they write, never doubles", "[complex_json]") {
  const RawComplex raw = parse_complex_json(
      std::string(kHead) + R"("vertices": [[0.1, 1e-1, "1/10"], [123456789012345678901234567890, -2.5E-3, "-7/21"],
                                            [0, "0.30", "1e400"]], "radius_squared": [0.01, "4", 0]})",
      "numbers");
  const mpq_class tenth = make_rational(1, 10);
  CHECK(raw.vertices[0] == ExactPoint3{tenth, tenth, tenth});
  CHECK(raw.vertices[1].x == mpq_class(mpz_class("123456789012345678901234567890")));
  CHECK(raw.vertices[1].y == make_rational(-1, 400));
  CHECK(raw.vertices[1].z == make_rational(-1, 3));
  CHECK(raw.vertices[2].y == make_rational(3, 10));
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 10, 400);
  CHECK(raw.vertices[2].z == mpq_class(big));  // beyond any double: still exact (as a string)
  CHECK(raw.radius_squared[0] == make_rational(1, 100));
  CHECK(raw.radius_squared[1] == 4);
  CHECK(raw.triangles.empty());
  CHECK(rational_json(make_rational(1, 10)) == "0.1");
  CHECK(rational_json(make_rational(-2, 6)) == "\"-1/3\"");
  CHECK(rational_json(mpq_class(7)) == "7");
}

TEST_CASE("complex JSON: every member read from a file, and checked by MedialComplex", "[complex_json]") {
  const RawComplex raw = read_complex_json(data("hinge.json"));
  CHECK(raw.source == data("hinge.json"));
  REQUIRE(raw.vertices.size() == 5);
  CHECK(raw.vertices[2].y == make_rational(3, 2));
  CHECK(raw.vertices[3].z == make_rational(1, 3));
  CHECK(raw.radius_squared[2] == make_rational(1, 9));
  CHECK(raw.segments == std::vector<std::array<std::uint32_t, 2>>{{1, 4}});
  REQUIRE(raw.border_rules.size() == 2);
  CHECK(raw.border_rules[0].rule == IgnitionRule::DistanceToPoint);
  CHECK(raw.border_rules[0].point.z == make_rational(1, 10));
  CHECK(raw.border_rules[1].rule == IgnitionRule::Never);
  const MedialComplex mc = grassfire::testing::built(raw);
  CHECK(mc.count(EdgeStratum::Manifold) == 1);
  CHECK(mc.count(EdgeStratum::Dangling) == 1);
  const std::uint32_t e02 = mc.find_edge(0, 2);
  CHECK(mc.edge(e02).rule == IgnitionRule::DistanceToPoint);
  CHECK(mc.ignition_on_edge(mc.find_edge(1, 3), 0.5) == std::numeric_limits<double>::infinity());
  // f at the middle of edge 0-2, (0.5, 0.75, 0), is its distance to (0.5, 0.75, 0.1).
  CHECK(mc.ignition_on_edge(e02, 0.5) == Approx(0.1));
  CHECK_THAT(error_of([] { grassfire::testing::built(read_complex_json(data("bad_complex_degenerate.json"))); }),
             Catch::Contains("bad_complex_degenerate.json"));
}

TEST_CASE("complex JSON: every synthetic complex, a .ma axis and a double mesh round-trip exactly", "[complex_json]") {
  std::vector<RawComplex> all;
  for (const std::string& name : synthetic_complex_names()) {
    const std::string instance = name == "book:K" ? "book:4" : name == "box:A:B:C" ? "box:5:3:2" : name;
    all.push_back(synthetic_complex(instance));
  }
  all.push_back(read_complex_json(data("hinge.json")));
  all.push_back(mesh_as_complex(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/tripod.off")));
  RawComplex thirds = synthetic_complex("tetrahedron");  // rationals that are not decimals
  for (ExactPoint3& p : thirds.vertices) p = {p.x / 3, p.y / 7, p.z * make_rational(5, 11)};
  thirds.radius_squared[1] = make_rational(2, 3);
  mpz_class huge;
  mpz_ui_pow_ui(huge.get_mpz_t(), 10, 400);
  thirds.radius_squared[2] = mpq_class(huge) + make_rational(1, 4);  // beyond doubles: written as a string
  all.push_back(thirds);
  CHECK(all.size() == synthetic_complex_names().size() + 3);
  for (const RawComplex& raw : all) {
    CAPTURE(raw.source);
    const std::string text = complex_json_text(raw);
    const RawComplex back = parse_complex_json(text, "round trip");
    require_same(raw, back);
    CHECK(back.source == "round trip");
    const std::string again = complex_json_text(back);
    CHECK(again.substr(again.find("\"vertices\"")) == text.substr(text.find("\"vertices\"")));
  }
  // Through a file: written atomically, read back the same.
  const std::string path = grassfire::testing::temp_path("gf_round_trip_complex.json");
  write_complex_json(thirds, path);
  require_same(thirds, read_complex_json(path));
  std::remove(path.c_str());
}

TEST_CASE("complex JSON: malformed documents get one message naming the file and the place", "[complex_json]") {
  const std::string tri = R"("vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]])";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{", "bad.json:1:2: invalid JSON"},
      {"[1, 2]", "document: is not a JSON object"},
      {kHead + std::string(R"("vertices": [[0, 0, 1e400]]})"), "number overflow parsing '1e400'"},
      {R"({"version": 1, )" + tri + "}", "format: missing"},
      {R"({"format": "grassfire-medial2d", "version": 1, )" + tri + "}", "format: is \"grassfire-medial2d\""},
      {R"({"format": "grassfire-complex", "version": 2, )" + tri + "}", "version: is 2"},
      {R"({"format": "grassfire-complex", )" + tri + "}", "version: missing"},
      {kHead + tri + R"(, "triangle": [[0, 1, 2]]})", "triangle: unknown member"},
      {kHead + tri + ", " + tri + "}", "key \"vertices\" appears twice"},
      {std::string(kHead) + R"("triangles": []})", "vertices: missing"},
      {std::string(kHead) + R"("vertices": []})", "vertices: is empty"},
      {std::string(kHead) + R"("vertices": {"a": 1}})", "vertices: is not an array"},
      {std::string(kHead) + R"("vertices": [[0, 0, 0], [1, 0]]})", "vertices[1]: has 2 entries, not 3"},
      {std::string(kHead) + R"("vertices": [[0, "abc", 0]]})", "vertices[0][1]: is not an exact number"},
      {std::string(kHead) + R"("vertices": [[0, "nan", 0]]})", "vertices[0][1]: is not an exact number"},
      {std::string(kHead) + R"("vertices": [[0, 0, "1/0"]]})", "vertices[0][2]: is not an exact number"},
      {std::string(kHead) + R"("vertices": [[0, 0, "0x10"]]})", "vertices[0][2]: is not an exact number"},
      {std::string(kHead) + R"("vertices": [[true, 0, 0]]})", "vertices[0][0]: is not a number"},
      {std::string(kHead) + R"("vertices": [[null, 0, 0]]})", "vertices[0][0]: is not a number"},
      {kHead + tri + R"(, "radius_squared": [0, 1]})", "radius_squared: has 2 entries, not 3"},
      {kHead + tri + R"(, "radius_squared": [0, 1, -0.5]})", "radius_squared[2]: is negative"},
      {kHead + tri + R"(, "triangles": [[0, 1, 7]]})", "triangles[0][2]: vertex index 7 is out of range (3 vertices)"},
      {kHead + tri + R"(, "triangles": [[0, -1, 2]]})", "triangles[0][1]: is a negative vertex index"},
      {kHead + tri + R"(, "triangles": [[0, 1.0, 2]]})", "triangles[0][1]: is not a vertex index"},
      {kHead + tri + R"(, "triangles": [[0, "1", 2]]})", "triangles[0][1]: is not a vertex index"},
      {kHead + tri + R"(, "triangles": [[0, 1, 2, 0]]})", "triangles[0]: has 4 entries, not 3"},
      {kHead + tri + R"(, "triangles": [[0, 1, 99999999999999999999999]]})", "triangles[0][2]: is not a vertex index"},
      {kHead + tri + R"(, "segments": [[0]]})", "segments[0]: has 1 entries, not 2"},
      {kHead + tri + R"(, "border": {}})", "border: is not an array"},
      {kHead + tri + R"(, "border": [[0, 1]]})", "border[0]: is not an object"},
      {kHead + tri + R"(, "border": [{"rule": "never"}]})", "border[0]: has no \"edge\""},
      {kHead + tri + R"(, "border": [{"edge": [0, 1]}]})", "border[0]: has no \"rule\""},
      {kHead + tri + R"(, "border": [{"edge": [0, 0], "rule": "never"}]})", "border[0].edge: repeats vertex 0"},
      {kHead + tri + R"(, "border": [{"edge": [0, 1], "rule": "sometimes"}]})", "border[0].rule: is \"sometimes\""},
      {kHead + tri + R"(, "border": [{"edge": [0, 1], "rule": "point"}]})", "border[0]: has rule \"point\" but no"},
      {kHead + tri + R"(, "border": [{"edge": [0, 1], "rule": "never", "point": [0, 0, 1]}]})",
       "border[0]: has a \"point\" but rule \"never\""},
      {kHead + tri + R"(, "border": [{"edge": [0, 1], "rule": "point", "point": [0, 0]}]})",
       "border[0].point: has 2 entries, not 3"},
      {kHead + tri + R"(, "border": [{"edge": [0, 1], "rule": "never", "colour": 1}]})",
       "border[0]: unknown member \"colour\""},
  };
  for (const auto& [text, expected] : cases) {
    CAPTURE(text);
    const std::string message = error_of([&] { parse_complex_json(text, "bad.json"); });
    CHECK_THAT(message, Catch::StartsWith("bad.json") && Catch::Contains(expected));
  }
  CHECK_THAT(error_of([] { read_complex_json(data("bad_complex_syntax.json")); }),
             Catch::Contains("bad_complex_syntax.json:2:36: invalid JSON: syntax error"));
  CHECK_THAT(error_of([] { read_complex_json(data("no_such_file.json")); }), Catch::Contains("cannot open"));
  // A wrongly sized radius list cannot be written (the reader would refuse it).
  RawComplex broken = synthetic_complex("tetrahedron");
  broken.radius_squared.pop_back();
  CHECK_THAT(error_of([&] { complex_json_text(broken); }), Catch::Contains("radius_squared has 3 values for 4"));
}
