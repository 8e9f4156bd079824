// The Voronoi medial axis of boundary samples (medial2/sampled/sampled_axis.h) and the 2D pipeline.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "burn2/edf_definition.h"
#include "geometry2/predicates2.h"
#include "medial2/sampled/sampled_geometry.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

Shape2 rectangle(double w, double h) {
  Shape2 s;
  s.name = "rectangle " + std::to_string(w) + "x" + std::to_string(h);
  s.rings.push_back(Ring{{{0, 0}, {w, 0}, {w, h}, {0, h}}});
  return s;
}

Shape2 transformed(const Shape2& s, double scale, double dx, double dy) {
  Shape2 t = s;
  for (Ring& r : t.rings)
    for (Point2& p : r.points) p = {p.x * scale + dx, p.y * scale + dy};
  return t;
}

}  // namespace

TEST_CASE("a 4x2 rectangle sampled symmetrically: EMA at the centre with EDF exactly 1 + sqrt 2", "[sampled]") {
  Edf2dOptions o;
  o.spacing = 0.25;  // exact binary fractions: the samples are exactly symmetric
  const Edf2dResult r = compute_edf2d(rectangle(4, 2), o);
  const MedialGraph& g = *r.graph;
  g.validate();
  CHECK(r.axis_report.samples == 48);
  CHECK(r.axis_report.merged_triangles > 0);  // cocircular samples share Voronoi vertices
  CHECK(g.component_count() == 1);
  CHECK(g.cycle_rank() == 0);
  REQUIRE(r.burning->ema.size() == 1);
  const ExtendedMedialAxis& ema = r.burning->ema[0];
  const Point2 p = position_of(g, ema.point);
  CHECK(std::fabs(p.x - 2) < 1e-12);
  CHECK(std::fabs(p.y - 1) < 1e-12);
  ExactSum edf = ema_edf_sum(*r.burning, ema).exact(g) - ExactSum::rational(1) - ExactSum::sqrt_of(2);
  CHECK(sign(edf) == 0);
}

TEST_CASE("the shape with a hole: one cycle, infinite EDF exactly on it", "[sampled]") {
  const Edf2dResult r = compute_edf2d(builtin_shape("hole"));
  const MedialGraph& g = *r.graph;
  g.validate();
  CHECK(g.component_count() == 1);
  CHECK(g.cycle_rank() == 1);
  REQUIRE(r.burning->ema.size() == 1);
  CHECK(r.burning->ema[0].kind == ExtendedMedialAxis::Kind::Cycles);
  const TwoCore core = two_core(g);
  for (std::uint32_t v = 0; v < g.node_count(); ++v) CHECK(r.burning->is_infinite(v) == core.node_in_core[v]);
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (core.node_in_core[v]) CHECK(r.measures.tubularity[v].lo == 1.0);
}

TEST_CASE("every node lies inside the shape and R is the distance to the nearest sample", "[sampled]") {
  const Shape2 s = builtin_shape("branches");
  const Edf2dResult r = compute_edf2d(s);
  const MedialGraph& g = *r.graph;
  std::vector<Point2> samples;
  for (const auto& ring : r.samples) samples.insert(samples.end(), ring.begin(), ring.end());
  REQUIRE(g.node_count() > 100);
  std::size_t inside = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const MedialNode& n = g.node(v);
    INFO("node " << v);
    // Exactly inside the polygon (the double position is within position_error of the
    // exact one, and no node comes that close to the boundary here).
    inside += locate_in_shape(n.position, s) == BoundedSide::Inside;
    double nearest = 1e300;
    for (const Point2& q : samples) nearest = std::min(nearest, std::hypot(q.x - n.position.x, q.y - n.position.y));
    // R encloses the exact distance from the exact position; the double position moves
    // the distance by at most sqrt2 position_error, and hypot rounds by a few ulps.
    CHECK(std::fabs(nearest - n.radius.mid()) <= n.radius.radius() + 1.5 * n.position_error + 1e-14 * (1 + nearest));
  }
  CHECK(inside == g.node_count());
}

TEST_CASE("exact similarity transforms of the samples change nothing but the scale", "[sampled][metamorphic]") {
  // Scaling by 2 and mirroring are exact on doubles, so the transformed samples are
  // exactly the transformed points and the axis must have the same combinatorics.
  const Shape2 s = builtin_shape("branches");
  const BoundarySamples samples = resample_by_count(s, 2000);
  for (const double sx : {2.0, -2.0}) {
    const Shape2 t = transformed(s, 1.0, 0.0, 0.0);
    Shape2 u = t;
    BoundarySamples v = samples;
    for (Ring& r : u.rings)
      for (Point2& p : r.points) p = {sx * p.x, 2.0 * p.y};
    for (auto& ring : v)
      for (Point2& p : ring) p = {sx * p.x, 2.0 * p.y};
    if (sx < 0)  // mirroring reverses the orientation of every ring
      for (Ring& r : u.rings) std::reverse(r.points.begin(), r.points.end());
    const MedialGraph ga = sampled_medial_axis(s, samples), gb = sampled_medial_axis(u, v);
    REQUIRE(ga.node_count() == gb.node_count());
    REQUIRE(ga.edge_count() == gb.edge_count());
    const GrassfireResult a = extended_grassfire(ga), b = extended_grassfire(gb);
    double worst = 0;
    std::vector<double> ea, eb;
    for (std::uint32_t n = 0; n < ga.node_count(); ++n) ea.push_back(2 * a.edf(n).mid());
    for (std::uint32_t n = 0; n < gb.node_count(); ++n) eb.push_back(b.edf(n).mid());
    std::sort(ea.begin(), ea.end());
    std::sort(eb.begin(), eb.end());
    for (std::size_t n = 0; n < ea.size(); ++n) worst = std::max(worst, std::fabs(ea[n] - eb[n]));
    CHECK(worst < 1e-9);
    CHECK(std::fabs(2 * a.ema[0].edf.mid() - b.ema[0].edf.mid()) < 1e-9);
  }
}

