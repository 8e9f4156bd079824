// The exact extended grassfire (burn2/extended_grassfire.h) on hand-built graphs with
// exact expected values, and against the definitional oracle on seeded random graphs.
#include <catch2/catch.hpp>

#include "burn2/edf_definition.h"
#include "burn2/extended_grassfire.h"
#include "medial2/synthetic_graphs.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

TEST_CASE("two leaves quench in the middle of their edge", "[grassfire]") {
  const MedialGraph g = integer_graph({1, 1}, {{0, 1, 2}});
  const GrassfireResult r = extended_grassfire(g);
  CHECK(exact_value(r, 0) == 1);
  CHECK(exact_value(r, 1) == 1);
  REQUIRE(r.ema.size() == 1);
  const ExtendedMedialAxis& ema = r.ema[0];
  REQUIRE(ema.kind == ExtendedMedialAxis::Kind::Point);
  CHECK_FALSE(ema.point.at_node);
  CHECK(exact_ema_offset(r, ema) == 1);
  CHECK(exact_ema_edf(r, ema) == 2);
}

TEST_CASE("a star: the second arrival burns the centre, the quench lies on the long edge", "[grassfire]") {
  // centre 0 (R = 1); leaves 1 (R 0, w 10), 2 (R 1, w 1), 3 (R 2, w 1).
  const MedialGraph g = integer_graph({1, 0, 1, 2}, {{0, 1, 10}, {0, 2, 1}, {0, 3, 1}});
  const GrassfireResult r = extended_grassfire(g);
  CHECK(exact_value(r, 0) == 3);
  const ExtendedMedialAxis& ema = r.ema.at(0);
  REQUIRE_FALSE(ema.point.at_node);
  CHECK(ema.point.edge == 0);
  CHECK(ema.point.from == 1);
  CHECK(exact_ema_offset(r, ema) == mpq_class(13, 2));
  CHECK(exact_ema_edf(r, ema) == mpq_class(13, 2));
  // ignite x3, one annihilation at the centre (leaf 2's front), one quench.
  std::vector<BurnEventType> types;
  for (const BurnEvent& e : r.events) types.push_back(e.type);
  CHECK(types == std::vector<BurnEventType>{BurnEventType::Ignite, BurnEventType::Ignite, BurnEventType::Ignite,
                                            BurnEventType::Annihilate, BurnEventType::Quench});
  CHECK(r.events[3].place.node == 0);
  CHECK(r.events[3].time.contains(2));
}

TEST_CASE("fronts meeting exactly at a node quench on the node", "[grassfire]") {
  const MedialGraph g = integer_graph({1, 0, 0}, {{0, 1, 1}, {0, 2, 1}});
  const GrassfireResult r = extended_grassfire(g);
  const ExtendedMedialAxis& ema = r.ema.at(0);
  REQUIRE(ema.point.at_node);
  CHECK(ema.point.node == 0);
  CHECK(exact_value(r, 0) == 1);
}

TEST_CASE("a symmetric cross quenches at its centre with two annihilations", "[grassfire]") {
  const MedialGraph g = integer_graph({1, 0, 0, 0, 0}, {{0, 1, 1}, {0, 2, 1}, {0, 3, 1}, {0, 4, 1}});
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.at(0).point.at_node);
  CHECK(r.ema[0].point.node == 0);
  int annihilations = 0;
  for (const BurnEvent& e : r.events) annihilations += e.type == BurnEventType::Annihilate;
  CHECK(annihilations == 2);
  CHECK(r.queue_ties > 0);
}

