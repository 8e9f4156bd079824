// mesh_samples.h -- points on the surface of a triangle mesh at a given spacing per
// triangle.
//
// Computes: the mesh vertices; on every edge, the points splitting it into
// ceil(length / h_e) equal parts, h_e the smaller spacing of its two triangles (computed
// once per edge, so both triangles share them); inside every triangle t, rows parallel to
// its longest edge at heights k / r of the apex height H (r = ceil(H / h_t)), each row
// split into ceil(row length / h_t) parts, its inner points kept. Every point is then
// rounded to the lattice g Z^3, g the smallest power of two with (largest extent of the
// bounding box) / g <= 2^26, and duplicates are dropped: samples are a choice, within g of
// the surface (3e-8 of the box's extent), and the lattice keeps every later construction
// small and exact (the circumcentres of lattice points are quotients of 128-bit integers,
// inner_voronoi.h). Each triangle lists the samples on it (vertices, edges, inside), so
// that a refinement can be driven per triangle.
// Canonical: edges are split from their lexicographically smaller end, rows run parallel
// to the longest edge (ties broken by comparing points), and the samples are numbered in
// lexicographic order of their lattice points; so renumbering the mesh's vertices,
// reordering its triangles or rotating their corners gives the same samples with the same
// ids, and everything built on them (mesh_axis.h) is the same.
// Density: every point of a triangle is within about h_t of a sample, and samples are
// about h_t apart, so the count is about 2 area / h_t^2 (more on triangles thinner than h_t).
// Contract: spacings positive and finite, one per triangle; finite coordinates.
// Complexity: O(V + E + samples).
// Section: 2.1.2 (the sampled boundary whose Voronoi diagram approximates the axis).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

struct SurfaceSamples {
  std::vector<std::array<std::int64_t, 3>> lattice;  // sample i is grid * lattice[i]
  double grid = 1;                                   // g, a power of two
  // The samples on triangle t: on_triangle[offset[t] .. offset[t + 1]).
  std::vector<std::uint32_t> offset, on_triangle;
  std::array<double, 3> point(std::size_t i) const;
};

SurfaceSamples sample_surface(const TriangleMesh3& mesh, const std::vector<double>& triangle_spacing);
SurfaceSamples sample_surface(const TriangleMesh3& mesh, double spacing);

// The lattice step for a mesh: the smallest power of two g with extent / g <= 2^26.
double sample_grid(const TriangleMesh3& mesh);

// The mean length of the mesh's edges (each undirected edge once).
double mean_edge_length(const TriangleMesh3& mesh);

}  // namespace grassfire
