// The state of the extended grassfire at a time t (burn2/burning_state.h): exact front
// positions on hand-built graphs, and invariants on seeded random graphs (the burnt length
// grows with t, fronts sit where the EDF equals t, everything finite burns, the events up
// to t are exactly those whose exact time is at most t).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>

#include "burn2/burning_state.h"
#include "medial2/synthetic_graphs.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// Fronts as (edge, from, exact offset), checked exactly: t - exact(sent) == offset.
void require_fronts(const GrassfireResult& r, const BurningState& s,
                    const std::vector<std::tuple<std::uint32_t, std::uint32_t, mpq_class>>& expected) {
  REQUIRE(s.fronts.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& [edge, from, offset] = expected[i];
    const FireFront& f = s.fronts[i];
    CHECK(f.edge == edge);
    CHECK(f.from == from);
    ExactSum d = ExactSum::rational(mpq_class(s.time)) - r.times.exact(f.sent) - ExactSum::rational(offset);
    CHECK(sign(d) == 0);
    CHECK(f.offset.contains(offset.get_d()));
  }
}

std::size_t count_burnt(const std::vector<bool>& v) {
  return static_cast<std::size_t>(std::count(v.begin(), v.end(), true));
}

// The largest finite time of the burning: node EDFs, EMA points, and fronts running into
// the 2-core (they reach it at their send time plus the edge length).
double last_finite_time(const MedialGraph& g, const GrassfireResult& r) {
  double t = 0;
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (!r.is_infinite(v)) t = std::max(t, r.edf(v).hi);
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    for (TimeId sent : {r.fire[e].from_u, r.fire[e].from_v})
      if (sent != kNoTime) t = std::max(t, (r.times.approx(sent) + g.edge(e).length).hi);
  for (const ExtendedMedialAxis& e : r.ema)
    if (e.kind == ExtendedMedialAxis::Kind::Point) t = std::max(t, e.edf.hi);
  return t;
}

}  // namespace

TEST_CASE("burning state of a star: fronts, burnt parts and events at given times", "[svg2d][burning_state]") {
  // centre 0 (R 1); leaves 1 (R 0, w 10), 2 (R 1, w 1), 3 (R 2, w 1). Leaf 2's front
  // annihilates at the centre at 2, leaf 3's burns it at 3, the fronts on edge 0 quench
  // at 13/2 from leaf 1 at time 13/2.
  const MedialGraph g = integer_graph({1, 0, 1, 2}, {{0, 1, 10}, {0, 2, 1}, {0, 3, 1}});
  const GrassfireResult r = extended_grassfire(g);

  BurningState s = burning_state_at(g, r, 2.5);
  require_fronts(r, s, {{0, 1, mpq_class(5, 2)}, {2, 3, mpq_class(1, 2)}});
  CHECK(s.edges[1].whole);
  CHECK_FALSE(s.edges[0].whole);
  CHECK(s.burnt_length(g).contains(4.0));
  CHECK(s.node_burnt == std::vector<bool>{false, true, true, true});
  CHECK(s.events == std::vector<std::size_t>{0, 1, 2, 3});  // three ignitions, one annihilation

  // At exactly t = 2 leaf 2's front has arrived (annihilated) and leaf 3's starts.
  s = burning_state_at(g, r, 2.0);
  require_fronts(r, s, {{0, 1, mpq_class(2)}, {2, 3, mpq_class(0)}});
  CHECK(s.edges[1].whole);
  CHECK(s.events.size() == 4);

  s = burning_state_at(g, r, 4.0);
  require_fronts(r, s, {{0, 0, mpq_class(1)}, {0, 1, mpq_class(4)}});
  CHECK(s.burnt_length(g).contains(7.0));
  CHECK(s.node_burnt[0]);

  // At the quench time the fronts are gone and the whole tree is burnt.
  s = burning_state_at(g, r, 6.5);
  CHECK(s.fronts.empty());
  for (const EdgeBurning& e : s.edges) CHECK(e.whole);
  CHECK(s.burnt_length(g).contains(12.0));
  CHECK(s.events.size() == r.events.size());

  s = burning_state_at(g, r, -1.0);
  CHECK(s.fronts.empty());
  CHECK(s.events.empty());
  CHECK(s.burnt_length(g).contains(0.0));
}

