// The exact engine as a BurningField (burn3/exact/exact_burning_field.h; docs/exact-engine.md): samples
// are the engine's certified enclosures, paths are geodesics from where the fire started
// (BT = f(end) + length, the length and f computed here independently), the discrete
// baseline lies above (gap shrinking in h), and medial curves from the exact field keep
// the axis' Betti numbers.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>

#include "curves3/burning_paths.h"
#include "burn3/discrete/discrete_burning_field.h"
#include "burn3/exact/exact_burning_field.h"
#include "curves3/medial_curves.h"
#include "complex3/synthetic_complexes.h"
#include "complex3/synthetic_tubes.h"
#include "geometry3/vec3.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

struct ExactRun {
  std::unique_ptr<MedialComplex> mc;
  std::unique_ptr<ExactBurning> eb;
  std::unique_ptr<ExactBurningField> field;
  explicit ExactRun(const RawComplex& raw, double spacing = 0.25) {
    mc = std::make_unique<MedialComplex>(raw);
    mc->validate();
    eb = std::make_unique<ExactBurning>(*mc);
    eb->add_border_ignition();
    eb->run();
    field = std::make_unique<ExactBurningField>(*eb, spacing);
  }
};

// f at a point y of the igniting border, computed from the rules directly: the least over
// the igniting border edges within 1e-9 of y (Linear: R interpolated; DistanceToPoint:
// |y - p|); +infinity when y is on none.
double border_ignition_at(const MedialComplex& mc, const Vec3d& y) {
  double best = std::numeric_limits<double>::infinity();
  for (const ComplexEdge& e : mc.edges()) {
    if (e.stratum != EdgeStratum::Border || e.rule == IgnitionRule::Never) continue;
    const Vec3d a = mc.vertex(e.v[0]).approx, b = mc.vertex(e.v[1]).approx, ab = v3::sub(b, a);
    const double s = std::clamp(v3::dot(v3::sub(y, a), ab) / v3::dot(ab, ab), 0.0, 1.0);
    if (v3::dist(y, v3::lerp(a, b, s)) > 1e-9) continue;
    const double f = e.rule == IgnitionRule::Linear
                         ? (1 - s) * mc.vertex(e.v[0]).radius + s * mc.vertex(e.v[1]).radius
                         : v3::dist(y, e.rule_point_approx);
    best = std::min(best, f);
  }
  return best;
}

// Random exact points (denominator 64) of random triangles.
std::vector<std::pair<std::uint32_t, ExactPoint3>> sample_points(const MedialComplex& mc, int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::pair<std::uint32_t, ExactPoint3>> r;
  for (int i = 0; i < count; ++i) {
    const auto t = static_cast<std::uint32_t>(rng() % mc.triangle_count());
    r.emplace_back(t, sample_triangle(mc, t, 1, rng).front());
  }
  return r;
}

// The manifold corpus (Definition 9 today) and the board and fin with its wall.
std::vector<std::pair<std::string, RawComplex>> field_corpus() {
  return {{"grid sheet with holes", grid_sheet(4, 3, 2, {{2, 2}, {5, 3}}, IgnitionRule::Linear)},
          {"tube", tube({8, 4, 2, 6})},
          {"board-fin", board_fin({8, 1})}};
}

}  // namespace

TEST_CASE("exact field samples are the engine's enclosures, paths carry BT as f(end) + length", "[exact3][paths]") {
  for (const auto& [name, raw] : field_corpus()) {
    CAPTURE(name);
    const ExactRun r(raw);
    CHECK(r.field->resolution() == 0.0);
    CHECK(r.field->definition9() == !exact_engine_unsupported(*r.mc));
    std::size_t finite = 0;
    for (const auto& [t, x] : sample_points(*r.mc, 150, 7)) {
      const Interval bt = r.eb->burn_time(t, x);
      const FieldSample s = r.field->sample_in_triangle(t, to_vec(x));
      if (bt.is_infinite()) {
        CHECK(std::isinf(s.bt));
        continue;
      }
      ++finite;
      CHECK(encloses(bt, s.bt, 1e-12));
      const std::vector<Vec3d> path = r.field->path_in_triangle(t, to_vec(x));
      REQUIRE(path.size() >= 1);
      double length = 0;
      for (std::size_t i = 1; i < path.size(); ++i) length += std::hypot(path[i][0] - path[i - 1][0],
                                                                         std::hypot(path[i][1] - path[i - 1][1],
                                                                                    path[i][2] - path[i - 1][2]));
      const double f = border_ignition_at(*r.mc, path.back());
      CAPTURE(t, s.bt, length, f, path.size());
      CHECK(std::isfinite(f));                        // the path ends on the igniting border
      CHECK(s.bt == Catch::Detail::Approx(f + length).margin(1e-9));  // and BT_t falls at unit rate along it
      if (!s.started) {
        REQUIRE(path.size() >= 2);
        CHECK(v3::norm(s.direction) == Catch::Detail::Approx(1.0));
        // The last straight piece runs from path[1] to p, through `from` (where it enters t).
        CHECK(v3::dist(v3::unit(v3::sub(path[0], path[1])), s.direction) < 1e-9);
        const double through = v3::dist(path[1], s.from) + v3::dist(s.from, path[0]) - v3::dist(path[1], path[0]);
        CHECK(std::fabs(through) < 1e-9);
      }
    }
    CHECK(finite > 100);
  }
}

