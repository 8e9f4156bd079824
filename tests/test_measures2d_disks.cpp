// The exact medial axis of a union of disks (medial2/disks/disk_union_axis.h) and its input
// format (io/disk_list.h): hand-derived axes, the definition-level validation, degenerate
// and malformed inputs, the pipeline and the command line.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "burn2/extended_grassfire.h"
#include "io/disk_list.h"
#include "medial2/disks/disk_union_axis.h"
#include "medial2/disks/disk_union_geometry.h"
#include "medial2/disks/disk_union_validate.h"
#include "pipeline/edf2d.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

const std::string kDisks = std::string(GF_TEST_DATA) + "/disks/";

bool equals(const ExactSum& a, const ExactSum& b) { return sign(a - b) == 0; }
ExactSum rat(long n, long d = 1) { return ExactSum::rational(make_rational(n, d)); }

// The node at (x, y) exactly (a centre or a Voronoi vertex).
std::uint32_t node_at(const MedialGraph& g, const ExactSum& x, const ExactSum& y) {
  const auto& geo = dynamic_cast<const DiskUnionGeometry&>(g.geometry());
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (equals(geo.exact_position(v)[0], x) && equals(geo.exact_position(v)[1], y)) return v;
  FAIL("no node at (" << to_string(x) << ", " << to_string(y) << ")");
  return 0;
}

MedialGraph valid_axis(const DiskList& list, DiskUnionAxisReport& report) {
  MedialGraph g = disk_union_axis(list, &report);
  g.validate();
  const DiskAxisValidation v = validate_disk_union_axis(g, report);
  INFO((v.failures.empty() ? std::string() : v.failures.front()));
  REQUIRE(v.ok());
  return g;
}

std::string message_of(const std::string& text) {
  try {
    parse_disk_list(text, "in.txt");
  } catch (const DiskListError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("disk lists are read exactly, with comments and separators", "[measures2d]") {
  const DiskList l = parse_disk_list("# header\n\n0.1 -2.5e-1 3 # trailing\n1,2,\t.5\n", "in.txt");
  REQUIRE(l.disks.size() == 2);
  CHECK(l.disks[0].x == make_rational(1, 10));
  CHECK(l.disks[0].y == make_rational(-1, 4));
  CHECK(l.disks[0].r == 3);
  CHECK(l.disks[0].line == 3);
  CHECK(l.disks[1].r == make_rational(1, 2));
  CHECK(l.disks[1].line == 4);
}

TEST_CASE("malformed disk lists name the file, the line and the problem", "[measures2d]") {
  CHECK(message_of("0 0 1\nnan 1 1\n") == "in.txt:2: x = 'nan' is not a decimal number (at most 1000 digits, an "
                                          "optional point and an exponent of at most 300)");
  CHECK(message_of("0 0 inf\n").find("in.txt:1: r = 'inf'") == 0);
  CHECK(message_of("0x1p3 0 1\n").find("in.txt:1: x") == 0);
  CHECK(message_of("1/2 0 1\n").find("in.txt:1: x") == 0);
  CHECK(message_of("0 0 1e400\n").find("in.txt:1: r") == 0);
  CHECK(message_of("0 0 0\n") == "in.txt:1: radius r = 0 must be positive");
  CHECK(message_of("0 0 1\n1 1 -0.5\n") == "in.txt:2: radius r = -0.5 must be positive");
  CHECK(message_of("0 0 1\n1 1\n") == "in.txt:2: expected three numbers 'x y r', found 2 fields");
  CHECK(message_of("0 0 1 2\n") == "in.txt:1: expected three numbers 'x y r', found 4 fields");
  CHECK(message_of("# nothing\n") == "in.txt: no disks (one 'x y r' line per disk)");
  CHECK_THROWS_WITH(read_disk_list(kDisks + "nan.txt"), Catch::Contains("nan.txt:2: x = 'nan'"));
  CHECK_THROWS_WITH(read_disk_list(kDisks + "missing.txt"), Catch::Contains("missing.txt: cannot open"));
  CHECK_THROWS_WITH(read_disk_list(kDisks), Catch::Contains("is a directory"));
}

TEST_CASE("two disks: the segment between the centres", "[measures2d]") {
  DiskUnionAxisReport report;
  const MedialGraph g = valid_axis(read_disk_list(kDisks + "two.txt"), report);
  CHECK(report.corners == 2);
  CHECK(report.arcs == 2);
  REQUIRE(g.node_count() == 2);
  REQUIRE(g.edge_count() == 1);
  const std::uint32_t a = node_at(g, rat(0), rat(0)), b = node_at(g, rat(1), rat(0));
  CHECK(equals(g.geometry().exact_radius(a), rat(1)));
  CHECK(equals(g.geometry().exact_radius(b), rat(1)));
  CHECK(equals(g.geometry().exact_length(0), rat(1)));
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.size() == 1);
  CHECK(exact_ema_offset(r, r.ema[0]) == make_rational(1, 2));
  CHECK(exact_ema_edf(r, r.ema[0]) == make_rational(3, 2));
}

TEST_CASE("three disks in an L with rational corners: a path through the middle centre", "[measures2d]") {
  // Circles of radius 5 at (8, 0), (0, 0), (0, 8) cross at (4, +-3) and (+-3, 4); the middle
  // circle carries two arcs, so its centre is a Voronoi vertex of its four corners.
  DiskUnionAxisReport report;
  const MedialGraph g = valid_axis(parse_disk_list("8 0 5\n0 0 5\n0 8 5\n", "L"), report);
  CHECK(report.corners == 4);
  CHECK(report.voronoi_vertices == 1);
  REQUIRE(g.node_count() == 3);
  REQUIRE(g.edge_count() == 2);
  const std::uint32_t mid = node_at(g, rat(0), rat(0));
  CHECK(g.degree(mid) == 2);
  for (std::uint32_t e = 0; e < 2; ++e) CHECK(equals(g.geometry().exact_length(e), rat(8)));
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.size() == 1);
  REQUIRE(r.ema[0].point.at_node);
  CHECK(r.ema[0].point.node == mid);
  CHECK(exact_value(r, mid) == 13);  // both leaves ignite at R = 5 and arrive after 8
}

