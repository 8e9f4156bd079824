// Pictures of scalars other than the burning's fields (render/svg_medial2.h: Medial2Scalar,
// potential_residue_scalar, draw_medial2_scalar, medial2_panel_frame): PR along the exact
// axis of the 10 x 4 rectangle against hand-derived values, PR constant on the edges of a
// sampled axis, a field drawn as a scalar equal to draw_medial2, and the panel frame.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "burn2/closest_points.h"
#include "burn2/potential_residue.h"
#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

struct Analysed {
  Shape2 shape;
  Edf2dResult axis;
  ClosestPoints cp;
  PotentialResidue pr;
};

Analysed analyse(const std::string& name, AxisMethod method) {
  Analysed a;
  a.shape = builtin_shape(name);
  Edf2dOptions o;
  o.axis = method;
  o.samples = 400;
  a.axis = compute_edf2d(a.shape, o);
  a.cp = closest_points(*a.axis.graph, &a.shape, &a.axis.samples);
  a.pr = potential_residue(*a.axis.graph, a.cp);
  return a;
}

// The edge of the rectangle's axis joining (2, 2) and (8, 2).
std::uint32_t central_edge(const MedialGraph& g) {
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const Point2 a = g.node(g.edge(e).u).position, b = g.node(g.edge(e).v).position;
    if (a.y == Approx(2) && b.y == Approx(2) && std::fabs(a.x - b.x) == Approx(6)) return e;
  }
  FAIL("no central edge");
  return 0;
}

}  // namespace

TEST_CASE("PR along the exact axis of the 10 x 4 rectangle: 2x + 4 up to L / 2 = 14 in the middle", "[svg2d_pr]") {
  // Perimeter 28. On the central edge the feet are (x, 0) and (x, 4): the boundary path
  // round the left side has length 2x + 4, round the right side 24 - 2x, so PR rises from
  // 8 at x = 2 to 14 at x = 5 (a peak) and falls to 8 at x = 8. On a corner's diagonal the
  // feet are (t, 0) and (0, t) (bottom-left corner): PR = 2t, from 0 to 4.
  const Analysed a = analyse("rectangle", AxisMethod::ExactPolygon);
  const MedialGraph& g = *a.axis.graph;
  REQUIRE(g.edge_count() == 5);
  const Medial2Scalar pr = potential_residue_scalar(g, a.cp, a.pr);
  CHECK(pr.name == "PR");
  const std::uint32_t mid = central_edge(g);
  const std::vector<double> cuts = pr.breakpoints(mid);
  REQUIRE(cuts.size() == 3);
  CHECK(cuts[0] == 0);
  CHECK(cuts[1] == Approx(3).epsilon(1e-12));
  CHECK(cuts[2] == Approx(6).epsilon(1e-12));
  // Symmetric about the middle, so the direction of the edge does not matter.
  CHECK(pr.along(mid, 0) == Approx(8).epsilon(1e-12));
  CHECK(pr.along(mid, 1.5) == Approx(11).epsilon(1e-12));
  CHECK(pr.along(mid, 3) == Approx(14).epsilon(1e-12));
  CHECK(pr.along(mid, 4.5) == Approx(11).epsilon(1e-12));
  CHECK(pr.along(mid, 6) == Approx(8).epsilon(1e-12));
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    if (e == mid) continue;
    CHECK(pr.breakpoints(e).size() == 2);
    const double w = g.edge(e).length.mid();
    CHECK(w == Approx(2 * std::sqrt(2.0)).epsilon(1e-12));
    const bool corner_at_u = g.degree(g.edge(e).u) == 1;
    const double at_corner = pr.along(e, corner_at_u ? 0 : w), inside = pr.along(e, corner_at_u ? w : 0);
    CHECK(at_corner == Approx(0).margin(1e-12));
    CHECK(inside == Approx(4).epsilon(1e-12));
    CHECK(pr.along(e, w / 2) == Approx(2).epsilon(1e-12));
  }
  const Medial2FieldRange range = medial2_scalar_range(g, pr);
  CHECK(range.lo == Approx(0).margin(1e-12));
  CHECK(range.hi == Approx(14).epsilon(1e-12));
  CHECK_FALSE(range.has_infinite);
}

