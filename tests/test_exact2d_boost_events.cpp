// Boost.Polygon's builder read from its events (medial2/polygon/boost_voronoi_events.h)
// against the same builder's full voronoi_diagram read by BoostExtractor (the reference):
// the identical interior topology, vertex by vertex and edge by edge in the same order, in
// the int32, wide and mp frames, on seeded polygons (stars, dense wavy curves with and
// without a mirror symmetry, cocircular grids, holes) and every shape of data/shapes2d.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "io/load_shape.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/segment_voronoi.h"
#include "shapes/validate_shape.h"
#include "binary_frame.h"

using namespace grassfire;

namespace {

Shape2 rings_shape(std::vector<std::vector<Point2>> rings, const std::string& name) {
  Shape2 s;
  s.name = name;
  for (auto& r : rings) s.rings.push_back({std::move(r)});
  validate_shape(s, name);
  return s;
}

void require_identical(const VoronoiTopology& a, const VoronoiTopology& b) {
  REQUIRE(a.vertices.size() == b.vertices.size());
  REQUIRE(a.edges.size() == b.edges.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    INFO("vertex " << i);
    REQUIRE(a.vertices[i].sites == b.vertices[i].sites);
    REQUIRE(a.vertices[i].apex == b.vertices[i].apex);
  }
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    INFO("edge " << e);
    const auto &x = a.edges[e], &y = b.edges[e];
    REQUIRE(x.u == y.u);
    REQUIRE(x.v == y.v);
    REQUIRE(x.site_a == y.site_a);
    REQUIRE(x.site_b == y.site_b);
  }
}

// Every Boost reader that accepts the shape's binary frame: events = diagram.
void require_events_equal_diagram(const Shape2& s) {
  INFO(s.name);
  const PolygonSites sites = testing::binary_frame(s);
  bool int32 = true;
  for (const Point2& p : sites.vertex) int32 = int32 && std::fabs(p.x) <= 2147483647.0 && std::fabs(p.y) <= 2147483647.0;
  if (int32) require_identical(boost_segment_voronoi(sites), boost_segment_voronoi(sites, BoostReader::Diagram));
  if (fits_wide_boost(sites))
    require_identical(boost_segment_voronoi_wide(sites), boost_segment_voronoi_wide(sites, BoostReader::Diagram));
  if (sites.vertex_count() <= 3000)  // the mp traits cost ~10x the others
    require_identical(boost_segment_voronoi_mp(sites), boost_segment_voronoi_mp(sites, nullptr, true, false, BoostReader::Diagram));
}

std::vector<Point2> star(std::mt19937& rng, int n, double r, bool integer) {
  std::uniform_real_distribution<double> radius(0.3 * r, r), jitter(-0.3, 0.3);
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * (k + jitter(rng)) / n, rk = radius(rng);
    Point2 p{rk * std::cos(t), rk * std::sin(t)};
    if (integer) p = {std::round(p.x), std::round(p.y)};
    ring.push_back(p);
  }
  return ring;
}

std::vector<Point2> wavy(int n, double r, double phase, bool integer) {
  std::vector<Point2> ring;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n, rk = r * (1 + 0.1 * std::sin(7 * t + phase));
    Point2 p{rk * std::cos(t), rk * std::sin(t)};
    if (integer) p = {std::round(p.x), std::round(p.y)};
    ring.push_back(p);
  }
  return ring;
}

}  // namespace

TEST_CASE("Boost's events give its diagram's topology: seeded stars, integer and full-mantissa", "[exact2d][boost-events]") {
  std::mt19937 rng(20261208);
  for (int k = 0; k < 40; ++k) {
    const int n = 5 + k * 3;
    require_events_equal_diagram(rings_shape({star(rng, n, 1e4, true)}, "integer star " + std::to_string(k)));
    require_events_equal_diagram(rings_shape({star(rng, n, 1.0, false)}, "double star " + std::to_string(k)));
  }
}

TEST_CASE("Boost's events give its diagram's topology: wavy curves, cocircular grids, holes", "[exact2d][boost-events]") {
  for (int n : {200, 2000, 20000}) {
    require_events_equal_diagram(rings_shape({wavy(n, 1e6, 0.0, true)}, "symmetric wavy " + std::to_string(n)));
    require_events_equal_diagram(rings_shape({wavy(n, 1e6, 0.3, true)}, "shifted wavy " + std::to_string(n)));
  }
  require_events_equal_diagram(rings_shape({wavy(3000, 1.0, 0.3, false)}, "full-mantissa wavy"));
  // Regular polygons and rectangles: cocircular sites, zero-length edges kept.
  for (int n : {4, 6, 8, 12}) {
    std::vector<Point2> ring;
    for (int k = 0; k < n; ++k) ring.push_back({std::round(1000 * std::cos(2 * M_PI * k / n)), std::round(1000 * std::sin(2 * M_PI * k / n))});
    require_events_equal_diagram(rings_shape({ring}, "regular " + std::to_string(n)));
  }
  require_events_equal_diagram(rings_shape({{{0, 0}, {8, 0}, {8, 8}, {0, 8}}, {{2, 2}, {2, 6}, {6, 6}, {6, 2}}}, "square with a hole"));
  require_events_equal_diagram(
      rings_shape({{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {4, 4}, {2, 4}, {0, 4}, {0, 2}}}, "square with collinear vertices"));
}

TEST_CASE("Boost's events give its diagram's topology on every shape of data/shapes2d", "[exact2d][boost-events]") {
  int shapes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(GF_PROJECT_DATA "/shapes2d")) {
    if (entry.path().extension() != ".json") continue;
    require_events_equal_diagram(load_shape(entry.path().string()));
    ++shapes;
  }
  CHECK(shapes >= 100);
}
