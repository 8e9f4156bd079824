// Shape readers and writers (io/shape_json.h, io/shape_wkt.h) and the shapes / validate
// commands.
#include <catch2/catch.hpp>

#include <dirent.h>

#include <array>
#include <cstdio>
#include <sstream>
#include <string>

#include "io/shape_json.h"
#include "io/shape_wkt.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"

using namespace grassfire;

namespace {

const std::string kData = std::string(GF_TEST_DATA) + "/shapes/";

// Output (stdout and stderr) and exit code of a grassfire command line.
std::pair<std::string, int> run_cli(const std::string& args) {
  const std::string command = std::string(GF_CLI) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  std::array<char, 4096> buf;
  while (std::size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

void require_same_points(const Shape2& a, const Shape2& b) {
  REQUIRE(a.rings.size() == b.rings.size());
  for (std::size_t r = 0; r < a.rings.size(); ++r) REQUIRE(a.rings[r].points == b.rings[r].points);
}

}  // namespace

TEST_CASE("malformed files are rejected with the file and the position", "[shapes]") {
  struct Case {
    const char* file;
    const char* where;  // what follows the path
  };
  const Case cases[] = {
      {"bad_syntax.json", ":5:1: invalid JSON: syntax error"},
      {"empty.json", ":1:1: invalid JSON"},
      {"nan.json", ":1:45: invalid JSON"},
      {"overflow.json", ":1:35: invalid JSON: number overflow parsing '1e999'"},
      {"no_points.json", ": no \"points\" member"},
      {"not_a_number.json", ": points[2].y is not a number (\"one\")"},
      {"empty.wkt", ":1:1: expected a geometry type (POLYGON), found the end of the text"},
      {"nan.wkt", ":1:21: x of point 2 of ring 0 is not a finite number ('nan')"},
      {"overflow.wkt", ":1:21: x of point 2 of ring 0 '1e999' is out of the range of doubles"},
      {"syntax_error.wkt", ":3:13: expected ',' or ')' after point 1 of ring 1"},
      {"polygon_z.wkt", ":1:9: POLYGON Z: only 2D coordinates are supported"},
      {"multipolygon_two.wkt", ":1:37: MULTIPOLYGON with more than one polygon"},
      {"linestring.wkt", ":1:1: expected POLYGON or MULTIPOLYGON, found 'LINESTRING'"},
      {"comment.txt", ":1:1: expected POLYGON or MULTIPOLYGON, found '#'"},
  };
  for (const Case& c : cases) {
    const std::string path = kData + c.file;
    INFO(path);
    CHECK_THROWS_AS(load_shape(path), ShapeFormatError);
    CHECK_THROWS_WITH(load_shape(path), Catch::StartsWith(path + c.where));
  }
}

TEST_CASE("WKT syntax: keywords, spacing, closing, EMPTY", "[shapes]") {
  const Shape2 s = parse_shape_wkt("  polygon((0 0,4 0 , 4 3,0 0),\n(1 0.5, 2 1,+3e0 .75))", "inline");
  REQUIRE(s.rings.size() == 2);
  CHECK(s.name == "inline");
  CHECK(s.rings[0].points.size() == 4);  // the closing point is read; validation drops it
  CHECK(s.rings[1].points[2].x == 3.0);
  CHECK(s.rings[1].points[2].y == 0.75);
  CHECK_THROWS_WITH(parse_shape_wkt("POLYGON EMPTY", "e"), "e:1:9: POLYGON EMPTY: the shape has no rings (empty input)");
  CHECK_THROWS_WITH(parse_shape_wkt("POLYGON ((0 0, 1 0, 1 1)) x", "t"), Catch::StartsWith("t:1:27: unexpected text"));
  CHECK_THROWS_WITH(parse_shape_wkt("POLYGON ((0 0, 1 0, 1 1)", "u"), "u:1:25: expected ')', found the end of the text");
  CHECK_THROWS_WITH(parse_shape_wkt("POLYGON ((0 0, 1 0, 1 0x1))", "h"), Catch::Contains("found '0x1'"));
  CHECK_NOTHROW(parse_shape_wkt("POLYGON ((0 0, 1 0, 1 1));", "semicolon"));
}

TEST_CASE("numbers are read as the nearest double", "[shapes]") {
  // 0.1 and 1e-310 (subnormal) as strtod gives them; 2^53 + 1 rounds to even.
  const Shape2 s = parse_shape_wkt("POLYGON ((0.1 1e-310, 9007199254740993 -0, 1 1))", "n");
  CHECK(s.rings[0].points[0].x == 0.1);
  CHECK(s.rings[0].points[0].y == 1e-310);
  CHECK(s.rings[0].points[1].x == 9007199254740992.0);
  const Shape2 j = parse_shape_json("{\"points\":[{\"x\":0.1,\"y\":1e-310},{\"x\":9007199254740993,\"y\":2}]}", "j");
  CHECK(j.rings[0].points[0].x == 0.1);
  CHECK(j.rings[0].points[0].y == 1e-310);
  CHECK(j.rings[0].points[1].x == 9007199254740992.0);
}

TEST_CASE("WKT and JSON round trips are exact", "[shapes]") {
  for (const BuiltinShapeInfo& info : builtin_shape_list()) {
    INFO(info.name);
    const Shape2 s = builtin_shape(info.name);
    Shape2 back = parse_shape_wkt(to_wkt(s), "back");
    validate_shape(back, "back");  // drops the closing point that WKT repeats
    require_same_points(s, back);
  }
  // Real shapes: coordinates like 0.31466 and values that need 17 digits.
  const Shape2 dino = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/dino.json");
  Shape2 awkward = dino;
  for (Point2& p : awkward.rings[0].points) p = {p.x / 3, p.y * 1e-7};
  for (const Shape2* s : {&dino, static_cast<const Shape2*>(&awkward)}) {
    Shape2 wkt = parse_shape_wkt(to_wkt(*s), "wkt");
    validate_shape(wkt, "wkt");
    require_same_points(*s, wkt);
    std::ostringstream json;
    write_shape_json(*s, json);
    const Shape2 from_json = parse_shape_json(json.str(), "json");
    require_same_points(*s, from_json);
  }
  CHECK(to_wkt(builtin_shape("rectangle")) == "POLYGON (\n  (0 0, 10 0, 10 4, 0 4, 0 0)\n)\n");
  std::ostringstream out;
  CHECK_THROWS_WITH(write_shape_json(builtin_shape("hole"), out), Catch::Contains("write it as WKT"));
}

TEST_CASE("grassfire validate: exit 0 with a description, 1 with the first problem", "[shapes]") {
  const auto [ok, ok_code] = run_cli("validate " + kData + "reversed_orientation.wkt");
  CHECK(ok_code == 0);
  CHECK_THAT(ok, Catch::Contains("valid, 2 rings"));
  CHECK_THAT(ok, Catch::Contains("ring 1 (hole): 4 vertices (1 repeated dropped), clockwise (reversed from the input)"));
  CHECK_THAT(ok, Catch::Contains("area 96 "));
  const auto [bad, bad_code] = run_cli("validate " + kData + "bowtie.wkt");
  CHECK(bad_code == 1);
  CHECK(bad == "grassfire validate: " + kData + "bowtie.wkt: ring 0 (outer): edge 0-1 crosses edge 2-3 at about (1, 1)\n");
  const auto [unknown, unknown_code] = run_cli("validate circle");
  CHECK(unknown_code == 1);
  CHECK_THAT(unknown, Catch::Contains("built-in shapes are: rectangle, rectangle-bump, branches, hole, noisy, blunt-sharp"));
}

TEST_CASE("grassfire shapes lists the built-ins and prints WKT that loads back", "[shapes]") {
  const auto [list, code] = run_cli("shapes");
  CHECK(code == 0);
  for (const BuiltinShapeInfo& info : builtin_shape_list()) CHECK_THAT(list, Catch::Contains(info.name + " "));
  const auto [wkt, wkt_code] = run_cli("shapes --wkt blunt-sharp");
  CHECK(wkt_code == 0);
  Shape2 s = parse_shape_wkt(wkt, "stdout");
  validate_shape(s, "stdout");
  require_same_points(s, builtin_shape("blunt-sharp"));
  CHECK(run_cli("shapes --wkt nope").second == 1);
}
