// burn_outputs.h -- what the exact burning time is turned into: per-vertex values, a
// refined sampling, iso-lines, the front at a time t, and the event log (docs/exact-engine.md).
//
// Computes, from an ExactBurning after run():
//  - vertex_values: BT and ET = BT - R per vertex, each as a midpoint with a certified
//    error bound, decision_error included (value +infinity where nothing burns);
//  - refine: every triangle split into n^2 triangles (barycentric grid, n >= 1; shared edge
//    points once), with BT at every grid point (certified enclosures), for io/'s writers;
//  - iso_lines: for each time t, the segments where the piecewise-linear interpolation of
//    the refined BT crosses t (marching triangles). The exact iso-line is a union of conic
//    arcs (one per window); these polylines have their vertices on grid edges, located by
//    linear interpolation of certified values -- a drawing, at distance O(h^2 |BT''|) from
//    the exact curve for grid spacing h, not a certified curve;
//  - front_at: the burned part of each triangle at time t as the same marching-triangles
//    polygons ("the front at time t" is their boundary);
//  - event_log: the engine's events (vertex sources made, vertices burned by the link rule)
//    sorted by certified comparisons of their exact times (ties by the documented rank:
//    kind, then id).
// Contract: the ExactBurning has run. Complexity: refine O(T n^2 q) for q windows per
// triangle; iso_lines O(T n^2 times); event_log O(E log E) comparisons.
#pragma once

#include <string>
#include <vector>

#include "burn3/exact/exact_burning.h"

namespace grassfire {

struct CertifiedValue {
  double value = 0.0;  // midpoint of the enclosure (+infinity: never burns)
  double error = 0.0;  // |value - exact| <= error
};
CertifiedValue certified_value(const Interval& i);

// What the run's decisions add to the error of every finite value beyond its enclosure:
// +infinity when a decision is uncertified (no bound is claimed), else the count of
// negligible ties (two fronts within 2^-64 on a stretch of an edge, no order proved) times
// 2^-64, rounded up: each moves every later arrival by at most 2^-64, since order
// statistics and min-plus propagation are 1-Lipschitz (edge_crossings.h).
double decision_error(ExactBurning& eb);

struct VertexBurnValues {
  std::vector<CertifiedValue> bt, et;
};
VertexBurnValues vertex_values(ExactBurning& eb);

struct RefinedBurn {
  std::vector<Vec3d> points;
  std::vector<CertifiedValue> bt;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> source_triangle;  // per refined triangle
};
RefinedBurn refine(ExactBurning& eb, int n);

struct Segment3 {
  Vec3d a, b;
};
// Per time, the iso-line segments of the refined BT.
std::vector<std::vector<Segment3>> iso_lines(const RefinedBurn& r, const std::vector<double>& times);
// The burned part {BT <= t} of the refined sampling, as polygons (3 to 5 corners each).
std::vector<std::vector<Vec3d>> front_at(const RefinedBurn& r, double t);

std::vector<SweepEvent> event_log(ExactBurning& eb);
const char* to_string(SweepEvent::Kind k);

}  // namespace grassfire
