// validate_shape on hand-built shapes, the invalid examples of tests/data/shapes, the
// built-in shapes and the copied real shapes of data/shapes2d.
#include <catch2/catch.hpp>

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "io/shape_format.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"

using namespace grassfire;

namespace {

const std::string kData = std::string(GF_TEST_DATA) + "/shapes/";

Shape2 polygon(std::vector<std::vector<Point2>> rings) {
  Shape2 s{"test", {}};
  for (auto& r : rings) s.rings.push_back(Ring{std::move(r)});
  return s;
}

std::vector<std::string> json_files(const std::string& dir) {
  std::vector<std::string> files;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0) files.push_back(dir + "/" + name);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("each invalid example is rejected at its first offending ring and vertex", "[shapes]") {
  struct Case {
    const char* file;
    long ring, vertex;
    const char* problem;
  };
  const Case cases[] = {
      {"bowtie.wkt", 0, 0, "edge 0-1 crosses edge 2-3 at about (1, 1)"},
      {"bowtie_repeated.wkt", 0, 0, "edge 0-2 crosses edge 3-4 at about (1, 1)"},  // input positions
      {"touch_vertex.wkt", 0, 0, "edge 0-1 touches edge 3-4 at about (2, 1)"},
      {"spike.wkt", 0, 2, "spike at vertex 3: edges 2-3 and 3-4 overlap"},
      {"two_distinct.wkt", 0, 0, "only 2 distinct vertices"},
      {"no_vertices.json", 0, -1, "only 0 distinct vertices"},
      {"hole_crosses_outer.wkt", 0, 1, "edge 1-2 crosses edge 3-0 of ring 1 (hole) at about (10, 4)"},
      {"holes_touch.wkt", 1, 0, "edge 0-1 touches edge 0-1 of ring 2 (hole) at about (2, 8)"},
      {"hole_outside.wkt", 1, 0, "lies outside the outer ring"},
      {"nested_holes.wkt", 2, 0, "lies inside ring 1 (hole); holes must not nest"},
      // Two of the 979 shapes of the shapes2d dataset, the only ones that are not simple.
      {"real_Glas-12.json", 0, 17, "edge 17-18 overlaps edge 20-21 at about (0, 0.96562)"},
      {"real_stef-20.json", 0, 33, "edge 33-34 touches edge 59-60 at about (0.57647, 0.27059)"},
  };
  for (const Case& c : cases) {
    const std::string path = kData + c.file;
    INFO(path);
    try {
      load_shape(path);
      FAIL("accepted");
    } catch (const InvalidShapeError& e) {
      CHECK(e.source() == path);
      CHECK(e.ring() == c.ring);
      CHECK(e.vertex() == c.vertex);
      CHECK(e.problem().find(c.problem) != std::string::npos);
      const std::string head = path + ": " + ring_label(static_cast<std::size_t>(c.ring)) + ": ";
      CHECK(std::string(e.what()).rfind(head, 0) == 0);
      CHECK_THAT(e.what(), Catch::Contains(c.problem));
    }
  }
}

TEST_CASE("an empty shape and non-finite coordinates are rejected", "[shapes]") {
  Shape2 empty{"empty", {}};
  CHECK_THROWS_WITH(validate_shape(empty, "built"), "built: the shape has no rings (empty input)");
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Shape2 a = polygon({{{0, 0}, {1, 0}, {1, 1}}, {{0.2, 0.1}, {0.5, 0.1}, {nan, 0.2}}});
  CHECK_THROWS_WITH(validate_shape(a, "a"), Catch::StartsWith("a: ring 1 (hole): vertex 2 has a non-finite"));
  Shape2 b = polygon({{{0, 0}, {1, 0}, {inf, 1}}});
  CHECK_THROWS_AS(validate_shape(b, "b"), InvalidShapeError);
}

TEST_CASE("degenerate rings: collinear vertices and a spike back to a vertex", "[shapes]") {
  // Three distinct collinear vertices: the boundary doubles back at vertices 2 and 0; the
  // pair of edges 2-0 and 0-1 comes first in (ring, vertex) order.
  Shape2 line = polygon({{{0, 0}, {1, 1}, {3, 3}}});
  CHECK_THROWS_WITH(validate_shape(line, "line"),
                    "line: ring 0 (outer): spike at vertex 0: edges 2-0 and 0-1 overlap (the boundary doubles back on itself)");
  // A spike whose tip returns exactly to the previous vertex's position touches it too;
  // the first offence in (ring, vertex) order is the touch of edges 1-2 and 3-4.
  Shape2 back = polygon({{{0, 0}, {4, 0}, {4, 2}, {6, 2}, {4, 2}, {4, 4}, {0, 4}}});
  CHECK_THROWS_WITH(validate_shape(back, "back"), Catch::Contains("ring 0 (outer): edge 1-2 touches edge 3-4 at about (4, 2)"));
  // Collinear consecutive edges that continue straight on are fine.
  Shape2 straight = polygon({{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0, 1}}});
  CHECK_NOTHROW(validate_shape(straight, "straight"));
}

TEST_CASE("a failed validation leaves the shape unchanged", "[shapes]") {
  Shape2 s = polygon({{{0, 0}, {0, 0}, {2, 2}, {2, 0}, {0, 2}, {0, 0}}});
  const Shape2 before = s;
  CHECK_THROWS_AS(validate_shape(s, "s"), InvalidShapeError);
  REQUIRE(s.rings.size() == 1);
  CHECK(s.rings[0].points.size() == before.rings[0].points.size());
}

