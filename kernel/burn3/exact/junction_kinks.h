// junction_kinks.h -- where along a singular edge two arrivals cross, and where a window's
// wedge ray meets the edge: the breakpoints of the junction rule (4.2.1, Fig. 4.4;
// docs/design.md 5a), located exactly where possible.
//
// Computes, for an edge E = v[0] v[1] and windows of triangles on E (parameter lambda along
// E, in each window's own frame, which contains E):
//  - approx_crossings: the parameters in (lo, hi) where two windows' times along E cross,
//    by sign changes on a fixed sample and bisection (kept only for the engine mutant
//    sampled_crossings, engine_mutant.h; the engine isolates crossings by edge_crossings.h);
//  - kink_parameter: one crossing located exactly. A window's time along E is
//    sigma + sqrt(gamma + 2 beta lambda + L2 lambda^2) (a point source) or c0 + c1 lambda (a
//    plane wave), so sigma1 + |x - s1| = sigma2 + |x - s2| becomes, after squaring twice, a
//    quadratic in lambda with coefficients in a multiquadratic field (number/
//    multiquadratic.h): its roots are lambda0 +- sqrt(delta) with lambda0, delta in the field
//    (the board-and-fin kink: lambda = sqrt2 - 1 on the edge from (3,3,0) to (4,4,0), i.e.
//    s = 2 + sqrt2). Squaring adds roots: the crossing is first bracketed by two rational
//    parameters at which Certifier::compare_times certifies opposite orders (bisected to
//    2^-100 of its width, or until no stage decides), and the exact
//    root is the only candidate between them (decided exactly). Without exact window data
//    (curved sheets, large expressions) the bracket is narrowed by certified bisection and
//    the enclosure is the answer (exact = none);
//  - ray_parameter: where the ray of a window through a vertex meets E (linear in lambda:
//    exact from exact window data, else a certified bisection on Certifier::side).
// `certified` is false when even the bracket could not be certified (then lambda is the
// double estimate as a point interval, and the caller counts an uncertified breakpoint).
// Contract: the windows' triangles contain E; `at` approximates the point sought.
// Complexity: O(1) field operations (at most 6 generators), or O(bits) certified comparisons.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "burn3/exact/window_certify.h"
#include "burn3/exact/window_values.h"

namespace grassfire {

// A window's time along the edge at parameter l, as an enclosure: the images A, B of the
// edge's ends in its frame taken once (A + l (B - A), the same operations per point).
struct EdgeImage {
  Interval ax, ay, dx, dy;
  EdgeImage() = default;
  EdgeImage(const Unfolding& u, const Window& W, std::uint32_t edge) {
    const auto& ev = u.complex().edge(edge).v;
    const DiscPoint A = u.vertex_image(W.triangle, ev[0]), B = u.vertex_image(W.triangle, ev[1]);
    ax = A.ix(), ay = A.iy(), dx = B.ix() - ax, dy = B.iy() - ay;
  }
  Interval time(const Window& W, double l) const {
    const Interval L(l);
    const Approx t = approx_time(W, DiscPoint::from_intervals(ax + L * dx, ay + L * dy));
    return {round_down(t.v - t.e), round_up(t.v + t.e)};
  }
};

struct KinkParameter {
  Interval lambda;
  std::optional<ExactSum> exact;
  bool certified = false;
  std::optional<std::array<mpq_class, 2>> bracket;  // certified rational ends, when bisected
};

std::vector<double> approx_crossings(const Unfolding& u, const WindowStore& s, std::uint32_t edge, std::uint32_t wa,
                                     std::uint32_t wb, double lo, double hi);
KinkParameter kink_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                             std::uint32_t wa, std::uint32_t wb, double at);
// The same from a certified bracket [lo, hi] of the crossing (edge_crossings.h; lo == hi: a
// proved zero at that rational), narrowed by certified bisection.
KinkParameter kink_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                             std::uint32_t wa, std::uint32_t wb, const mpq_class& lo, const mpq_class& hi);
// Every parameter where the two windows' times along the edge line are equal, among the
// (at most two) roots of the polynomial left after squaring, as exact sums; none without
// exact window data (or past the exact stage's size limits).
std::optional<std::vector<ExactSum>> crossing_candidates(const Unfolding& u, const WindowStore& s, Certifier& cert,
                                                         std::uint32_t edge, std::uint32_t wa, std::uint32_t wb);
// Whether the two windows' times along the whole edge line are one function, proved from
// their exact data (equal offsets and equal squared distances sigma, gamma, beta, |E|^2 in
// their frames, or equal c0, c1 for plane waves: the same virtual source seen from the
// edge); false where not proved (no exact data, or different).
bool identical_along_edge(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                          std::uint32_t wa, std::uint32_t wb);
// The point a + l (b - a) of the edge (a, b), exactly.
ExactPoint3 edge_point_at(const MedialComplex& mc, std::uint32_t edge, const mpq_class& l);
KinkParameter ray_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                            std::uint32_t w, std::uint32_t bound_vertex, double at);

}  // namespace grassfire
