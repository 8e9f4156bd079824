// synthetic_meshes.h -- closed triangle meshes made in code, with known topology: tori and
// voxel solids (the boundary of a union of unit cubes).
//
// Computes:
//  - torus_mesh, pinched_torus_mesh, sphere_mesh (an icosphere): the torus of radii R > r > 0 about the z axis, n x m quads split into
//    triangles, outward (genus 1; coordinates are the nearest doubles of the parametric
//    points);
//  - voxel_mesh: the faces between filled and empty unit cells of an integer voxel set,
//    scaled by `size`, two outward triangles per face, vertices shared exactly. The
//    solid's topology is the union's: a plate with g through-holes has genus g, disjoint
//    voxels give separate shells, an empty cell enclosed by filled ones a cavity;
//  - prism_mesh: a polygon extruded (notches and slits with sharp reflex edges);
//  - lens_mesh: a spherical cap closed by its disc (a sharp convex rim);
//  - random_convex_hull_mesh: a seeded random convex polyhedron (convex_hull_mesh.cpp).
// Contract: for voxel_mesh, no two filled voxels that touch only along an edge or a corner
// (the boundary would not be a manifold; require_closed_manifold says so), size > 0.
// Complexity: O(n log n) for n voxels; O(n m) for the torus.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

TriangleMesh3 torus_mesh(double major, double minor, int n, int m);

// The same torus with the tube's radius minor * |sin(u / 2)| along the angle u about the z
// axis: the ring at u = 0 is one vertex, a non-manifold vertex with two fans (a pinched
// torus, the defective input of mesh_repair.h's tests).
TriangleMesh3 pinched_torus_mesh(double major, double minor, int n, int m);

// The icosahedron subdivided `levels` times, its vertices pushed onto the sphere of `radius`
// about `centre` (outward; 20 * 4^levels triangles).
TriangleMesh3 sphere_mesh(const std::array<double, 3>& centre, double radius, int levels);

using Voxel = std::array<int, 3>;
TriangleMesh3 voxel_mesh(const std::vector<Voxel>& filled, double size = 1, const std::string& name = "voxels");

// The prism over a simple polygon (counter-clockwise, star-shaped from its first vertex,
// which the top and bottom are fanned from) between z = 0 and z = height.
TriangleMesh3 prism_mesh(const std::vector<std::array<double, 2>>& polygon, double height, const std::string& name = "prism");

// The solid cut from the unit ball by the plane z = cos a, a = rim_angle degrees (0 < a <
// 90): the spherical cap of polar angle a (`rings` rings of `sectors` vertices) closed by
// its flat disc (rings of the same radii). Its rim is a circular edge of interior dihedral
// angle a: a thin filled cap, a sharp wedge all around for small a (mesh_axis.h, step 7).
// Outward; one shell, Betti numbers 1, 0, 0; rings >= 2, sectors >= 3.
TriangleMesh3 lens_mesh(double rim_angle, int rings, int sectors);

// The convex hull of `points` seeded random points on the sphere of radius 8, rounded to
// integers (CGAL convex_hull_3; triangles outward, coplanar ones kept as triangles).
TriangleMesh3 random_convex_hull_mesh(std::uint32_t seed, int points);

// The voxels of an n x n x n block whose inner (n - 2)^3 cells are empty (a cavity, n >= 3).
std::vector<Voxel> hollow_block_voxels(int n);

// A box of nx x ny x 1 voxels with the listed (x, y) cells removed: genus = holes when the
// holes are interior and do not touch each other.
TriangleMesh3 plate_with_holes(int nx, int ny, const std::vector<std::array<int, 2>>& holes);

}  // namespace grassfire
