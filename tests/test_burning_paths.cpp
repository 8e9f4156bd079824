// Burning paths (burning_field.h, burning_paths.h) from the discrete baseline: they start
// on the border, BT = f(start) + length along them, and BT falls along the recorded
// predecessors; the field's samples agree with the baseline at its graph points.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "curves3/burning_paths.h"
#include "burn3/discrete/discrete_burning_field.h"
#include "burn3/point_sources.h"
#include "complex3/synthetic_complexes.h"
#include "complex3/synthetic_tubes.h"
#include "geometry3/vec3.h"
#include "test_complex3_support.h"

using namespace grassfire;
using testing::built;

namespace {

// Distance from p to the nearest igniting border edge of mc.
double to_border(const MedialComplex& mc, const Vec3d& p) {
  double best = 1e300;
  for (const ComplexEdge& e : mc.edges()) {
    if (e.stratum != EdgeStratum::Border || e.rule == IgnitionRule::Never) continue;
    const Vec3d a = mc.vertex(e.v[0]).approx, b = mc.vertex(e.v[1]).approx, ab = v3::sub(b, a);
    const double t = std::clamp(v3::dot(v3::sub(p, a), ab) / v3::dot(ab, ab), 0.0, 1.0);
    best = std::min(best, v3::dist(p, v3::lerp(a, b, t)));
  }
  return best;
}

}  // namespace

TEST_CASE("burning paths start on the border and carry BT as their length (R = 0)", "[paths]") {
  for (const RawComplex& raw : {board_fin({8, 1}), y_junction(1), tube({8, 4, 2, 6})}) {
    const MedialComplex mc = built(raw);
    const DiscreteBurning d = burn_discrete(mc, {0.25});
    const DiscreteBurningField field(mc, d);
    CAPTURE(mc.source());
    std::vector<BurningPath> paths = paths_from_vertices(field);
    std::mt19937 rng(12);
    std::vector<CellPoint> points;
    std::uniform_real_distribution<double> w(0, 1);
    for (int i = 0; i < 200; ++i) {
      const auto t = static_cast<std::uint32_t>(rng() % mc.triangle_count());
      double u = w(rng), v = w(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const auto& tv = mc.triangle(t).v;
      const Vec3d a = mc.vertex(tv[0]).approx;
      const Vec3d p = v3::add(a, v3::add(v3::scale(v3::sub(mc.vertex(tv[1]).approx, a), u),
                                         v3::scale(v3::sub(mc.vertex(tv[2]).approx, a), v)));
      points.push_back({CellPoint::Kind::Triangle, t, p, 0});
    }
    for (const BurningPath& p : paths_from_points(field, points)) paths.push_back(p);
    std::size_t checked = 0;
    for (const BurningPath& p : paths) {
      if (!std::isfinite(p.bt)) continue;  // the truncation's far corner may not burn
      ++checked;
      CHECK(p.bt == Approx(p.length).margin(1e-9));          // f = 0 on the border
      CHECK(to_border(mc, p.points.back()) <= 1e-9);        // started on the border
    }
    CHECK(checked > 200);
  }
}

TEST_CASE("recorded predecessors lead down to ignited points", "[paths]") {
  const MedialComplex mc = built(box_medial_axis(4, 3, 1, 2));
  const DiscreteBurning d = burn_discrete(mc, {0.2});
  const SteinerGraph g(mc, 0.2, 1'000'000);
  REQUIRE(d.burn_slot.size() == g.node_count());
  auto bt = [&](std::uint32_t n) { return g.is_vertex(n) ? d.vertex_bt[n] : d.steiner_bt[n - g.vertex_count()]; };
  std::size_t ignited = 0;
  for (std::uint32_t start = 0; start < g.node_count(); ++start) {
    std::uint32_t n = start;
    std::size_t steps = 0;
    while (d.burn_slot[n] != DiscreteBurning::kIgnited && steps <= g.node_count()) {
      REQUIRE(d.burn_slot[n] != kNoIndex);  // every point of the box axis burns
      const std::uint32_t from = d.arrival_from[g.slot(n, d.burn_slot[n])];
      REQUIRE(from != kNoIndex);
      CHECK(bt(from) <= bt(n));
      CHECK(bt(n) == Approx(bt(from) + v3::dist(g.position(n), g.position(from))).margin(1e-12));
      n = from;
      ++steps;
    }
    CHECK(steps <= g.node_count());
    ignited += steps == 0 ? 1 : 0;
  }
  CHECK(ignited > 0);
}

TEST_CASE("field samples are side times at graph points and 1-Lipschitz between them", "[paths]") {
  const MedialComplex mc = built(y_junction(1));
  const DiscreteBurning d = burn_discrete(mc, {0.25});
  const DiscreteBurningField field(mc, d);
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mc.triangle(t).v[c];
      const FieldSample s = field.sample_in_triangle(t, mc.vertex(v).approx);
      CHECK(s.bt <= d.vertex_bt[v]);  // the side time is at most BT (Prop. 6: a side limit)
      const double arrival = d.arrival_time[d.vertex_slot[v] + mc.corner_element(t, c)];
      CHECK(s.bt <= std::min(arrival, d.vertex_bt[v]));  // one more step can only shorten
    }
  // Inside a triangle: 1-Lipschitz between the sample and the corners.
  const std::uint32_t t = mc.triangle_count() / 2;
  const auto& tv = mc.triangle(t).v;
  const Vec3d centre = v3::scale(v3::add(mc.vertex(tv[0]).approx, v3::add(mc.vertex(tv[1]).approx, mc.vertex(tv[2]).approx)), 1.0 / 3);
  const FieldSample s = field.sample_in_triangle(t, centre);
  for (std::uint32_t v : tv) CHECK(std::abs(s.bt - d.vertex_bt[v]) <= v3::dist(centre, mc.vertex(v).approx) + 1e-12);
  CHECK(std::abs(v3::norm(s.direction) - 1) <= 1e-12);
}

TEST_CASE("burning paths from a point source end at the source", "[paths]") {
  // A square sheet whose border never ignites, lit at a point inside a triangle: BT is the
  // distance to the source and every path runs straight back to it.
  const MedialComplex mc = built(without_border_ignition(square_annulus({4, 2, 1})));
  const ComplexLocator locator(mc);
  const ExactPoint3 q{mpq_class(7, 2), mpq_class(3, 10), mpq_class(0)};
  DiscreteBurningOptions o;
  o.spacing = 0.25;
  o.sources.push_back({locator.locate(q), 0});
  REQUIRE(o.sources[0].location.kind == ComplexPoint::Kind::Triangle);
  const DiscreteBurning d = burn_discrete(mc, o);
  const DiscreteBurningField field(mc, d);
  std::size_t checked = 0;
  for (const BurningPath& p : paths_from_vertices(field)) {
    if (!std::isfinite(p.bt)) continue;
    ++checked;
    CHECK(v3::dist(p.points.back(), {3.5, 0.3, 0}) <= 1e-12);  // ends at the source
    CHECK(p.bt == Approx(p.length).margin(1e-9));                 // t0 = 0
  }
  CHECK(checked > 20);
}
