// burning_field.h -- a burning-time field with burning paths on a medial complex (4.2.3,
// 5.1.2): what the medial curves, the burning-path export and the shape analysis need from
// a burning engine, and nothing more.
//
// Vocabulary. BT jumps across singular curves (Prop. 6), so values are asked for "as seen
// from a triangle t": the t-side burning time BT_t(p) at a point p of the closed triangle
// t is the limit of BT at p from inside t (BT itself inside t; on an edge of t the time
// the fire in t reached p, which on a singular curve may be earlier than BT(p), when the
// front in t arrived and waited, 4.2.1). The burning path of p seen from t is the curve the
// fire followed to reach p through t, traced backwards: a polyline p = q0, q1, ..., qm
// that is straight inside each triangle it crosses, turns only on edges and vertices, and
// ends where the fire started (a border point burning at its own f, or a source). Along
// it BT_t decreases at unit rate: BT_t(p) = f(qm) + length (Definition 9: every burning
// path is a non-crossing curve from a burned point).
//
// Contract of an implementation:
//  - sample_in_triangle(t, p), p in closed t (a caller's point; the implementation may
//    clamp it into t): BT_t(p) (+infinity where nothing burns) and the last straight piece
//    of the path, as the point `from` where it enters p's straight piece (in closed t) and
//    the unit direction of travel at p (from -> p); `started` when p itself is where the
//    fire started (then direction is zero).
//  - sample_on_segment(e, s): the same on a dangling segment e (a 1-dimensional part) at
//    parameter s from e.v[0].
//  - path_in_triangle / path_on_segment / path_from_vertex / path_from_edge_point: the
//    whole path (q0 = p); at a vertex or an edge point the path of the point's own BT.
//  - edge_points(e) and edge_point_burn_time(e, i): the points at which the field resolves
//    edge e (i = 1 .. edge_points(e) at parameters i / (edge_points(e) + 1) from e.v[0]; 0
//    and edge_points(e) + 1 are e's ends) and BT of the point itself there (the link rule
//    applied, not a side limit). Refinements of the complex (axis_refinement.h) put their
//    vertices there, so that the medial curves follow the field's own resolution.
//  - resolution(): the length scale of the field's error (h for the discrete baseline;
//    0 for an exact engine); method(): a short description for reports.
//
// The discrete baseline (discrete_burning_field.h) implements this from its graph points
// and the predecessors it records. How an exact engine (the sweep of 5.2, kernel/burn3/
// exact/) plugs in: inside triangle t its fronts are windows (pseudo-source s unfolded into
// t's plane, offset sigma, over a wedge), so sample_in_triangle is the min over the windows
// that cover p of sigma + |p - s|, `from` the point where the segment s -> p enters closed t
// (s itself when s lies in t), direction (p - s) / |p - s|; `started` when the minimum is a
// border ignition or a source at p. path_in_triangle walks the winning window's chain of
// parents: the straight piece back to the window's entry edge, the parent window that
// emitted it (across a manifold edge: the same pseudo-source unfolded; across a singular
// curve: the arriving window rotated about the curve, docs/design.md 5), down to its origin on
// the border or at a source. edge_points may be any subdivision (e.g. ceil(|e| / h) - 1
// points, as the baseline) and edge_point_burn_time is the engine's BT at those points.
// That implementation is burn3/exact/exact_burning_field.h. Nothing else changes:
// medial_curves.h, shape_analysis.h and the commands only see this interface (`--method
// exact` picks the implementation, tools/field_input.h).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

struct FieldSample {
  double bt = std::numeric_limits<double>::infinity();
  Vec3d from{};       // where the straight piece of the burning path into p starts
  Vec3d direction{};  // unit direction of travel at p; zero when `started` or unburned
  bool started = false;
};

class BurningField {
 public:
  virtual ~BurningField() = default;
  virtual const MedialComplex& complex() const = 0;
  virtual std::string method() const = 0;
  virtual double resolution() const = 0;

  virtual double vertex_burn_time(std::uint32_t v) const = 0;
  virtual std::uint32_t edge_points(std::uint32_t e) const = 0;
  virtual double edge_point_burn_time(std::uint32_t e, std::uint32_t i) const = 0;

  virtual FieldSample sample_in_triangle(std::uint32_t t, const Vec3d& p) const = 0;
  virtual FieldSample sample_on_segment(std::uint32_t e, double s) const = 0;

  virtual std::vector<Vec3d> path_in_triangle(std::uint32_t t, const Vec3d& p) const = 0;
  virtual std::vector<Vec3d> path_on_segment(std::uint32_t e, double s) const = 0;
  virtual std::vector<Vec3d> path_from_vertex(std::uint32_t v) const = 0;
  // The path of edge e's point i (1 .. edge_points(e)) itself: the one its burning time
  // came by (through the link rule), not a side's.
  virtual std::vector<Vec3d> path_from_edge_point(std::uint32_t e, std::uint32_t i) const = 0;
};

// The point at parameter s of edge e (from e.v[0]), in doubles.
Vec3d edge_point(const MedialComplex& mc, std::uint32_t e, double s);
double polyline_length(const std::vector<Vec3d>& path);

}  // namespace grassfire
