// disk_union_triangulations.h -- the two CGAL triangulations behind the medial axis of a
// union of disks (medial2/disks/disk_union_axis.h), handed over as plain data.
//
// Computes: (1) the regular triangulation of the disks (weighted points, weight r^2), on
// CGAL's exact-constructions kernel fed with the exact rationals of the disk list;
// (2) the Delaunay triangulation of the boundary corners, on CGAL's triangulation with a
// traits class whose predicates are CornerPredicates (exact for points in Q(sqrt sigma)).
// Both are CGAL's; this file only maps them to ids, so no other file needs CGAL headers.
// Contract: disks have positive radii; corners are pairwise distinct.
// Complexity: O(n log n) expected; corners are inserted in Morton order of their
// approximations with the previous vertex as the location hint.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "medial2/disks/disks.h"
#include "medial2/disks/disk_union_geometry.h"

namespace grassfire {

constexpr std::uint32_t kNoId = 0xffffffffu;

struct RegularTriangulationData {
  int dimension = -1;
  std::vector<std::uint32_t> vertices;             // disks that are vertices (the others are hidden)
  std::vector<std::array<std::uint32_t, 3>> faces; // finite faces, disks counter-clockwise
  struct Edge {
    std::uint32_t i = 0, j = 0;
    std::array<std::uint32_t, 2> face{kNoId, kNoId};  // adjacent finite faces (kNoId: infinite or none)
    std::array<std::uint32_t, 2> apex{kNoId, kNoId};  // the disk opposite the edge in each face
  };
  std::vector<Edge> edges;  // every finite edge once
};

RegularTriangulationData regular_triangulation(const std::vector<Disk>& disks);

struct CornerTriangulationData {
  int dimension = -1;
  std::vector<std::array<std::uint32_t, 3>> faces;  // finite faces, corners counter-clockwise
  struct Edge {
    std::uint32_t a = 0, b = 0;
    std::uint32_t left = kNoId, right = kNoId;  // faces left and right of a -> b (kNoId: infinite/none)
  };
  std::vector<Edge> edges;  // every finite edge once
};

CornerTriangulationData corner_delaunay(const std::vector<UnionCorner>& corners, const CornerPredicates& predicates);

}  // namespace grassfire