TEST_CASE("PR drawn: one piece per linear part, the colour bar labelled PR from 0 to 14", "[svg2d_pr]") {
  const Analysed a = analyse("rectangle", AxisMethod::ExactPolygon);
  const MedialGraph& g = *a.axis.graph;
  Medial2SvgOptions o;
  o.max_piece = 1e9;
  o.axis_width = 3.3;
  SvgCanvas c(800, 400);
  const std::size_t pieces =
      draw_medial2_scalar(c, 0, 0, 800, 400, a.shape, g, *a.axis.burning, potential_residue_scalar(g, a.cp, a.pr), o);
  CHECK(pieces == 6);  // four diagonals, the central edge in two halves
  const std::string svg = c.str();
  CHECK(count(svg, "stroke-width=\"3.30\"") == 6);
  CHECK(count(svg, ">PR</text>") == 1);
  CHECK(count(svg, ">14</text>") == 1);
  CHECK(count(svg, ">EDF</text>") == 0);
  // Both halves of the central edge at PR 11 of 14; the diagonals at 2 of 14.
  CHECK(count(svg, "stroke=\"" + to_svg_color(heat_color(11.0 / 14)) + "\" stroke-width=\"3.30\"") == 2);
  CHECK(count(svg, "stroke=\"" + to_svg_color(heat_color(2.0 / 14)) + "\" stroke-width=\"3.30\"") == 4);
}

TEST_CASE("PR is constant along every edge of a sampled axis, and the scalar refuses another graph", "[svg2d_pr]") {
  const Analysed a = analyse("rectangle", AxisMethod::Sampled);
  const MedialGraph& g = *a.axis.graph;
  const Medial2Scalar pr = potential_residue_scalar(g, a.cp, a.pr);
  REQUIRE(g.edge_count() > 100);
  std::size_t constant = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::vector<double> cuts = pr.breakpoints(e);
    constant += cuts.size() == 2 && pr.along(e, cuts[0]) == pr.along(e, cuts[1]);
  }
  CHECK(constant == g.edge_count());
  // The largest PR of the sampled axis is about half the perimeter, 14.
  CHECK(medial2_scalar_range(g, pr).hi == Approx(14).epsilon(0.01));
  const Analysed exact = analyse("rectangle", AxisMethod::ExactPolygon);
  CHECK_THROWS_AS(potential_residue_scalar(g, exact.cp, exact.pr), std::invalid_argument);
}

TEST_CASE("a field drawn as a scalar is draw_medial2: the panel frame is the one drawn in", "[svg2d_pr]") {
  const Analysed a = analyse("rectangle", AxisMethod::ExactPolygon);
  const MedialGraph& g = *a.axis.graph;
  const GrassfireResult& r = *a.axis.burning;
  Medial2SvgOptions o;
  o.title = "rectangle";
  o.field = Medial2Field::Et;
  const Medial2FieldRange range = medial2_field_range(g, r, a.axis.measures, o.field);
  o.range_lo = range.lo, o.range_hi = range.hi;
  SvgCanvas by_field(700, 400), by_scalar(700, 400);
  draw_medial2(by_field, 0, 0, 700, 400, a.shape, g, r, a.axis.measures, o);
  draw_medial2_scalar(by_scalar, 0, 0, 700, 400, a.shape, g, r, medial2_field_scalar(g, r, o.field), o);
  CHECK(by_field.str() == by_scalar.str());
  // The shape's fill is drawn through the frame: its first corner (0, 0) lands where the
  // frame puts it.
  const Medial2Frame f = medial2_panel_frame(a.shape, o, 0, 0, 700, 400);
  SvgCanvas probe(700, 400);
  probe.polygon_outline(shape_polygon(f, a.shape), {0.92, 0.92, 0.92}, {0.92, 0.92, 0.92}, 0);
  const std::string fill = probe.str().substr(probe.str().find("<polygon"));
  CHECK(by_field.str().find(fill.substr(0, fill.find("/>"))) != std::string::npos);
  CHECK(f.scale() > 0);
  CHECK(f({10, 4})[0] - f({0, 4})[0] == Approx(10 * f.scale()));
}
