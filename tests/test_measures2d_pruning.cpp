// Rate pruning (3.4.1) as an independent computation of ET, and pruning by ET and ST
// thresholds (3.5.1), plain and topology-preserving, with `grassfire prune2d`.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>

#include "burn2/axis_pruning.h"
#include "burn2/rate_pruning.h"
#include "medial2/synthetic_graphs.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

void require_et_identity(const MedialGraph& g) {
  const GrassfireResult burn = extended_grassfire(g);
  const RatePruning rp = rate_pruning(g);
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    REQUIRE(burn.is_infinite(v) == !rp.time[v]);
    if (!rp.time[v]) continue;
    GraphSum et = burn.times.as_graph_sum(burn.burn[v]);
    et.add_radius(v, -1);
    REQUIRE(compare(et, *rp.time[v], g) == 0);
  }
}

PrunedAxis prune(const std::string& shape, AxisMethod method, double relative_et, const mpq_class& st,
                 bool topology) {
  const Shape2 s = builtin_shape(shape);
  Edf2dOptions o;
  o.axis = method;
  const Edf2dResult r = compute_edf2d(s, o);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const Point2& p : s.rings[0].points)
    x0 = std::fmin(x0, p.x), x1 = std::fmax(x1, p.x), y0 = std::fmin(y0, p.y), y1 = std::fmax(y1, p.y);
  PruningThresholds t;
  t.erosion = mpq_class(relative_et) * mpq_class(std::fmax(x1 - x0, y1 - y0));
  t.tubularity = st;
  t.topology = topology;
  return prune_axis(*r.graph, *r.burning, t);
}

std::uint64_t components(const PrunedAxis& p) {
  std::vector<std::uint32_t> parent(p.nodes.size());
  std::iota(parent.begin(), parent.end(), 0u);
  std::function<std::uint32_t(std::uint32_t)> find = [&](std::uint32_t x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  std::uint64_t n = p.nodes.size();
  for (const PrunedEdge& e : p.edges)
    if (find(e.u) != find(e.v)) parent[find(e.u)] = find(e.v), --n;
  return n;
}

const mpq_class kSt = make_rational(3, 10);  // just above 1 - 1/sqrt(2), the ST of a right-angled corner's branch

}  // namespace

TEST_CASE("rate pruning by hand on a star", "[measures2d]") {
  // Centre c (R = 3) with leaves a (R = 1, edge 5), b (R = 0, edge 4), d (R = 2, edge 1).
  // Fronts cross an edge i -> j in w - R(j) + R(i): they reach c at 3 (from a), 1 (b) and
  // 0 (d); c is pruned by the second arrival, at 1 = EDF(c) - R(c) = 4 - 3, and the front
  // goes on towards a, meeting a's front (w + P_c + R_c - P_a - R_a) / 2 = 4 from a.
  const MedialGraph g = integer_graph({3, 1, 0, 2}, {{0, 1, 5}, {0, 2, 4}, {0, 3, 1}});
  const RatePruning rp = rate_pruning(g);
  CHECK(rp.time[0]->exact(g).rational_part() == 1);
  for (std::uint32_t leaf : {1u, 2u, 3u}) CHECK(sign(rp.time[leaf]->exact(g)) == 0);
  REQUIRE(rp.last_quench.size() == 1);
  const PruningQuench& q = rp.last_quench[0];
  REQUIRE_FALSE(q.at_node);
  CHECK(q.edge == 0);
  const mpq_class from_a = q.from == 1 ? q.offset.exact(g).rational_part() : 5 - q.offset.exact(g).rational_part();
  CHECK(from_a == 4);
  require_et_identity(g);
}

TEST_CASE("rate pruning equals EDF - R exactly on random graphs", "[measures2d]") {
  for (std::uint32_t k = 0; k < 60; ++k) {
    const MedialGraph g = random_medial_graph(900 + k, 3 + k % 40, k % 4 == 0 ? 1 + k % 3 : 0,
                                              k % 2 ? SyntheticFamily::Integer : SyntheticFamily::Geometric);
    require_et_identity(g);
  }
}

