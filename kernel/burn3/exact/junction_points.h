// junction_points.h -- the kinks, merges and quench points of the junction rule, located
// and classified on every singular edge (4.2.1, Fig. 4.4; docs/design.md 5 "Fronts"; docs/exact-engine.md).
//
// Computes, from an ExactBurning after run(), the switch points of each singular edge E:
// the interior points p of E where the record realising the (k-1)-th arrival A changes
// (WindowPropagation::junction_switches). With a and b the arrivals realising A just below
// and just above p's parameter lambda (both equal A(p) there) and a', b' their derivatives
// along E at p (per unit of lambda; for a point window sigma + |X - S| it is
// (X - S) . (V1 - V0) / |X - S|, for a plane wave u . (V1 - V0)), p is
//  - a kink when a' < b': A has a convex corner; the pair of sheets on which BT is
//    continuous changes there (Fig. 4.4: the board-and-fin kink at s = 2 + sqrt2);
//  - a quench when a' > 0 > b': the fronts running along E meet head on, A has a local
//    maximum there (the board and fin truncated at E = 6: the kink's front meets the fire
//    of the far end (6, 6, 0) at s = 7/2 + 3/2 sqrt2, BT = 3 + 5/2 sqrt2);
//  - a merge when the two fronts run the same way along E and continue each other: a' > b'
//    with a' < 0 or b' > 0 (the faster front takes over; A has a concave corner), or a and
//    b come through different sheet sides and are proved to be the same function along E
//    (equal times at both ends of E and at p, decided exactly or structurally by
//    Certifier::compare_times: two functions of this form that agree at three points are
//    equal, since their difference vanishes on the roots of a quadratic). The same function
//    through the same side is one front split by the mesh: not a switch, not listed;
//  - a tangent handover when a and b lie in one triangle and b is a point window proved to
//    start on a's front (junction_tangents.h: b's offset is a's time at b's source, so b >= a
//    with equality along a ray, and a' = b' at p: A is differentiable there). One fire front
//    runs on smoothly (a Linear border edge's plane wave continued by the circle about its
//    border vertex, or a circle by the circle of a vertex it ignited): no corner, so neither a
//    kink nor a quench, and not a merge of two fronts either; listed as `tangents`;
//  - unclassified otherwise (a sign no stage certified; counted, never guessed), and where
//    a corner is certified between two windows of one triangle one of which is proved to
//    start on the other's front: b >= a with equality only along a ray leaves no corner
//    where a(p) = b(p), so such a switch is a discontinuity of the computed A (tripod-s2: two
//    record ends of one plane wave 1e-15 apart, ordered by their double parameters, with the
//    circle of its border vertex realising the sliver between them), never a kink.
// Each point is given exactly where the data is exact: lambda as a sum of square roots (the
// edge point's closed form, junction_kinks.h) and BT as an ExactSum (Certifier::
// exact_expr); else as certified enclosures. x, bt and error are doubles with |x_i - exact|
// <= error and |bt - BT(p)| <= error.
// Switches at vertices where a curve runs on from one singular edge into another (no link
// rule there) are classified the same way, with both slopes per unit length along the curve
// (the board and fin whose curve runs at direction (3/5, 4/5) has its kink s* = 5 at a vertex).
// Switches at vertices with a link rule (singular points, segments) are not listed: the link
// rule decides those points (vertex_burning.cpp) and the event log lists them. Quench lines inside
// sheets (where two windows meet) are curves, not points, and not listed.
// Contract: eb has run. Complexity: O(switches) Arb evaluations of two windows' chains at
// 128..max_bits bits, plus 2 staged comparisons per switch whose slopes Arb cannot separate
// and a structural proof (junction_tangents.h) for those that are not one function.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "burn3/exact/exact_burning.h"

namespace grassfire {

struct JunctionPoint {
  enum class Kind : std::uint8_t { Kink, Merge, Quench, Tangent };
  Kind kind = Kind::Kink;
  std::uint32_t edge = 0;
  std::uint32_t edge_point = 0;       // index into WindowStore::edge_points
  std::uint32_t left = 0, right = 0;  // the windows realising A below and above lambda
  std::optional<ExactSum> lambda;     // exact parameter along v[0] -> v[1]
  std::optional<std::array<ExactSum, 3>> exact_x;
  std::optional<ExactSum> exact_bt;
  std::array<double, 3> x{};
  double bt = 0.0, error = 0.0;
};

struct JunctionPoints {
  std::vector<JunctionPoint> kinks, merges, quenches, tangents;
  std::uint64_t unclassified = 0;  // switch points no certified sign classified
};

JunctionPoints junction_points(ExactBurning& eb);
const char* to_string(JunctionPoint::Kind k);

}  // namespace grassfire