TEST_CASE("the engine equals the definition on every real shape of the test data", "[sampled][oracle]") {
  int shapes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GF_PROJECT_DATA) + "/shapes2d")) {
    if (entry.path().extension() != ".json") continue;
    const Shape2 s = load_shape(entry.path().string());
    Edf2dOptions o;
    o.samples = 600;
    const Edf2dResult r = compute_edf2d(s, o);
    INFO(s.name);
    r.graph->validate();
    require_equal_to_definition(*r.graph, *r.burning, edf_by_definition(*r.graph));
    ++shapes;
  }
  CHECK(shapes >= 100);
}

TEST_CASE("the insertion order does not change the axis: rings started elsewhere give the same nodes and edges",
          "[sampled][metamorphic]") {
  // Starting every ring at another sample renumbers the samples, which changes the rounds
  // and the order of the triangulation's insertions (sampled_axis.cpp, triangulate) and the
  // storage order of its triangles. The Delaunay triangulation, hence the axis, is the same:
  // same counts, and every node and edge matches one of the other axis within the bounds.
  for (const char* name : {"rectangle", "hole", "noisy", "branches"}) {
    INFO(name);
    const Shape2 s = builtin_shape(name);
    const BoundarySamples samples = resample_by_count(s, 3000);
    BoundarySamples rotated = samples;
    for (auto& ring : rotated) std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(ring.size() / 3), ring.end());
    const MedialGraph a = sampled_medial_axis(s, samples), b = sampled_medial_axis(s, rotated);
    REQUIRE(a.node_count() == b.node_count());
    REQUIRE(a.edge_count() == b.edge_count());
    REQUIRE(a.node_count() > 1000);
    // Node positions of merged cocircular triangles may come from different triangles, so
    // they are matched within their error bounds, after sorting.
    auto sorted_nodes = [](const MedialGraph& g) {
      std::vector<MedialNode> n;
      for (std::uint32_t v = 0; v < g.node_count(); ++v) n.push_back(g.node(v));
      std::sort(n.begin(), n.end(), [](const MedialNode& p, const MedialNode& q) {
        return std::tie(p.position.x, p.position.y) < std::tie(q.position.x, q.position.y);
      });
      return n;
    };
    const std::vector<MedialNode> na = sorted_nodes(a), nb = sorted_nodes(b);
    std::size_t matched = 0;
    for (std::size_t k = 0; k < na.size(); ++k) {
      const double tolerance = na[k].position_error + nb[k].position_error;
      matched += std::fabs(na[k].position.x - nb[k].position.x) <= tolerance &&
                 std::fabs(na[k].position.y - nb[k].position.y) <= tolerance &&
                 na[k].radius.lo <= nb[k].radius.hi && nb[k].radius.lo <= na[k].radius.hi;
    }
    CHECK(matched == na.size());
    const GrassfireResult ba = extended_grassfire(a), bb = extended_grassfire(b);
    REQUIRE(ba.ema.size() == bb.ema.size());
    CHECK(ba.ema[0].kind == bb.ema[0].kind);
    if (ba.ema[0].kind == ExtendedMedialAxis::Kind::Point) {
      CHECK(ba.ema[0].edf.lo <= bb.ema[0].edf.hi);
      CHECK(bb.ema[0].edf.lo <= ba.ema[0].edf.hi);
    }
  }
}

TEST_CASE("sampled axis nodes are numbered by the smallest sample of their triangle, edges by their smaller end",
          "[sampled]") {
  const Shape2 s = builtin_shape("branches");
  const MedialGraph g = sampled_medial_axis(s, resample_by_count(s, 4000));
  const auto* geometry = dynamic_cast<const SampledVoronoiGeometry*>(&g.geometry());
  REQUIRE(geometry != nullptr);
  REQUIRE(g.node_count() > 1000);
  auto key = [&](std::uint32_t v) {
    const auto& t = geometry->node_triangle(v);
    return std::min({t[0], t[1], t[2]});
  };
  std::size_t ordered_nodes = 0, ordered_edges = 0;
  for (std::uint32_t v = 1; v < g.node_count(); ++v) ordered_nodes += key(v - 1) <= key(v);
  for (std::uint32_t e = 1; e < g.edge_count(); ++e)
    ordered_edges += std::min(g.edge(e - 1).u, g.edge(e - 1).v) <= std::min(g.edge(e).u, g.edge(e).v);
  CHECK(ordered_nodes == g.node_count() - 1);
  CHECK(ordered_edges == g.edge_count() - 1);
}

TEST_CASE("coincident samples are rejected with a clear message", "[sampled]") {
  const Shape2 s = rectangle(1, 1);
  std::vector<std::vector<Point2>> samples{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0}}};
  CHECK_THROWS_WITH(sampled_medial_axis(s, samples), Catch::Contains("not pairwise distinct"));
}