TEST_CASE("exact field at vertices and edge points: the engine's values, paths from the border", "[exact3][paths]") {
  const ExactRun r(tube({8, 4, 2, 6}), 0.3);
  std::size_t checked = 0;
  for (const BurningPath& p : paths_from_vertices(*r.field)) {
    if (!std::isfinite(p.bt)) continue;
    ++checked;
    CHECK(p.bt == Catch::Detail::Approx(border_ignition_at(*r.mc, p.points.back()) + p.length).margin(1e-9));
  }
  CHECK(checked == r.mc->vertex_count());
  for (std::uint32_t e = 0; e < r.mc->edge_count(); e += 7)
    for (std::uint32_t i = 1; i <= r.field->edge_points(e); ++i) {
      const double bt = r.field->edge_point_burn_time(e, i);
      CHECK(encloses(r.eb->burn_time(r.field->edge_complex_point(e, i)), bt));
      const std::vector<Vec3d> path = r.field->path_from_edge_point(e, i);
      CHECK(bt == Catch::Detail::Approx(border_ignition_at(*r.mc, path.back()) + polyline_length(path)).margin(1e-9));
    }
}

TEST_CASE("the discrete field is an upper bound of the exact field, the gap shrinking in h", "[exact3][paths]") {
  const ExactRun r(grid_sheet(4, 3, 2, {{2, 2}, {5, 3}}, IgnitionRule::Linear));
  std::vector<double> gaps;
  for (double h : {0.2, 0.1, 0.05}) {
    const DiscreteBurning d = burn_discrete(*r.mc, {h});
    const DiscreteBurningField discrete(*r.mc, d);
    double gap = 0;
    for (const auto& [t, x] : sample_points(*r.mc, 200, 11)) {
      const double exact = r.field->sample_in_triangle(t, to_vec(x)).bt;
      const double upper = discrete.sample_in_triangle(t, to_vec(x)).bt;
      CHECK(upper >= exact - 1e-9);
      gap = std::max(gap, upper - exact);
    }
    CAPTURE(h, gap);
    CHECK(gap <= 2 * h);
    gaps.push_back(gap);
  }
  CHECK(gaps[1] < gaps[0]);
  CHECK(gaps[2] < gaps[1]);
}

TEST_CASE("medial curves from the exact field have the axis' b0 and b1", "[exact3][curves]") {
  const std::vector<std::pair<std::string, RawComplex>> cases = {
      {"tube (b1 = 1)", tube({8, 4, 2, 6})},
      {"grid sheet with two holes (b1 = 2)", grid_sheet(4, 3, 2, {{2, 2}, {5, 3}}, IgnitionRule::Linear)},
      {"board-fin", board_fin({8, 1})},
      {"y-junction (walls)", y_junction(1)}};
  for (const auto& [name, raw] : cases) {
    CAPTURE(name);
    const ExactRun r(raw, 0.25);
    const MedialCurves curves = medial_curves(*r.field);
    REQUIRE_NOTHROW(curves.validate(*r.mc));
    CHECK(curves.curve_betti.b0 == curves.axis_betti.b0);
    CHECK(curves.curve_betti.b1 == curves.axis_betti.b1);
    CHECK(curves.stats.residual_triangles == 0);
    CHECK(curves.method == r.field->method());
  }
}

TEST_CASE("exact field on segments: the 2D rule's paths through the link-rule centre of a Y", "[exact3][paths]") {
  // Leaves at distance 3 with R = 1, 2, 4 (test_burn3_exact_corpus.cpp): the centre burns at
  // 5 by its second arrival, the fire from the leaf with R = 2; the third branch's point at
  // distance 1/2 from the centre burns at 5.5 through the centre, the one at distance 2 at 5
  // from its own leaf (R = 4, 1 away).
  ComplexBuilder b("Y graph");
  const std::uint32_t c = b.vertex({0, 0, 0}, 16);
  const std::uint32_t l1 = b.vertex({3, 0, 0}, 1), l2 = b.vertex({0, 3, 0}, 4), l3 = b.vertex({0, 0, 3}, 16);
  b.segment(c, l1), b.segment(c, l2), b.segment(c, l3);
  const ExactRun r(b.raw(), 0.5);
  const std::vector<Vec3d> centre = r.field->path_from_vertex(c);
  REQUIRE(centre.size() == 2);
  CHECK(v3::dist(centre.back(), r.mc->vertex(l2).approx) == 0.0);  // back along the leaf with R = 2
  CHECK(r.field->vertex_burn_time(c) == Catch::Detail::Approx(5.0).margin(1e-12));
  const std::uint32_t e3 = r.mc->find_edge(c, l3);
  const bool from_centre = r.mc->edge(e3).v[0] == c;
  for (const double s : {1.0 / 6, 2.0 / 3}) {
    const double at = from_centre ? s : 1 - s;  // s: the distance from the centre / 3
    const FieldSample x = r.field->sample_on_segment(e3, at);
    const std::vector<Vec3d> path = r.field->path_on_segment(e3, at);
    const double f = std::sqrt(r.mc->vertex(path.size() == 2 ? l3 : l2).radius_squared.get_d());
    CAPTURE(s, x.bt, path.size());
    CHECK(x.bt == Catch::Detail::Approx(std::min(5 + 3 * s, 4 + 3 * (1 - s))).margin(1e-12));
    CHECK(x.bt == Catch::Detail::Approx(f + polyline_length(path)).margin(1e-12));
    CHECK(path.size() == (s < 0.5 ? 3u : 2u));  // through the centre, or straight from l3
  }
}
