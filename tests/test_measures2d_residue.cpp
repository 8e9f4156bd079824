// Potential residue (3.4.2), separation angle and feature size (2.2.1), E(x) and boundary
// eccentricity (3.5.3): exact values on the rectangle, both axes.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "burn2/boundary_eccentricity.h"
#include "burn2/closest_points.h"
#include "burn2/feature_size.h"
#include "burn2/potential_residue.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

ExactSum rat(long n, long d = 1) { return ExactSum::rational(make_rational(n, d)); }
ExactSum root(long n) { return ExactSum::sqrt_of(n); }
bool equals(const ExactSum& a, const ExactSum& b) { return sign(a - b) == 0; }

std::uint32_t node_near(const MedialGraph& g, double x, double y) {
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (std::hypot(g.node(v).position.x - x, g.node(v).position.y - y) < 1e-9) return v;
  FAIL("no node at (" << x << ", " << y << ")");
  return 0;
}

// An enclosure that holds the exact value and is tight.
bool encloses(const Interval& i, const ExactSum& exact) {
  const Interval e = exact.approx();
  return i.lo <= e.hi && e.lo <= i.hi && i.hi - i.lo < 1e-9;
}

struct Axis {
  Shape2 shape;
  Edf2dResult result;
  ClosestPoints closest;
};

Axis rectangle(AxisMethod method, std::size_t samples = kDefaultSamples) {
  Axis a{builtin_shape("rectangle"), {}, {}};
  Edf2dOptions o;
  o.axis = method;
  o.samples = samples;
  a.result = compute_edf2d(a.shape, o);
  a.closest = closest_points(*a.result.graph, &a.shape, &a.result.samples);
  return a;
}

}  // namespace

TEST_CASE("PR on the rectangle's exact axis", "[measures2d]") {
  // 10 x 4: corners (R = 0) have PR 0; the junctions (2, 2) and (8, 2) have their three
  // closest points 2 + 2, 2 + 2 and 2 + 4 + 2 apart along the boundary, so PR = 8 (the
  // largest limit, along the central edge); on the central edge PR = min(2x + 4, 24 - 2x)
  // peaks at L / 2 = 14 at (5, 2), between (5, 0) and (5, 4).
  const Axis a = rectangle(AxisMethod::ExactPolygon);
  const MedialGraph& g = *a.result.graph;
  const PotentialResidue pr = potential_residue(g, a.closest);
  for (const auto& [x, y, value] : {std::tuple{0.0, 0.0, 0L}, {10.0, 4.0, 0L}, {2.0, 2.0, 8L}, {8.0, 2.0, 8L}}) {
    const ResidueValue& v = pr.node[node_near(g, x, y)];
    REQUIRE(v.exact);
    CHECK(equals(*v.exact, rat(value)));
  }
  const std::uint32_t j = node_near(g, 2, 2);
  g.for_each_incident(j, [&](std::uint32_t e) {  // diagonal limits 4, central limit 8
    const ResidueValue& limit = g.edge(e).u == j ? pr.edge[e].at_u : pr.edge[e].at_v;
    const bool central = std::fabs(g.node(g.other_end(e, j)).position.y - 2) < 1e-9;
    CHECK(equals(*limit.exact, rat(central ? 8 : 4)));
    CHECK(pr.edge[e].peak == central);
  });
  const ResidueMaximum& m = pr.maximum;
  CHECK_FALSE(m.at_node);
  CHECK(equals(*m.value.exact, rat(14)));
  CHECK(m.fraction.contains(0.5));
  CHECK(m.position.x == Approx(5).margin(1e-12));
  CHECK(m.position.y == Approx(2).margin(1e-12));
  CHECK(std::fabs(m.closest[0].x - 5) < 1e-12);
  CHECK(std::fabs(m.closest[0].y + m.closest[1].y - 4) < 1e-12);
  CHECK(pr.local_maxima == 1);
  const ResidueMonotonicity mono = residue_monotonicity(g, pr);
  CHECK(mono.edges_checked == 4);
  CHECK(mono.edge_decreases + mono.regular_decreases + mono.junction_decreases == 0);
}

