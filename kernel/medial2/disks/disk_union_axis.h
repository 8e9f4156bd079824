// disk_union_axis.h -- the exact medial axis of a union of disks (2.1.1; Attali and
// Montanvert 1997; Amenta and Kolluri 2001).
//
// Computes: the medial graph of U = union of the disks of a DiskList. The boundary of U
// is made of circular arcs meeting at corners (points on two circles and in no other
// disk). Amenta and Kolluri: the medial axis of U is the part of the Voronoi diagram of
// the corners that lies in the dual complex K (the alpha complex at alpha = 0: the nerve
// of the disks restricted to their power cells), plus the centres of isolated disks. In
// the plane it is piecewise linear and meets the boundary of K only at disk centres,
// and at the centre of a disk whose circle carries k >= 1 boundary arcs the axis has one
// branch per gap between consecutive arcs, along the bisector of the corners that bound
// the gap. The construction therefore needs no point location:
//   1. K from CGAL's regular triangulation of the disks (weights r^2), classified exactly
//      with rational power values; its Betti numbers b0, b1 are those of U;
//   2. corners: the chord ends of every edge of K that lie in no adjacent apex's disk;
//      arcs: the corners on each circle in exact angular order;
//   3. the Delaunay triangulation of the corners (CGAL, with exact predicates on points
//      in Q(sqrt sigma): disk_union_geometry.h), cocircular triangles merged exactly, so
//      the centre of a circle with k >= 2 arcs is one Voronoi vertex;
//   4. from every centre, the Voronoi pieces towards its gaps are medial, the ones towards
//      its arcs are not; a medial piece makes its far Voronoi vertex medial and then all
//      pieces around that vertex; nothing else is medial. Every piece reached twice must
//      agree and no medial piece may reach infinity (checked: std::logic_error).
// Nodes: disk centres (leaves for one arc, junctions of k branches for k >= 2 arcs,
// isolated disks) and Voronoi vertices of corners; edges are straight segments. Exact
// values: medial2/disks/disk_union_geometry.h. Validation against the definition:
// medial2/disks/disk_union_validate.h.
// Input policy (io/disk_list.h): covered disks (inside another, repeated, or inside the
// union of others) are ignored and counted; disconnected unions give a forest. Rejected
// with the disks' line numbers (std::invalid_argument): two circles touching at a single
// boundary point, three circles through one boundary point (the boundary is then not a
// union of arcs with two-circle corners).
// Complexity: O(n log n) expected for n disks (two triangulations); exact arithmetic
// only where the interval filters fail (counted in the report).
#pragma once

#include <cstdint>

#include "medial2/disks/disks.h"
#include "medial2/medial_graph.h"
#include "number/exact_sum.h"

namespace grassfire {

struct DiskUnionAxisReport {
  std::uint64_t disks = 0;
  std::uint64_t covered_disks = 0;   // contribute nothing to the union's boundary or K
  std::uint64_t isolated_disks = 0;  // components made of one disk (axis: its centre)
  // The dual complex K and the Betti numbers of the union computed from it.
  std::uint64_t dual_vertices = 0, dual_edges = 0, dual_triangles = 0;
  std::uint64_t union_components = 0, union_holes = 0;
  std::uint64_t corners = 0, arcs = 0;
  std::uint64_t voronoi_vertices = 0;  // after merging cocircular Delaunay triangles
  std::uint64_t cocircular_merges = 0;
  std::uint64_t nodes = 0, edges = 0, leaves = 0;
  NumberStats predicates;  // corner predicates: interval filter vs exact
  double dual_seconds = 0, voronoi_seconds = 0, axis_seconds = 0;
};

MedialGraph disk_union_axis(const DiskList& disks, DiskUnionAxisReport* report = nullptr);

}  // namespace grassfire