TEST_CASE("burning state with a cycle: the 2-core never burns, fronts annihilate on it", "[svg2d][burning_state]") {
  // triangle 0-1-2 (R 2) with the pendant path 2-3-4 (R 1, 0): leaf 4 ignites at 0, node 3
  // burns at 1, the front reaches node 2 of the core at 2 and annihilates.
  const MedialGraph g = integer_graph({2, 2, 2, 1, 0}, {{0, 1, 1}, {1, 2, 1}, {2, 0, 1}, {2, 3, 1}, {3, 4, 1}});
  const GrassfireResult r = extended_grassfire(g);
  BurningState s = burning_state_at(g, r, 1.5);
  require_fronts(r, s, {{3, 3, mpq_class(1, 2)}});
  CHECK(s.burnt_length(g).contains(1.5));
  s = burning_state_at(g, r, 100.0);
  CHECK(s.fronts.empty());
  CHECK(s.edges[3].whole);
  CHECK(s.edges[4].whole);
  for (std::uint32_t e : {0u, 1u, 2u}) {
    CHECK_FALSE(s.edges[e].whole);
    CHECK(s.edges[e].from_u.hi == 0);
    CHECK(s.edges[e].from_v.hi == 0);
  }
  CHECK(s.node_burnt == std::vector<bool>{false, false, false, true, true});
  REQUIRE(s.events.size() == 2);
  CHECK(r.events[s.events[1]].type == BurnEventType::Annihilate);
  CHECK(burning_state_at(g, r, 1.999).events.size() == 1);
  CHECK(burning_state_at(g, r, 2.0).events.size() == 2);
}

TEST_CASE("burning state needs the exact variant and a finite time", "[svg2d][burning_state]") {
  const MedialGraph g = integer_graph({1, 1}, {{0, 1, 2}});
  const GrassfireResult d = extended_grassfire(g, GrassfireVariant::Dissertation);
  CHECK_THROWS_AS(burning_state_at(g, d, 1.0), std::invalid_argument);
  const GrassfireResult r = extended_grassfire(g);
  CHECK_THROWS_AS(burning_state_at(g, r, std::nan("")), std::invalid_argument);
}

TEST_CASE("burning state invariants on seeded random graphs", "[svg2d][burning_state]") {
  for (SyntheticFamily family : {SyntheticFamily::Integer, SyntheticFamily::Geometric}) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      const std::uint32_t extra = seed % 3 == 0 ? 2 : 0;
      const MedialGraph g = random_medial_graph(seed, 40, extra, family);
      const GrassfireResult r = extended_grassfire(g);
      const TwoCore core = two_core(g);
      const double end = last_finite_time(g, r);
      INFO("family " << static_cast<int>(family) << " seed " << seed);
      double previous_length = -1;
      std::size_t previous_nodes = 0, previous_events = 0;
      // Quarter steps: in the integer family every burn time is an integer and every
      // quench time a half-integer, so the integer and half-integer steps are exact ties.
      for (double t = -0.5; t <= end + 1; t += 0.25) {
        const BurningState s = burning_state_at(g, r, t);
        const double length = s.burnt_length(g).mid();
        CHECK(length >= previous_length);
        CHECK(count_burnt(s.node_burnt) >= previous_nodes);
        CHECK(s.events.size() >= previous_events);
        previous_length = length, previous_nodes = count_burnt(s.node_burnt), previous_events = s.events.size();
        for (const FireFront& f : s.fronts) {
          // The front is where the EDF along the edge equals t (EDF is 1-Lipschitz).
          const Interval edf = r.edf_along(f.edge, f.from, f.offset.mid());
          CHECK(edf.lo - f.offset.radius() <= t);
          CHECK(t <= edf.hi + f.offset.radius());
        }
        for (std::size_t i = 0; i < r.events.size(); ++i) {
          const Interval time = r.events[i].time;
          const bool listed = std::binary_search(s.events.begin(), s.events.end(), i);
          if (family == SyntheticFamily::Integer) {
            CHECK(listed == (std::round(2 * time.mid()) / 2 <= t));  // exact times are half-integers
          } else {
            if (time.hi < t) CHECK(listed);
            if (time.lo > t) CHECK_FALSE(listed);
          }
        }
      }
      const BurningState done = burning_state_at(g, r, end + 1);
      CHECK(done.fronts.empty());
      CHECK(done.events.size() == r.events.size());
      for (std::uint32_t v = 0; v < g.node_count(); ++v) CHECK(done.node_burnt[v] == !r.is_infinite(v));
      for (std::uint32_t e = 0; e < g.edge_count(); ++e) CHECK(done.edges[e].whole == !core.edge_in_core[e]);
    }
  }
}
