// axis_pruning3_detail.h -- the subdivision K that axis_pruning3.cpp builds and
// axis_pruning3_collapse.cpp collapses (internal to prune_axis3, axis_pruning3.h).
//
// K's vertices: M's vertices first (same ids), then the cut points on M's edges (edge by
// edge, by parameter), then points inside triangles (crossings of the two threshold lines
// and centroids of fanned pieces). Each simplex carries whether it fails a threshold;
// each edge the edge of M it lies on (kNoIndex inside a triangle).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "curves3/axis_pruning3.h"

namespace grassfire::pruning3 {

struct RefinedVertex3 {
  ExactPoint3 point;
  mpq_class radius_squared;
  PrunedVertex3 info;
};

struct RefinedEdge3 {
  std::array<std::uint32_t, 2> v{};
  std::uint32_t parent = kNoIndex;  // the edge of M it lies on
  bool fails = false;
};

struct RefinedTriangle3 {
  std::array<std::uint32_t, 3> v{};
  std::array<std::uint32_t, 3> e{};  // e[i] opposite v[i]
  bool fails = false;
};

struct Refined {
  std::vector<RefinedVertex3> vertices;
  std::vector<RefinedEdge3> edges;
  std::vector<RefinedTriangle3> triangles;
  std::uint64_t cut_points = 0;
};

Refined subdivide(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& thresholds);
// The collapse of axis_pruning3.h; fills everything but betti_axis and the uncertified count.
PrunedAxis3 collapse(const MedialComplex& mc, Refined k);

}  // namespace grassfire::pruning3