TEST_CASE("PR, feature size and BE on a rectangle sampled at the integer points", "[measures2d]") {
  // 28 samples on the 10 x 4 rectangle: one per unit of length, at the integer points, so
  // every Voronoi vertex is rational and the values below are exact: the central nodes
  // (k + 1/2, 2) have R = sqrt(17) / 2; the EMA is (5, 2), inside the edge between them.
  const Axis a = rectangle(AxisMethod::Sampled, 28);
  const MedialGraph& g = *a.result.graph;
  const PotentialResidue pr = potential_residue(g, a.closest);
  const std::uint32_t c = node_near(g, 4.5, 2);
  CHECK(a.closest.node[c].size() == 4);  // (4, 0), (5, 0), (4, 4), (5, 4): cocircular
  CHECK(pr.node[c].sample_steps == 14);   // (5, 0) to (5, 4): 14 spacings either way
  CHECK(pr.node[node_near(g, 2, 2)].sample_steps == 8);
  CHECK(pr.node[node_near(g, 0.5, 0.5)].sample_steps == 2);
  CHECK(pr.maximum.value.sample_steps == 14);
  CHECK(pr.local_maxima == 1);

  const LocalFeatureMeasures f = local_feature_measures(g, a.closest);
  CHECK(encloses(f.feature_size[c], root(17).scale(mpq_class(1, 2))));  // the points surround it: r = R
  CHECK(f.separation_angle[c].contains(std::acos(-1.0)));              // (4, 0) and (5, 4) are antipodal
  const std::uint32_t d = node_near(g, 1.5, 2.5);                      // closest (2, 4), (1, 4), (0, 3), (0, 2)
  CHECK(encloses(f.feature_size[d], root(2)));                         // half the chord (2, 4)-(0, 2)
  CHECK(f.separation_angle[d].contains(2 * std::asin(std::sqrt(0.8))));

  const AxisEccentricity e = distance_to_ema(g, *a.result.burning);
  CHECK(encloses(e.node[c], rat(1, 2)));
  CHECK(equals(e.exact(c).exact(g), rat(1, 2)));
  const BoundaryEccentricity be = boundary_eccentricity(g, *a.result.burning, e, a.closest);
  CHECK(be.samples_without_medial_point == 0);
  CHECK(be.argmin[0][5] == kEmaPoint);  // (5, 0) generates the EMA's edge: BE = |ema - p| = 2
  CHECK(encloses(be.value[0][5], rat(2)));
  CHECK(be.argmin[0][4] == c);  // (4, 0): E + R = 1/2 + sqrt(17) / 2 at (4.5, 2)
  CHECK(encloses(be.value[0][4], rat(1, 2) + root(17).scale(mpq_class(1, 2))));
  CHECK(encloses(be.value[0][0], rat(3) + root(8)));  // the corner: 3 + 2 sqrt(2), as on the true axis
  CHECK(be.argmin[0][12] == node_near(g, 8, 2));     // (10, 2): E = 3 and R = 2 at (8, 2)
  CHECK(encloses(be.value[0][12], rat(5)));
}

TEST_CASE("E on the rectangle's exact axis", "[measures2d]") {
  const Axis a = rectangle(AxisMethod::ExactPolygon);
  const MedialGraph& g = *a.result.graph;
  const AxisEccentricity e = distance_to_ema(g, *a.result.burning);
  CHECK(equals(e.exact(node_near(g, 2, 2)).exact(g), rat(3)));
  CHECK(equals(e.exact(node_near(g, 10, 0)).exact(g), rat(3) + root(8)));
  CHECK_THROWS_AS(boundary_eccentricity(g, *a.result.burning, e, a.closest), std::invalid_argument);
}

TEST_CASE("PR is infinite where the closest points lie on different rings", "[measures2d]") {
  const Shape2 shape = builtin_shape("hole");
  Edf2dOptions o;
  o.samples = 600;
  const Edf2dResult r = compute_edf2d(shape, o);
  const PotentialResidue pr = potential_residue(*r.graph, closest_points(*r.graph, &shape, &r.samples));
  std::uint32_t infinite = 0;
  for (const ResidueValue& v : pr.node) infinite += v.value.is_infinite();
  CHECK(infinite > 0);
  CHECK(pr.maximum.value.value.is_infinite());
  CHECK_THROWS_AS(closest_points(*r.graph), std::invalid_argument);  // a sampled axis needs its samples
}

TEST_CASE("edf2d writes PR per node and the PR maximum", "[measures2d]") {
  const std::string out = grassfire::testing::temp_path("gf_measures2d_pr.json");
  std::filesystem::remove(out);
  const CliRun run = run_cli("edf2d rectangle --exact --quiet --json " + out);
  REQUIRE(run.code == 0);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["version"] == 1);
  for (const auto& n : j["nodes"]) REQUIRE(n.contains("pr"));
  CHECK(j["pr_max"]["x"].get<double>() == Approx(5));
  CHECK(j["pr_max"]["y"].get<double>() == Approx(2));
  CHECK(j["pr_max"]["pr"].get<double>() == Approx(14));
  CHECK(j["error_bound"].contains("pr"));
}