TEST_CASE("repeated vertices are dropped and orientation is normalized", "[shapes]") {
  // Clockwise outer ring with repeated vertices and a repeated closing vertex.
  Shape2 s = polygon({{{0, 0}, {0, 0}, {0, 3}, {4, 0}, {4, 0}, {0, 0}, {0, 0}}});
  const ShapeValidation v = validate_shape(s, "s");
  REQUIRE(v.rings.size() == 1);
  CHECK(v.rings[0].input_vertices == 7);
  CHECK(v.rings[0].vertices == 3);
  CHECK(v.rings[0].reversed);
  const std::vector<Point2> expected = {{0, 0}, {4, 0}, {0, 3}};
  CHECK(s.rings[0].points.size() == 3);
  CHECK(std::equal(expected.begin(), expected.end(), s.rings[0].points.begin()));
  // A second validation changes nothing.
  const ShapeValidation again = validate_shape(s, "s");
  CHECK_FALSE(again.rings[0].reversed);
  CHECK(again.rings[0].vertices == 3);
}

TEST_CASE("a file with both rings reversed is reoriented keeping vertex 0 first", "[shapes]") {
  ShapeValidation v;
  const Shape2 s = load_shape(kData + "reversed_orientation.wkt", &v);
  REQUIRE(s.rings.size() == 2);
  CHECK(v.rings[0].reversed);
  CHECK(v.rings[1].reversed);
  const std::vector<Point2> outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<Point2> hole = {{2, 2}, {2, 4}, {4, 4}, {4, 2}};
  CHECK(s.rings[0].points == std::vector<Point2>(outer));
  CHECK(s.rings[1].points == std::vector<Point2>(hole));
  CHECK(signed_area(s.rings[0]).contains(100));
  CHECK(signed_area(s.rings[1]).contains(-4));
}

TEST_CASE("every built-in shape is valid, normalized, with the intended area", "[shapes]") {
  REQUIRE(builtin_shape_list().size() == 6);
  for (const BuiltinShapeInfo& info : builtin_shape_list()) {
    INFO(info.name);
    Shape2 s = builtin_shape(info.name);
    CHECK(s.name == info.name);
    CHECK_FALSE(info.description.empty());
    const ShapeValidation v = validate_shape(s, info.name);  // already normalized: nothing to reverse
    for (std::size_t r = 0; r < s.rings.size(); ++r) {
      CHECK_FALSE(v.rings[r].reversed);
      CHECK(v.rings[r].input_vertices == v.rings[r].vertices);
      CHECK((r == 0 ? signed_area(s.rings[r]).lo > 0 : signed_area(s.rings[r]).hi < 0));
    }
  }
  CHECK(signed_area(builtin_shape("rectangle").rings[0]).contains(40));
  CHECK(signed_area(builtin_shape("rectangle-bump").rings[0]).contains(40.0625));
  CHECK(signed_area(builtin_shape("blunt-sharp").rings[0]).contains(26.45));
  const Shape2 hole = builtin_shape("hole");
  REQUIRE(hole.rings.size() == 2);
  CHECK(signed_area(hole.rings[1]).contains(-7));
  CHECK(builtin_shape("noisy").rings[0].points.size() == 400);
  CHECK(builtin_shape("branches").rings[0].points.size() == 18);
  CHECK_THROWS_WITH(builtin_shape("circle"), Catch::Contains("rectangle, rectangle-bump, branches, hole, noisy"));
}

TEST_CASE("every copied shapes2d shape validates, counter-clockwise", "[shapes]") {
  const std::vector<std::string> files = json_files(std::string(GF_PROJECT_DATA) + "/shapes2d");
  REQUIRE(files.size() == 107);
  std::size_t reversed = 0;
  for (const std::string& f : files) {
    INFO(f);
    ShapeValidation v;
    const Shape2 s = load_shape(f, &v);
    REQUIRE(s.rings.size() == 1);
    CHECK(s.rings[0].points.size() >= 100);
    CHECK(s.rings[0].points.size() <= 188);
    CHECK(signed_area(s.rings[0]).lo > 0);
    reversed += v.rings[0].reversed;
  }
  // The dataset's rings run clockwise in y-up coordinates (they were traced in image
  // coordinates), so validation reverses all of them.
  CHECK(reversed == files.size());
}

TEST_CASE("load_shape: built-in names, builtin: prefix, and clear errors", "[shapes]") {
  CHECK(load_shape("hole").rings.size() == 2);
  CHECK(load_shape("builtin:rectangle").name == "rectangle");
  CHECK(load_shape(kData + "unclosed.txt").rings[0].points.size() == 4);
  CHECK(load_shape(kData + "multipolygon_one.wkt").rings[0].points.size() == 3);
  CHECK_THROWS_WITH(load_shape("builtin:nope"), Catch::Contains("built-in shapes are: rectangle,"));
  CHECK_THROWS_WITH(load_shape("nope"), Catch::Contains("'nope' is neither a shape file"));
  CHECK_THROWS_AS(load_shape(kData + "missing.wkt"), ShapeFormatError);
  CHECK_THROWS_WITH(load_shape(kData + "missing.wkt"), Catch::EndsWith("missing.wkt: no such file"));
  CHECK_THROWS_WITH(load_shape(kData), Catch::EndsWith(": is a directory"));
  CHECK_THROWS_WITH(load_shape(kData + "LICENSE-shapes2d.md"), Catch::Contains("unknown shape file type"));
}