TEST_CASE("three overlapping disks: a Y whose junction is on the symmetry axis", "[measures2d]") {
  DiskUnionAxisReport report;
  const MedialGraph g = valid_axis(read_disk_list(kDisks + "three.txt"), report);
  CHECK(report.dual_triangles == 1);
  REQUIRE(g.node_count() == 4);
  REQUIRE(g.edge_count() == 3);
  const auto& geo = dynamic_cast<const DiskUnionGeometry&>(g.geometry());
  std::uint32_t junctions = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    if (geo.node_data(v).kind == UnionNodeKind::Center) {
      CHECK(g.degree(v) == 1);
      CHECK(equals(geo.exact_radius(v), rat(1)));
      continue;
    }
    ++junctions;
    CHECK(g.degree(v) == 3);
    CHECK(equals(geo.exact_position(v)[0], rat(1, 2)));  // the disks are symmetric about x = 1/2
  }
  CHECK(junctions == 1);
}

TEST_CASE("a ring of disks around a hole: the axis has one cycle", "[measures2d]") {
  DiskUnionAxisReport report;
  const MedialGraph g = valid_axis(read_disk_list(kDisks + "ring.txt"), report);
  CHECK(report.union_components == 1);
  CHECK(report.union_holes == 1);
  CHECK(g.cycle_rank() == 1);
  CHECK(report.leaves == 4);  // the corner disks carry one arc each
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.size() == 1);
  CHECK(r.ema[0].kind == ExtendedMedialAxis::Kind::Cycles);
}

TEST_CASE("covered disks are ignored and separate groups give a forest", "[measures2d]") {
  DiskUnionAxisReport covered;
  const MedialGraph g = valid_axis(read_disk_list(kDisks + "covered.txt"), covered);
  CHECK(covered.covered_disks == 2);
  REQUIRE(g.edge_count() == 1);
  CHECK(equals(g.geometry().exact_length(0), rat(3)));
  DiskUnionAxisReport separate;
  const MedialGraph f = valid_axis(read_disk_list(kDisks + "separate.txt"), separate);
  CHECK(separate.isolated_disks == 1);
  CHECK(f.component_count() == 2);
  const std::uint32_t lone = node_at(f, rat(0), rat(0));
  CHECK(f.degree(lone) == 0);
  CHECK(extended_grassfire(f).ema.size() == 2);
}

