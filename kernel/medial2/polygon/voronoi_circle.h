// voronoi_circle.h -- the empty circle at a Voronoi vertex of point and segment sites:
// centre and radius R, from the defining sites (2.1.1; docs/exactness.md).
//
// Computes, for three sites given counter-clockwise around the vertex, the circle
// tangent to the three (through a point site, touching a segment's line on the
// polygon's interior side). Kinds: PPP (circumcircle, rational centre, R = sqrt of a
// rational), PPS (centre in Q(sqrt D), R a sum of two square roots), PSS (centre on the
// bisector of two lines: in general a nested radical), PSS with parallel lines (a strip),
// SSS (incircle of three lines: a multiquadratic number). Where two circles fit the
// sites (PPS, PSS), the one whose tangency points run counter-clockwise in the sites'
// order is chosen, by exact signs of rationals (PPS) or of one cross product (PSS)
// (a PSS circle whose point lies on one of its lines is unique and has a linear formula):
// for PSS with lines L1, L2 after the point, the smaller circle is the right one exactly
// when cross(n1, n2) > 0 (the tangency points then run L1, L2, P counter-clockwise).
// One formula, four number types: double intervals (fast filter), double-double balls
// (when the intervals lose too much to cancellation), Arb balls (any precision), and
// exact sums of square roots (nullopt where the value is a nested
// radical that does not denest; solve_radical then writes it with square roots of sums).
// Contract: the sites come from a validated polygon and define a Voronoi vertex.
// Complexity: O(1) arithmetic per circle.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "medial2/polygon/segment_voronoi.h"
#include "number/ball.h"
#include "number/dd_ball.h"
#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

enum class CircleKind : std::uint8_t { Apex, PPP, PPS, PPSLinear, PSS, PSSParallel, SSS };
const char* to_string(CircleKind kind);

struct VoronoiCircle {
  CircleKind kind = CircleKind::Apex;
  // Roles: Apex (p); PPP (P1, P2, P3); PPS (P, Q, L); PSS (P, L1, L2); SSS (L1, L2, L3).
  std::array<std::uint32_t, 3> sites{};
  std::int8_t root = 1;  // PPS: sign of the root term; PSS: -1 smaller, +1 larger circle
  // PSS whose point lies on the line of L1 (1) or L2 (2), e.g. a reflex vertex and one of
  // its own segments: the circle touches that line at P, so R is linear (solve_pss_tangent
  // in voronoi_circle.cpp) and the circle lies in Q(sqrt N1, sqrt N2), never nested.
  std::uint8_t tangent = 0;
  // PPS (not linear) whose P (1) or Q (2) lies on L's line: the discriminant is exactly 0
  // (one circle, touching L there), and the enclosures use the linear formula of that
  // circle (solve_pps in voronoi_circle.cpp; the exact forms keep the general one).
};

VoronoiCircle classify_circle(const PolygonSites& sites, const VoronoiTopology::Vertex& vertex);
// A string naming the circle by its sites and root: equal strings, equal circles.
std::string identity(const VoronoiCircle& c);

template <class T>
struct CircleValue {
  T x, y, r;
};

// At most one circle with R > 0 satisfies c's conditions (through its point sites, at
// signed distance R from its segment sites' lines): PPP (circumcircle), SSS and PPS-linear
// (linear systems), or a point site P on the line of one of c's segment sites (then the
// circle touches that line at P, its centre is P + R n, and the remaining condition is
// linear in R; for PSS-parallel only when the two lines are anti-parallel). PPS, PSS and
// PSS-parallel circles otherwise have two solutions: c and the other root.
bool at_most_one_circle(const PolygonSites& sites, const VoronoiCircle& c);

CircleValue<Interval> solve_interval(const PolygonSites& sites, const VoronoiCircle& c);
CircleValue<Ball> solve_ball(const PolygonSites& sites, const VoronoiCircle& c);
// In double-double balls (number/dd_ball.h): the stage between intervals and Arb.
CircleValue<DDBall> solve_dd(const PolygonSites& sites, const VoronoiCircle& c);
std::optional<CircleValue<ExactSum>> solve_exact(const PolygonSites& sites, const VoronoiCircle& c);
// solve_exact, or for a PSS circle that is a nested radical its exact form with square roots
// of sums of square roots as constants (number/sqrt_field.h: sqrt_term, multiply_radical),
// which number/root_separation.h compares exactly; nullopt when even that form fails.
std::optional<CircleValue<ExactSum>> solve_radical(const PolygonSites& sites, const VoronoiCircle& c);

}  // namespace grassfire
