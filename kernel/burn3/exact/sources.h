// sources.h -- where fire starts: the exact data of the border ignition rules and the
// position of every pseudo-source in a triangle's frame (ch. 4, docs/design.md 5 and 5a).
//
// Computes:
//  - the ignition f(v) at a border vertex as an exact sum of square roots: the minimum over
//    its border edges of their rule at v (Linear: R(v) = sqrt(R^2); DistanceToPoint:
//    |v - p|), R(v) for a border point without border edges (RawComplex), none for Never;
//  - the plane-wave test of a Linear border edge: f = R interpolated linearly has slope
//    s = (R1 - R0) / |e| and ignites a plane wave iff |s| < 1 (decided exactly: (R1 - R0)^2
//    < |e|^2 with R = sqrt(R^2)); with |s| >= 1 the minimum of f(y) + |x - y| over the edge
//    is at an endpoint, and the endpoints' vertex sources already cover it;
//  - the rotated point of a DistanceToPoint edge: p rotated about the edge's line into the
//    sheet's plane, on the far side of the edge: S = a + alpha (b - a) - h n, n the unit
//    normal into the triangle, alpha = (p - a).(b - a) / |b - a|^2, h^2 = |p - a|^2 - alpha^2 |b - a|^2
//    (both rational), so that |S - y| = |p - y| for y on the edge's line;
//  - the image of a point of an edge (a kink of the junction rule) in a triangle's frame;
//  - the root image of a pseudo-source in a triangle's frame, as a double disc (with an
//    Interval offset) or an Arb ball (for the certified re-evaluation): the point S (with
//    offset sigma), or for a plane wave the unit direction u with time c + u . X,
//    u = s a + sqrt(1 - s^2) n, c = R0 - u . A.
// Contract: a validated MedialComplex; pseudo-sources as the engine creates them (their
// triangle t contains the source point, or is the border edge's triangle).
// Complexity: O(1) exact / interval / Arb operations per call.
#pragma once

#include <optional>

#include "burn3/exact/unfolding.h"
#include "burn3/exact/windows.h"

namespace grassfire {

std::optional<ExactSum> exact_vertex_ignition(const MedialComplex& mc, std::uint32_t v);
bool linear_plane_wave(const MedialComplex& mc, std::uint32_t e);

struct RotatedPoint {
  mpq_class alpha, h2;  // foot parameter along e.v[0] -> e.v[1], squared distance to the line
};
RotatedPoint rotated_point(const MedialComplex& mc, std::uint32_t e);

struct RootDisc {
  DiscPoint source;
  Interval offset;
  bool plane = false;
};
struct RootBall {
  BallVec2 source;
  Ball offset;
  bool plane = false;
};

// The root of pseudo-source p in t's frame; `sigma` is the offset of point sources at the
// current precision (the caller evaluates vertex offsets along their spawning chain).
RootDisc root_disc(const Unfolding& u, const WindowStore& s, std::uint32_t p, std::uint32_t t);
RootBall root_ball(const Unfolding& u, const WindowStore& s, std::uint32_t p, std::uint32_t t, const Ball& sigma);

// The image of edge point `id` (an index into s.edge_points) in the frame of triangle t,
// which contains its edge: (1 - lambda) A + lambda B from the edge ends' images.
DiscPoint edge_point_image(const Unfolding& u, const WindowStore& s, std::uint32_t t, std::uint32_t id);
BallVec2 edge_point_ball(const Unfolding& u, const WindowStore& s, std::uint32_t t, std::uint32_t id);
// lambda as a ball at the current precision (exact: from its ExactSum; else its rational
// bracket, or its double enclosure).
Ball edge_point_lambda_ball(const WindowStore& s, std::uint32_t id);

// The border edge's only triangle (the sheet side that a border rule ignites).
std::uint32_t border_triangle(const MedialComplex& mc, std::uint32_t e);

}  // namespace grassfire
