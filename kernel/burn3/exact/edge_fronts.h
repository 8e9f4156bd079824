// edge_fronts.h -- a window's time along an edge of its triangle in closed form, with
// certified coefficients: the fronts whose crossings the junction rule isolates (4.2.1,
// Fig. 4.4; docs/design.md 3, 5a).
//
// Computes, for a window w and an edge E = a + l (b - a) of its triangle (A + l D in w's
// frame, an isometric unfolding), the time of w at the point l of E's line:
//  - a point source S with offset sigma: t(l) = sigma + sqrt(delta (l - l0)^2 + h2), with
//    delta = |D|^2, l0 = (S - A).D / delta the foot of S on the line and h2 =
//    cross(A - S, D)^2 / delta its squared distance to it (exactly 0 for a source on E's
//    line: EdgeFront::on_line);
//  - a plane wave with unit direction u and offset c: t(l) = c0 + c1 l, c0 = c + u.A,
//    c1 = u.D;
// and its derivative in l, over a parameter box given as an Interval or a Ball (rigorous
// enclosures: the box's points, the coefficients' enclosures and every rounding).
// The coefficients come from the window's exact data re-evaluated in Arb
// (Certifier::along_edge) at 128 bits, and at max_bits when asked; their double enclosures
// (one outward rounding of the 128-bit balls) are far tighter than the windows' double
// discs, whose radii carry the error accumulated along the unfolding chain, so the double
// filter of the crossings' isolation decides almost everything itself.
// EdgeFronts keeps them per (window, edge): a record meets every other record of its edge.
// Contract: E is an edge of w's triangle; the store's windows never change their source.
// Complexity: O(chain) Arb operations once per (window, edge, precision), O(1) per evaluation.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "burn3/exact/window_certify.h"
#include "number/ball.h"
#include "number/interval.h"

namespace grassfire {

template <class T>
struct FrontCoefficients {
  bool plane = false;
  bool on_line = false;    // a point source on E's line: h2 = 0, t = sigma + sqrt(delta) |l - l0|
  T c0, c1;                // plane: t = c0 + c1 l
  T sigma, delta, l0, h2;  // point: t = sigma + sqrt(delta (l - l0)^2 + h2)
};

struct EdgeFront {
  Interval corner;  // on_line: l0 as the caller knows it (a point where it is a double)
  FrontCoefficients<Interval> d;  // double enclosures
  std::array<std::unique_ptr<FrontCoefficients<Ball>>, 2> balls;  // at 128 bits, at max_bits
};

// The time and its derivative over the box l (Interval or Ball at the current precision).
Interval front_time(const FrontCoefficients<Interval>& c, const Interval& l);
Interval front_rate(const FrontCoefficients<Interval>& c, const Interval& l);
Ball front_time(const FrontCoefficients<Ball>& c, const Ball& l);
Ball front_rate(const FrontCoefficients<Ball>& c, const Ball& l);
// An upper bound of |t_a(l) - t_b(l)| over l in [lo, hi] from the coefficients' differences
// (|sqrt(P) - sqrt(Q)| <= sqrt(|P - Q|)): tiny for two expressions of one front, whatever
// the width of the range; inf for a plane wave against a point source.
double front_difference_bound(const FrontCoefficients<Ball>& a, const FrontCoefficients<Ball>& b, double lo, double hi);

class EdgeFronts {
 public:
  // on_line: the window's source lies on E's line, at the parameter enclosed by `corner`
  // (the caller knows it exactly).
  EdgeFront& front(Certifier& cert, std::uint32_t w, std::uint32_t edge, bool on_line, const Interval& corner);
  // Its coefficients in Arb: level 0 at 128 bits, level 1 at cert.max_bits().
  const FrontCoefficients<Ball>& ball(Certifier& cert, std::uint32_t w, std::uint32_t edge, int level);

 private:
  std::unordered_map<std::uint64_t, EdgeFront> fronts_;
};

}  // namespace grassfire
