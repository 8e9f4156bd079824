// Shape analysis (5.3): the planar / tubular split on a box axis against its closed form,
// the signature, and the burning mapped to the box's surface through the touching balls.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "burn3/discrete/discrete_burning_field.h"
#include "curves3/shape_analysis.h"
#include "complex3/synthetic_complexes.h"
#include "test_complex3_support.h"

using namespace grassfire;
using testing::built;

namespace {

// The box [-a, a] x [-b, b] x [-c, c]: BT on its medial axis (box_medial_axis, f = R = 0
// on the box edges): sqrt2 R on the trapezoids and triangles, and on the middle rectangle
// (R = c) sqrt2 c + the distance to the rectangle's border.
double box_rectangle_bt(double a, double b, double c, double x, double y) {
  return std::sqrt(2.0) * c + std::min(a - c - std::abs(x), b - c - std::abs(y));
}

}  // namespace

TEST_CASE("planar and tubular parts of a box axis: the rectangle's core is the sheet", "[shape]") {
  const double a = 8, b = 6, c = 1, h = 0.25;
  const MedialComplex mc = built(box_medial_axis(8, 6, 1, 2));
  const DiscreteBurning d = burn_discrete(mc, {h});
  const DiscreteBurningField field(mc, d);
  const AxisRefinement k = AxisRefinement::build(field);
  const MedialCurves curves = medial_curves(k, field);
  curves.validate(mc);
  const ShapeAnalysis s = analyze_shape(k, curves);
  // ST = 1 - R / BT >= 1/2 iff BT >= 2 R: on the rectangle at distance >= 2 - sqrt2 from its
  // border; nowhere on the trapezoids and triangles (ST = 1 - 1/sqrt2 there).
  const double inset = 2 - std::sqrt(2.0);
  const double expected = (2 * (a - c) - 2 * inset) * (2 * (b - c) - 2 * inset);
  CAPTURE(s.signature.planar_area, expected, s.signature.sheet_areas.size());
  CHECK(s.signature.planar_area == Approx(expected).epsilon(0.03));
  REQUIRE(!s.signature.sheet_areas.empty());
  CHECK(s.signature.sheet_areas[0] == Approx(s.signature.planar_area).epsilon(1e-9));  // one sheet
  double total = 0;
  for (std::uint32_t t = 0; t < k.triangles.size(); ++t) total += k.area(t);
  CHECK(s.signature.planar_area + s.signature.tubular_area == Approx(total).epsilon(1e-12));
  // The curves' corner segments (on trapezoids and triangles) are tubular; the middle
  // segment of the rectangle's medial axis is planar.
  CHECK(s.signature.tubular_curve_length > 8 * std::sqrt(2.0) * c * 0.9);
  CHECK(s.signature.planar_curve_length > 2 * (a - b) * 0.9);
  double branches = 0;
  for (double l : s.signature.curve_lengths) branches += l;
  CHECK(branches == Approx(s.signature.tubular_curve_length).epsilon(1e-12));
}

TEST_CASE("surface values: each surface point takes the burning of the ball that touches it", "[shape]") {
  const double a = 4, b = 3, c = 1, h = 0.2;
  const MedialComplex mc = built(box_medial_axis(4, 3, 1, 2));
  const DiscreteBurning d = burn_discrete(mc, {h});
  const DiscreteBurningField field(mc, d);
  const AxisRefinement k = AxisRefinement::build(field);
  std::vector<Vec3d> points;
  for (double x = -2.5; x <= 2.5; x += 0.5)
    for (double y = -1.5; y <= 1.5; y += 0.5) points.push_back({x, y, c});  // the top face over the rectangle
  const SurfaceValues v = map_to_surface(k, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    CAPTURE(points[i][0], points[i][1]);
    CHECK(std::abs(v.gap[i]) <= h);                // a ball of the axis touches the point
    CHECK(v.radius[i] == Approx(c).margin(h));    // the rectangle's ball
    CHECK(v.bt[i] == Approx(box_rectangle_bt(a, b, c, points[i][0], points[i][1])).margin(2 * h));
    CHECK(v.et[i] == Approx(v.bt[i] - v.radius[i]).margin(1e-12));
  }
}