TEST_CASE("degenerate unions are rejected with the disks involved", "[measures2d]") {
  CHECK_THROWS_WITH(disk_union_axis(read_disk_list(kDisks + "touching.txt")),
                    Catch::Contains("touching.txt: the circles of the disks on line 2, line 3 meet at one point") &&
                        Catch::Contains("the disks touch there"));
  CHECK_THROWS_WITH(disk_union_axis(read_disk_list(kDisks + "three-circles.txt")),
                    Catch::Contains("line 3, line 4, line 5") && Catch::Contains("three or more circles"));
  // Three circles through a point that the three disks surround: an interior point, fine.
  DiskUnionAxisReport report;
  const MedialGraph g = valid_axis(read_disk_list(kDisks + "three-circles-inside.txt"), report);
  CHECK(report.corners == 3);
  CHECK(g.node_count() == 4);
  // Tangent inside a third disk: harmless.
  DiskUnionAxisReport inside;
  valid_axis(parse_disk_list("0 0 1\n2 0 1\n1 0 0.5\n", "t"), inside);
  CHECK(inside.union_components == 1);
}

TEST_CASE("random unions: valid axes with the Betti numbers of the union: translation", "[measures2d]") {
  std::mt19937 rng(44);
  std::uniform_int_distribution<int> coord(0, 600), radius(40, 150);
  for (int k = 0; k < 12; ++k) {
    std::string text, moved;
    for (int i = 0; i < 6 + k; ++i) {
      const int x = coord(rng), y = coord(rng), r = radius(rng);
      text += std::to_string(x) + "e-2 " + std::to_string(y) + "e-2 " + std::to_string(r) + "e-2\n";
      moved += std::to_string(x + 25) + "e-2 " + std::to_string(y - 150) + "e-2 " + std::to_string(r) + "e-2\n";
    }
    DiskUnionAxisReport report, report2;
    const MedialGraph g = valid_axis(parse_disk_list(text, "random"), report);
    const MedialGraph h = disk_union_axis(parse_disk_list(moved, "moved"), &report2);
    CHECK(g.component_count() == report.union_components);
    CHECK(g.cycle_rank() == report.union_holes);
    // Translated by (1/4, -3/2): the same graph, every node moved exactly.
    REQUIRE(h.node_count() == g.node_count());
    REQUIRE(h.edge_count() == g.edge_count());
    const auto& geo = dynamic_cast<const DiskUnionGeometry&>(g.geometry());
    for (std::uint32_t v = 0; v < g.node_count(); ++v)
      node_at(h, geo.exact_position(v)[0] + rat(1, 4), geo.exact_position(v)[1] - rat(3, 2));
  }
}

TEST_CASE("the pipeline and grassfire edf2d --disks", "[measures2d]") {
  const DiskList list = read_disk_list(kDisks + "ring.txt");
  Edf2dOptions o;
  o.axis = AxisMethod::DiskUnion;
  CHECK_THROWS_AS(compute_edf2d(Shape2{}, o), std::invalid_argument);
  o.disks = &list;
  const Edf2dResult r = compute_edf2d(Shape2{}, o);
  CHECK(r.disk_report.union_holes == 1);
  CHECK(r.graph->cycle_rank() == 1);

  const std::string out = grassfire::testing::temp_path("gf_measures2d_disks.json");
  std::filesystem::remove(out);
  const CliRun ok = run_cli("edf2d --disks " + kDisks + "three.txt --json " + out);
  REQUIRE(ok.code == 0);
  CHECK(ok.output.find("exact axis of a union of 3 disks") != std::string::npos);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["format"] == "grassfire-medial2d");
  CHECK(j["nodes"].size() == 4);
  CHECK(!j["nodes"][0].contains("pr"));  // no arc lengths along circular arcs
  const CliRun bad = run_cli("edf2d --disks " + kDisks + "negative.txt");
  CHECK(bad.code == 1);
  CHECK(bad.output.find("negative.txt:2: radius r = -0.5 must be positive") != std::string::npos);
  CHECK(run_cli("edf2d rectangle --disks " + kDisks + "two.txt").code == 2);
  CHECK(run_cli("edf2d").code == 2);
}
