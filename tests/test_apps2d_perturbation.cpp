// apps2d/perturbation.h: seeded boundary perturbations for the stability study (3.4).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "apps2d/alignment.h"
#include "apps2d/perturbation.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"

using namespace grassfire;

namespace {

double distance_to_boundary(const Shape2& s, const Point2& q) {
  double best = std::numeric_limits<double>::infinity();
  for (const Ring& r : s.rings)
    for (std::size_t i = 0, n = r.points.size(); i < n; ++i) {
      const Point2 &a = r.points[i], &b = r.points[(i + 1) % n];
      const double dx = b.x - a.x, dy = b.y - a.y;
      const double t = std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      best = std::min(best, std::hypot(q.x - a.x - t * dx, q.y - a.y - t * dy));
    }
  return best;
}

// Points every `step` along every edge of the shape, vertices included.
std::vector<Point2> dense(const Shape2& s, double step) {
  std::vector<Point2> out;
  for (const Ring& r : s.rings)
    for (std::size_t i = 0, n = r.points.size(); i < n; ++i) {
      const Point2 &a = r.points[i], &b = r.points[(i + 1) % n];
      const int k = std::max(1, int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
      for (int j = 0; j < k; ++j) out.push_back({a.x + (b.x - a.x) * j / k, a.y + (b.y - a.y) * j / k});
    }
  return out;
}

double hausdorff(const Shape2& a, const Shape2& b, double step) {
  double h = 0;
  for (const Point2& p : dense(a, step)) h = std::max(h, distance_to_boundary(b, p));
  for (const Point2& p : dense(b, step)) h = std::max(h, distance_to_boundary(a, p));
  return h;
}

}  // namespace

TEST_CASE("perturbations are deterministic per seed", "[apps2d]") {
  const Shape2 key = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/key-1.json");
  PerturbationOptions o;
  o.amplitude = 0.004;
  o.spacing = 0.005;
  o.seed = 42;
  const PerturbedShape a = perturb_boundary(key, o), b = perturb_boundary(key, o);
  REQUIRE(a.shape.rings.size() == b.shape.rings.size());
  CHECK(a.shape.rings[0].points == b.shape.rings[0].points);
  CHECK(a.attempts == b.attempts);
  o.seed = 43;
  const PerturbedShape c = perturb_boundary(key, o);
  CHECK(c.shape.rings[0].points != a.shape.rings[0].points);
  CHECK(a.points > key.rings[0].points.size());
  CHECK(a.perturbed_points == a.points);
}

TEST_CASE("the amplitude bounds the Hausdorff distance to the original boundary", "[apps2d]") {
  const std::string dir = std::string(GF_PROJECT_DATA) + "/shapes2d/";
  // Amplitudes well below the thinnest limb of each shape (children's limbs are ~0.02 wide,
  // and noise of that size folds them whatever the seed).
  const std::vector<std::pair<const char*, std::vector<double>>> cases = {
      {"key-1.json", {0.001, 0.005, 0.02}}, {"children-2.json", {0.001, 0.004}}, {"Bone-1.json", {0.001, 0.01}}};
  for (const auto& [name, amplitudes] : cases) {
    const Shape2 s = load_shape(dir + name);
    for (double amp : amplitudes) {
      for (PerturbationKind kind : {PerturbationKind::Uniform, PerturbationKind::OneSided}) {
        PerturbationOptions o;
        o.kind = kind;
        o.amplitude = amp;
        o.spacing = 0.004;
        o.seed = 5;
        const PerturbedShape p = perturb_boundary(s, o);
        const double h = hausdorff(s, p.shape, 0.0005);
        CHECK(h <= amp);
        CHECK(h > 0.3 * amp);  // the noise does use its amplitude
        if (kind == PerturbationKind::OneSided) {
          CHECK(p.perturbed_points < p.points);
          CHECK(p.perturbed_points > 0);
          // Points on the unperturbed side stay on the old boundary up to the rounding.
          const Point2 c = bounding_box_centre(s);
          for (const Point2& q : p.shape.rings[0].points)
            if (q.x < c.x - amp) CHECK(distance_to_boundary(s, q) <= 1e-6);
        }
      }
    }
  }
}

TEST_CASE("perturbation of a square stays a valid shape with holes kept", "[apps2d]") {
  const Shape2 hole = builtin_shape("hole");
  PerturbationOptions o;
  o.amplitude = 0.05;
  o.spacing = 0.1;
  const PerturbedShape p = perturb_boundary(hole, o);
  CHECK(p.shape.rings.size() == hole.rings.size());
  CHECK(hausdorff(hole, p.shape, 0.01) <= 0.05);
}

TEST_CASE("perturbation rejects bad options", "[apps2d]") {
  const Shape2 r = builtin_shape("rectangle");
  PerturbationOptions o;
  o.spacing = 0.1;
  o.amplitude = 1e-7;  // below the rounding of 6 decimals
  CHECK_THROWS_AS(perturb_boundary(r, o), std::invalid_argument);
  o.amplitude = 0.1;
  o.spacing = 0;
  CHECK_THROWS_AS(perturb_boundary(r, o), std::invalid_argument);
  o.spacing = std::nan("");
  CHECK_THROWS_AS(perturb_boundary(r, o), std::invalid_argument);
  // Noise far above the spacing folds the boundary every time: a clear error, no shape.
  o.spacing = 0.01;
  o.amplitude = 1.0;
  o.max_attempts = 3;
  CHECK_THROWS_WITH(perturb_boundary(r, o), Catch::Contains("no valid perturbation"));
}
