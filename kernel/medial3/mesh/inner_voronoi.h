// inner_voronoi.h -- the part of the Voronoi diagram of surface samples that lies inside a
// solid, as a polygonal 2-complex with exact combinatorics (2.1.2 in 3D).
//
// Computes, for samples P of the boundary of a solid S (mesh_samples.h) and S's exact
// locator (mesh_solid.h):
//  - the Delaunay triangulation of P (CGAL, exact predicates on the double samples) and
//    its Delaunay cells: tetrahedra with a common circumsphere merged (exact in-sphere
//    test on adjacent tetrahedra; equal circumcentres imply equal empty spheres, so the
//    cells are the classes and the Voronoi vertices are distinct);
//  - D_in, the cells whose circumcentre (Voronoi vertex) lies strictly inside S (exact);
//  - the Voronoi subcomplex V_in dual to the faces of D_in interior to it (every
//    incident cell in D_in): a vertex per cell of D_in, a polygon per interior Delaunay
//    edge pq (the Voronoi face of p and q: the circumcentres of the cells around pq in
//    cyclic order), a segment per interior Delaunay 2-face that is no polygon's side (the
//    Voronoi edge of a triangle pqr spanning a tube: a 1-dimensional part of the axis);
//    a sample whose every cell is in D_in has its whole Voronoi cell in the dual complex:
//    that 3-cell is collapsed through one boundary polygon (so V_in stays a 2-complex
//    of the same homotopy type).
// Topology (why this complex): the dual blocks of the faces of a cell complex that are not
// on its frontier form a deformation retract of the complex minus its frontier (the
// complementary-subcomplex lemma of PL topology, on the barycentric subdivision), so V_in
// is homotopy equivalent to the interior of |D_in|. For an epsilon-sample of a smooth
// surface (epsilon small) the Delaunay triangles whose Voronoi edges cross the surface
// once form a surface homeomorphic to it (Amenta-Bern 1999, Edelsbrunner-Shah 1997), which
// bounds D_in, so V_in has the homotopy type of the solid. Meshes are not smooth: the
// builder (mesh_axis.h) checks the Betti numbers exactly and refines the samples.
// Exactness: combinatorics from CGAL's filtered exact predicates and exact in/out tests.
// The samples lie on a lattice g Z^3 spanning at most 2^27 steps (mesh_samples.h), so the
// circumcentre of a tetrahedron n_0..n_3 is c = g (n_0 + N / D) with D = 2 det[n_i - n_0]
// (|D| < 2^85) and |N_k| < 2^113: exact in 128-bit integers, enclosed from them in
// doubles, and a rational only when asked for.
// Contract: lattice coordinates within 2^27 of each other (std::invalid_argument
// otherwise); distinct samples. Fewer than 4 affinely independent samples give an empty
// complex.
// Complexity: O(n log n) expected for the triangulation of n samples, then linear in its
// size plus one locator query per Delaunay cell.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "medial3/mesh/axis_pruning.h"
#include "medial3/mesh/mesh_samples.h"
#include "medial3/mesh/mesh_solid.h"
#include "number/interval.h"

namespace grassfire {

// The circumcentre of a lattice tetrahedron t: g (n_{t[0]} + num / den), den != 0.
struct LatticeCentre {
  std::array<std::uint32_t, 4> tetrahedron{};  // sample ids
  std::array<__int128, 3> num{};
  __int128 den = 0;
};

struct InnerVoronoi {
  struct Vertex {  // a Delaunay cell with its circumcentre inside
    LatticeCentre centre;  // of one of its tetrahedra
    std::array<Interval, 3> box;
  };
  struct Segment {  // the Voronoi edge of triangle `triangle` (samples)
    std::array<std::uint32_t, 2> v{};
    std::array<std::uint32_t, 3> triangle{};
  };

  SurfaceSamples samples;
  std::vector<Vertex> vertices;
  // Polygon i is the Voronoi face of samples pq[i]: a ring of distinct vertex ids; its
  // side k is dual to the Delaunay triangle (p, q, apex[offset[i] + k]).
  PolygonRings polygons;
  std::vector<std::uint32_t> apex;
  std::vector<std::array<std::uint32_t, 2>> pq;
  std::vector<Segment> segments;
  // Per sample, the distance to the nearer of its two poles (a local feature size
  // estimate, in doubles: it only steers the refinement of the sampling).
  std::vector<double> pole_distance;
  // Per sample, the distance to its inner pole (the largest R(x) over the inner Voronoi
  // vertices of its cell; 0 when the cell has none): the local half-thickness of the solid
  // at the sample, which the separation test of the pruning must resolve (mesh_axis.h).
  std::vector<double> inner_pole_distance;
  // Per sample, the vertex (index into `vertices`) at that distance: its inner pole
  // (UINT32_MAX when the cell has no inner vertex).
  std::vector<std::uint32_t> inner_pole;
  // Structure and cost.
  std::size_t tetrahedra = 0, cells = 0, cells_on_boundary = 0, cospherical_pairs = 0;
  std::size_t interior_samples = 0;  // Voronoi cells wholly inside, collapsed through one face
  double delaunay_seconds = 0, classify_seconds = 0, extract_seconds = 0;
};

InnerVoronoi inner_voronoi(SurfaceSamples samples, const SolidLocator& solid);

// The baseline of the benchmarks: CGAL's Delaunay_triangulation_3 construction alone on the
// same points (Epick, range insertion with spatial sorting); returns its finite cell count.
std::size_t cgal_delaunay_cells(const SurfaceSamples& samples);

LatticeCentre lattice_circumcentre(const SurfaceSamples& s, const std::array<std::uint32_t, 4>& tetrahedron);
std::array<Interval, 3> enclose(const SurfaceSamples& s, const LatticeCentre& c);
// The exact centre, and its exact squared radius when asked.
ExactPoint3 exact_point(const SurfaceSamples& s, const LatticeCentre& c, mpq_class* radius_squared = nullptr);
ExactPoint3 exact_sample(const SurfaceSamples& s, std::uint32_t i);
// GMP values of a 128-bit integer.
mpz_class to_mpz(__int128 x);
mpq_class to_mpq(__int128 x);

}  // namespace grassfire
