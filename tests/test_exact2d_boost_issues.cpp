// The exact polygon axis on polygons where Boost.Polygon's Voronoi builder is known to go
// wrong (the polygon of boostorg/polygon #43 and its variants) and on seeded adversarial
// polygons (shapes/adversarial_polygons.h): every diagram is checked
// (medial2/polygon/segment_voronoi_check.h), a wrong one is rebuilt by CGAL's segment Delaunay graph,
// and the axis passes the definition-level check (medial2/polygon/polygon_axis_validate.h: R is the
// distance to the boundary at every node, the leaves are the convex corners).
#include <catch2/catch.hpp>

#include <string>

#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/polygon_axis_validate.h"
#include "medial2/polygon/segment_voronoi.h"
#include "medial2/polygon/segment_voronoi_check.h"
#include "shapes/adversarial_polygons.h"
#include "shapes/validate_shape.h"
#include "support.h"

using namespace grassfire;

namespace {

Shape2 issue43(double tiny, double scale) {
  Shape2 s{"boost-43", {Ring{{{0, 1e7}, {7e5, tiny}, {7e5, 9e6}, {9.1e6, 9e6}, {9.1e6, 0}, {1e7, 1e7}}}}};
  for (Point2& p : s.rings[0].points) p = {p.x * scale, p.y * scale};
  validate_shape(s, s.name);
  return s;
}

// The axis of `s` by `construction`, checked against the definition.
PolygonAxisReport require_valid_axis(const Shape2& s, AxisConstruction construction = AxisConstruction::Auto) {
  PolygonAxisReport rep;
  PolygonAxisOptions opt;
  opt.construction = construction;
  const MedialGraph g = exact_polygon_axis(s, opt, &rep);
  const AxisValidation v = validate_polygon_axis(g);
  INFO(s.name << " by " << to_string(rep.construction) << ": " << (v.ok() ? "" : v.failures.front()));
  REQUIRE(v.ok());
  return rep;
}

}  // namespace

TEST_CASE("Boost's wrong diagram of boostorg/polygon #43 is detected and rebuilt by CGAL", "[exact2d][boost-issues]") {
  const Shape2 s = issue43(1, 1);
  const PolygonSites sites = make_sites(s, 1.0);
  std::string defect;
  try {
    const VoronoiTopology topo = boost_segment_voronoi(sites);
    defect = voronoi_topology_defect(sites, topo, 0).value_or("");
  } catch (const std::logic_error& e) {
    defect = e.what();
  }
  CHECK_FALSE(defect.empty());  // Boost's own diagram is wrong here
  CHECK_FALSE(voronoi_topology_defect(sites, cgal_segment_voronoi(sites), 0).has_value());
  const PolygonAxisReport rep = require_valid_axis(s);
  CHECK(rep.voronoi_fallbacks == 1);
  CHECK(rep.construction == AxisConstruction::CgalSdg);
  CHECK(rep.rejected_construction == AxisConstruction::BoostPolygon);
  CHECK(rep.fallback_reason == defect);
}

TEST_CASE("variants of boostorg/polygon #43: other tiny coordinates and scales", "[exact2d][boost-issues]") {
  int fallbacks = 0;
  for (double tiny : {-3.0, -1.0, 0.0, 1.0, 2.0, 3.0})
    for (double scale : {1e-7, 1e-3, 0.1, 1.0, 10.0, 100.0}) {
      const Shape2 s = issue43(tiny, scale);
      const PolygonAxisReport rep = require_valid_axis(s);
      fallbacks += static_cast<int>(rep.voronoi_fallbacks);
      // The same axis as CGAL's diagram alone.
      PolygonAxisReport cgal;
      PolygonAxisOptions opt;
      opt.construction = AxisConstruction::CgalSdg;
      exact_polygon_axis(s, opt, &cgal);
      CHECK(cgal.nodes == rep.nodes);
      CHECK(cgal.edges == rep.edges);
      CHECK(cgal.leaves == rep.leaves);
    }
  CHECK(fallbacks >= 1);
}

TEST_CASE("adversarial polygons: every axis passes the definition check", "[exact2d][boost-issues]") {
  for (const std::string& kind : adversarial_polygon_kinds()) {
    int valid = 0;
    for (std::uint64_t seed = 1; seed <= 25; ++seed) {
      Shape2 s = adversarial_polygon(kind, seed);
      try {
        validate_shape(s, s.name);
      } catch (const InvalidShapeError&) {
        continue;
      }
      ++valid;
      require_valid_axis(s);
    }
    INFO(kind);
    CHECK(valid >= 10);
  }
}

TEST_CASE("edf2d --exact on the polygon of boostorg/polygon #43 reports the fallback", "[cli][boost-issues]") {
  const testing::CliRun r = testing::run_cli("edf2d " + std::string(GF_TEST_DATA) + "/shapes/boost_polygon_43.wkt --exact");
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(r.output.find("cgal-sdg; fallbacks 1: boost-polygon gave a wrong diagram") != std::string::npos);
}

TEST_CASE("the topology check refuses mutated diagrams of valid polygons", "[exact2d][boost-issues]") {
  // An L-shaped hexagon with a square hole: reflex corner, hole, collinear-free.
  Shape2 s{"ell", {Ring{{{0, 0}, {40, 0}, {40, 20}, {20, 20}, {20, 40}, {0, 40}}}, Ring{{{4, 4}, {8, 4}, {8, 8}, {4, 8}}}}};
  validate_shape(s, s.name);
  const PolygonSites sites = make_sites(s, 1.0);
  const VoronoiTopology good = boost_segment_voronoi(sites);
  REQUIRE_FALSE(voronoi_topology_defect(sites, good, 1).has_value());
  REQUIRE_FALSE(voronoi_topology_defect(sites, cgal_segment_voronoi(sites), 1).has_value());
  CHECK(voronoi_topology_defect(sites, good, 0).has_value());  // the hole's cycle is counted
  int refused = 0, mutants = 0;
  for (std::size_t e = 0; e < good.edges.size(); ++e) {
    VoronoiTopology t = good;  // an edge missing
    t.edges.erase(t.edges.begin() + static_cast<long>(e));
    refused += voronoi_topology_defect(sites, t, 1).has_value();
    t = good;  // an edge with a wrong site
    t.edges[e].site_a = (t.edges[e].site_a + 1) % sites.site_count();
    refused += voronoi_topology_defect(sites, t, 1).has_value();
    mutants += 2;
  }
  for (std::size_t v = 0; v < good.vertices.size(); ++v) {
    VoronoiTopology t = good;  // a vertex's site replaced
    t.vertices[v].sites[1] = (t.vertices[v].sites[1] + 3) % sites.site_count();
    refused += voronoi_topology_defect(sites, t, 1).has_value();
    ++mutants;
  }
  CHECK(refused == mutants);
}