TEST_CASE("pruning the rectangle with a bump drops the bump's branch and the corners", "[measures2d]") {
  for (AxisMethod m : {AxisMethod::Sampled, AxisMethod::ExactPolygon})
    for (bool topology : {false, true}) {
      const PrunedAxis p = prune("rectangle-bump", m, 0.05, kSt, topology);
      REQUIRE(!p.nodes.empty());
      double x0 = 1e300, x1 = -1e300;
      for (const PrunedNode& n : p.nodes) {
        CHECK(std::fabs(n.position.y - 2) < 0.01);  // only the central segment
        x0 = std::fmin(x0, n.position.x), x1 = std::fmax(x1, n.position.x);
      }
      CHECK(x0 < 2.1);
      CHECK(x1 > 7.9);
      CHECK(components(p) == 1);
      CHECK(p.cut_points == 2);
      CHECK(p.uncertified == 0);
    }
}

TEST_CASE("pruning blunt-sharp keeps the sharp protrusion, drops blunt corners and noise", "[measures2d]") {
  // The thin rectangle's axis y = 2 runs to its corner junction (8.6, 2), where R = 0.4 and
  // EDF = 0.4 sqrt(2); ET = EDF - R grows by 1 per unit to the left, so with T = 0.05 x 9 it
  // is cut at x = 8.6 - (0.45 - 0.4 sqrt(2) + 0.4) = 7.75 + 0.4 sqrt(2).
  const double cut = 7.75 + 0.4 * std::sqrt(2.0);
  for (bool topology : {false, true}) {
    const PrunedAxis p = prune("blunt-sharp", AxisMethod::ExactPolygon, 0.05, kSt, topology);
    double x1 = -1e300;
    for (const PrunedNode& n : p.nodes) {
      CHECK(std::fabs(n.position.y - 2) < 0.01);  // no diagonal branch, no bump branch (its junction dips 0.005)
      x1 = std::fmax(x1, n.position.x);
    }
    CHECK(x1 == Approx(cut).epsilon(1e-12));
    CHECK(components(p) == 1);
  }
  const PrunedAxis sampled = prune("blunt-sharp", AxisMethod::Sampled, 0.05, kSt, false);
  for (const PrunedNode& n : sampled.nodes) CHECK(std::fabs(n.position.y - 2) < 0.01);
}

TEST_CASE("topology-preserving pruning keeps the hole's cycle and a tree's EMA", "[measures2d]") {
  const PrunedAxis hole = prune("hole", AxisMethod::Sampled, 0.3, make_rational(1, 2), true);
  CHECK(components(hole) == 1);
  CHECK(hole.edges.size() + components(hole) - hole.nodes.size() == 1);
  const PrunedAxis all_gone = prune("rectangle", AxisMethod::ExactPolygon, 100, 0, false);
  CHECK(all_gone.nodes.empty());
  const PrunedAxis ema = prune("rectangle", AxisMethod::ExactPolygon, 100, 0, true);
  REQUIRE(ema.nodes.size() == 1);
  CHECK(ema.edges.empty());
  CHECK(ema.nodes[0].position.x == Approx(5));
  CHECK(ema.nodes[0].position.y == Approx(2));
  const PrunedAxis whole = prune("branches", AxisMethod::ExactPolygon, 0, 0, false);
  const Edf2dResult r = compute_edf2d(builtin_shape("branches"), Edf2dOptions{AxisMethod::ExactPolygon});
  CHECK(whole.nodes.size() == r.graph->node_count());
  CHECK(whole.edges.size() == r.graph->edge_count());
}

TEST_CASE("grassfire prune2d", "[measures2d]") {
  const std::string out = grassfire::testing::temp_path("gf_measures2d_prune.json");
  std::filesystem::remove(out);
  const CliRun run = run_cli("prune2d blunt-sharp --exact --et 0.05 --relative --st 0.3 --topology --json " + out);
  REQUIRE(run.code == 0);
  CHECK(run.output.find("1 components, 0 independent cycles") != std::string::npos);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["format"] == "grassfire-pruned2d");
  CHECK(j["thresholds"]["et"].get<double>() == Approx(0.45));
  CHECK(j["thresholds"]["topology"] == true);
  std::size_t cuts = 0;
  for (const auto& n : j["nodes"]) cuts += n["source"].contains("edge");
  CHECK(cuts == 2);
  for (const auto& e : j["edges"]) CHECK(e["u"].get<std::size_t>() < j["nodes"].size());
  const CliRun bad = run_cli("prune2d rectangle --st 1.5");
  CHECK(bad.code == 1);
  CHECK(bad.output.find("--st must be at most 1") != std::string::npos);
  CHECK(run_cli("prune2d rectangle --et -1").code == 1);
  CHECK(run_cli("prune2d rectangle --et abc").code == 1);
}
