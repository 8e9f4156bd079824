// apps2d/axis_correspondence.h: nearest points between axes and the EDF comparison that the
// sampling convergence study reports, checked against closed forms on the rectangle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "apps2d/axis_correspondence.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"

using namespace grassfire;

namespace {

struct Seg {
  Point2 a, b;
};

double seg_distance(const Seg& s, const Point2& q, double* t_out = nullptr) {
  const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  double t = ((q.x - s.a.x) * dx + (q.y - s.a.y) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, 0.0, 1.0);
  if (t_out) *t_out = t;
  return std::hypot(q.x - (s.a.x + t * dx), q.y - (s.a.y + t * dy));
}

// The 10 x 4 rectangle: central segment (2,2)-(8,2), four diagonals from the corners.
// Closed-form EDF (3.1.2): t on a diagonal at distance t from its corner (fire from the
// corner, R = 0 there); 2 sqrt 2 + min(x - 2, 8 - x) on the central segment.
double closed_form_edf_at_nearest(const Point2& q) {
  const Seg diagonals[] = {{{0, 0}, {2, 2}}, {{10, 0}, {8, 2}}, {{10, 4}, {8, 2}}, {{0, 4}, {2, 2}}};
  const Seg centre{{2, 2}, {8, 2}};
  double t = 0, best = seg_distance(centre, q, &t);
  const double x = 2 + 6 * t;
  double edf = 2 * std::sqrt(2.0) + std::min(x - 2, 8 - x);
  for (const Seg& d : diagonals) {
    double td = 0;
    const double dist = seg_distance(d, q, &td);
    if (dist < best) best = dist, edf = td * 2 * std::sqrt(2.0);
  }
  return edf;
}

}  // namespace

TEST_CASE("exact rectangle axis: EDF equals the closed form at the nodes", "[apps2d]") {
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(builtin_shape("rectangle"), o);
  const MedialGraph& g = *r.graph;
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    CHECK(r.burning->edf(v).mid() == Approx(closed_form_edf_at_nearest(g.node(v).position)).margin(1e-12));
  Point2 ema;
  REQUIRE(ema_position(g, *r.burning, &ema));
  CHECK(ema.x == Approx(5).margin(1e-12));
  CHECK(ema.y == Approx(2).margin(1e-12));
}

TEST_CASE("convergence error on the rectangle equals the closed-form computation", "[apps2d]") {
  const Shape2 shape = builtin_shape("rectangle");
  const double diameter = shape_diameter(shape);
  CHECK(diameter == Approx(std::sqrt(116.0)).epsilon(1e-15));
  Edf2dOptions exact_opt;
  exact_opt.axis = AxisMethod::ExactPolygon;
  const Edf2dResult exact = compute_edf2d(shape, exact_opt);
  for (std::size_t n : {64, 200, 500}) {
    Edf2dOptions o;
    o.samples = n;
    const Edf2dResult s = compute_edf2d(shape, o);
    const AxisComparison c = compare_axes(*s.graph, *s.burning, *exact.graph, *exact.burning, diameter, 0.01);
    double max_err = 0, sum = 0;
    for (std::uint32_t v = 0; v < s.graph->node_count(); ++v) {
      const double e = std::abs(s.burning->edf(v).mid() - closed_form_edf_at_nearest(s.graph->node(v).position));
      max_err = std::max(max_err, e / diameter);
      sum += e / diameter;
    }
    CHECK(c.nodes == s.graph->node_count());
    CHECK(c.infinite == 0);
    CHECK(c.max_edf_error == Approx(max_err).margin(1e-12));
    CHECK(c.mean_edf_error == Approx(sum / s.graph->node_count()).margin(1e-12));
    Point2 e;
    REQUIRE(ema_position(*s.graph, *s.burning, &e));
    CHECK(c.ema_distance == Approx(std::hypot(e.x - 5, e.y - 2) / diameter).margin(1e-12));
    CHECK(c.hausdorff >= c.max_node_offset);
    CHECK(c.max_edf_error > 0);  // the sampled axis does not reach the corners
    INFO("n = " << n << ": max " << c.max_edf_error << ", mean " << c.mean_edf_error);
    CHECK(c.max_edf_error * diameter < 28.0 / n);  // within one sample spacing (28 / n)
  }
}

TEST_CASE("the axis locator finds the nearest point that brute force finds", "[apps2d]") {
  const Shape2 shape = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/key-1.json");
  Edf2dOptions o;
  o.samples = 600;
  const Edf2dResult r = compute_edf2d(shape, o);
  const MedialGraph& g = *r.graph;
  const AxisLocator locator(g, 0.01);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  for (int k = 0; k < 400; ++k) {
    const Point2 q{u(rng), u(rng)};
    double best = std::numeric_limits<double>::infinity();
    for (const MedialEdge& e : g.edges()) best = std::min(best, seg_distance({g.node(e.u).position, g.node(e.v).position}, q));
    const AxisPoint p = locator.nearest(q);
    CHECK(p.distance == Approx(best).margin(1e-14));
    CHECK(std::hypot(p.position.x - q.x, p.position.y - q.y) == Approx(p.distance).margin(1e-14));
  }
}

TEST_CASE("exact polygon axis: the locator follows parabolic arcs", "[apps2d]") {
  const Shape2 shape = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/children-1.json");
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(shape, o);
  const MedialGraph& g = *r.graph;
  const double h = 0.001;
  const AxisLocator locator(g, h);
  std::size_t arcs = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (g.edge(e).kind != EdgeKind::ParabolicArc) continue;
    ++arcs;
    const std::uint32_t u = g.edge(e).u;
    const double len = g.edge(e).length.mid();
    const auto k = static_cast<int>(std::ceil(len / h));
    // The chords the locator uses (axis_correspondence.h) and their largest sagitta,
    // measured at the middle of each piece of arc.
    double sagitta = 0;
    for (int i = 0; i < k; ++i) {
      const Point2 a = g.geometry().point_along(g, e, u, len * i / k), b = g.geometry().point_along(g, e, u, len * (i + 1) / k);
      const Point2 m = g.geometry().point_along(g, e, u, len * (i + 0.5) / k);
      sagitta = std::max(sagitta, seg_distance({a, b}, m));
    }
    // A point of the arc itself is found within the sagitta, at about its own arc length.
    const double s = 0.37 * len;
    const AxisPoint p = locator.nearest(g.geometry().point_along(g, e, u, s));
    CHECK(p.distance <= sagitta + 1e-12);
    if (p.edge == e) CHECK(std::abs(p.s - s) <= len / k);
  }
  CHECK(arcs > 0);
}