TEST_CASE("cycles never burn and are the extended medial axis", "[grassfire]") {
  // triangle 0-1-2 with a pendant path 2-3-4.
  const MedialGraph g =
      integer_graph({2, 2, 2, 1, 0}, {{0, 1, 1}, {1, 2, 1}, {2, 0, 1}, {2, 3, 1}, {3, 4, 1}});
  const GrassfireResult r = extended_grassfire(g);
  for (std::uint32_t v : {0u, 1u, 2u}) CHECK(r.is_infinite(v));
  CHECK(exact_value(r, 3) == 1);
  CHECK(exact_value(r, 4) == 0);
  const ExtendedMedialAxis& ema = r.ema.at(0);
  REQUIRE(ema.kind == ExtendedMedialAxis::Kind::Cycles);
  CHECK(ema.nodes == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(ema.edges == std::vector<std::uint32_t>{0, 1, 2});
  for (const BurnEvent& e : r.events) CHECK(e.type != BurnEventType::Quench);
}

TEST_CASE("an isolated node is its own extended medial axis", "[grassfire]") {
  const MedialGraph g = integer_graph({5}, {});
  const GrassfireResult r = extended_grassfire(g);
  CHECK(exact_value(r, 0) == 5);
  REQUIRE(r.ema.at(0).point.at_node);
}

TEST_CASE("square-root lengths: a symmetric Y quenches exactly at its junction", "[grassfire]") {
  // Junction at the origin, leaves at (3,4), (-3,4), (0,-5), all R = 0: lengths 5 = sqrt(25)
  // on two arms and sqrt(25) on the third, written as square roots of different forms.
  std::vector<ExactSum> radii{ExactSum::sqrt_of(4), ExactSum::rational(0), ExactSum::rational(0),
                              ExactSum::rational(0)};
  std::vector<ExactSum> lengths{ExactSum::sqrt_of(25), ExactSum::sqrt_of(make_rational(100, 4)),
                                ExactSum::rational(5)};
  const MedialGraph g = MedialGraph::from_exact({{0, 0}, {3, 4}, {-3, 4}, {0, -5}}, radii,
                                                {{0, 1}, {0, 2}, {0, 3}}, lengths);
  const GrassfireResult r = extended_grassfire(g);
  REQUIRE(r.ema.at(0).point.at_node);
  CHECK(r.ema[0].point.node == 0);
  CHECK(exact_value(r, 0) == 5);
}

TEST_CASE("the engine equals the definition on random trees and graphs with cycles", "[grassfire][oracle]") {
  int graphs = 0, with_cycles = 0, edge_quenches = 0;
  for (std::uint64_t seed = 0; seed < 1200; ++seed) {
    const SyntheticFamily family = seed % 2 ? SyntheticFamily::Geometric : SyntheticFamily::Integer;
    const std::uint32_t nodes = 1 + static_cast<std::uint32_t>(seed % 37);
    const std::uint32_t extra = (seed % 3 == 0) ? static_cast<std::uint32_t>(seed % 4) : 0;
    const MedialGraph g = random_medial_graph(seed, nodes, extra, family);
    g.validate();
    const GrassfireResult r = extended_grassfire(g);
    const DefinitionalEdf d = edf_by_definition(g);
    INFO("seed " << seed);
    require_equal_to_definition(g, r, d);
    for (std::size_t k = 1; k < r.events.size(); ++k)  // the log is in exact time order
      REQUIRE(compare(event_time(r, r.events[k - 1]), event_time(r, r.events[k]), g) <= 0);
    ++graphs;
    with_cycles += g.cycle_rank() > 0;
    for (const ExtendedMedialAxis& e : r.ema) edge_quenches += e.kind == ExtendedMedialAxis::Kind::Point && !e.point.at_node;
  }
  CHECK(graphs == 1200);
  CHECK(with_cycles > 200);
  CHECK(edge_quenches > 300);
}

namespace {

// g with edge e split into 1 + (e + seed) % 4 equal pieces by new degree-2 nodes (R = 1/2:
// R at a degree-2 node never enters a burn time), so long chains with exact ties inside
// them appear: the engine runs its queue over stops only (medial2/medial_chains.h).
MedialGraph subdivided(const MedialGraph& g, std::uint64_t seed) {
  std::vector<Point2> positions;
  std::vector<ExactSum> radii;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    positions.push_back(g.node(v).position);
    radii.push_back(g.geometry().exact_radius(v));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  std::vector<ExactSum> lengths;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::uint32_t pieces = 1 + static_cast<std::uint32_t>((e + seed) % 4);
    ExactSum piece = g.geometry().exact_length(e);
    piece.scale(mpq_class(1, pieces));
    std::uint32_t from = g.edge(e).u;
    const Point2 a = g.node(g.edge(e).u).position, b = g.node(g.edge(e).v).position;
    for (std::uint32_t k = 1; k <= pieces; ++k) {
      std::uint32_t to = g.edge(e).v;
      if (k < pieces) {
        to = static_cast<std::uint32_t>(positions.size());
        const double t = static_cast<double>(k) / pieces;
        positions.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        radii.push_back(ExactSum::rational(mpq_class(1, 2)));
      }
      ends.emplace_back(from, to);
      lengths.push_back(piece);
      from = to;
    }
  }
  return MedialGraph::from_exact(std::move(positions), std::move(radii), std::move(ends), std::move(lengths));
}

}  // namespace

TEST_CASE("chains of degree-2 nodes: subdividing edges changes no EDF and engine = definition", "[grassfire][oracle]") {
  int graphs = 0, chain_quenches = 0;
  for (std::uint64_t seed = 0; seed < 400; ++seed) {
    const SyntheticFamily family = seed % 2 ? SyntheticFamily::Geometric : SyntheticFamily::Integer;
    const MedialGraph g = random_medial_graph(seed, 2 + static_cast<std::uint32_t>(seed % 23),
                                              seed % 5 == 0 ? 1 : 0, family);
    const MedialGraph h = subdivided(g, seed);
    h.validate();
    const GrassfireResult rg = extended_grassfire(g), rh = extended_grassfire(h);
    INFO("seed " << seed);
    require_equal_to_definition(h, rh, edf_by_definition(h));
    for (std::uint32_t v = 0; v < g.node_count(); ++v) {
      REQUIRE(rg.is_infinite(v) == rh.is_infinite(v));
      if (!rg.is_infinite(v)) REQUIRE(sign(rg.times.exact(rg.burn[v]) - rh.times.exact(rh.burn[v])) == 0);
    }
    for (std::size_t k = 1; k < rh.events.size(); ++k)
      REQUIRE(compare(event_time(rh, rh.events[k - 1]), event_time(rh, rh.events[k]), h) <= 0);
    for (const ExtendedMedialAxis& e : rh.ema)
      chain_quenches += e.kind == ExtendedMedialAxis::Kind::Point &&
                        (e.point.at_node ? h.degree(e.point.node) == 2 : true);
    ++graphs;
  }
  CHECK(graphs == 400);
  CHECK(chain_quenches > 100);
}
