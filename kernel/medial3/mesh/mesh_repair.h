// mesh_repair.h -- from a defective triangle mesh (self-intersecting, non-manifold, slightly
// open, several overlapping shells) to a closed, embedded solid whose medial axis the mesh
// builder can compute, with what was repaired and how far the surface moved.
//
// Computes:
//  - mesh_defects: a census of what keeps a mesh from bounding a solid (mesh_checks.h
//    refuses at the first one): pairs of vertices at the same point, zero-area triangles,
//    border edges (in one triangle), non-manifold edges (in three or more), edges used
//    twice in the same direction (inconsistent orientation), non-manifold vertices (their
//    triangles form more than one fan: the link graph has several components), pairs of
//    triangles meeting outside a common vertex or edge (mesh_embedding.h, exact), and
//    shells (edge-connected components). All exact: combinatorics and CGAL's filtered
//    predicates on the double coordinates.
//  - repair_mesh, three steps, the first whose result passes require_closed_manifold
//    (the same exact check every mesh meets, so no step is trusted blindly):
//     1. "weld": vertices at the same point become one, degenerate and repeated triangles
//        are dropped (geometry3/mesh_weld.h, what every reader does; needed for meshes made in
//        code, e.g. a shell listed twice). No point moves: Hausdorff distance 0.
//     2. "fill": only when the defects are border edges and orientation (no crossing, no
//        non-manifold element): CGAL's orient_polygon_soup makes the orientation
//        consistent, and every border cycle is closed by PMP::triangulate_hole (the min-max
//        dihedral-angle, then area, triangulation of the hole's vertices; Liepa 2003). No vertex moves and no
//        vertex is added; cavities and separate shells are kept. The added triangles lie
//        within the hole's diameter of the input.
//     3. "alpha_wrap": CGAL's Alpha_wrap_3 (Portaneri et al. 2022) of the triangle soup
//        with alpha and offset (defaults: 1/50 and 1/300 of the bounding box
//        diagonal). Why not smaller: the wrap rounds convex edges and corners with
//        radius `offset`, and the mesh axis builder's thickness rule (mesh_axis.h, 6)
//        samples such a rounding finely: two overlapping copies of joint.off needed
//        2.9 million samples (over the limit) at 1/100 and 1/3000, 8.8 s of CPU at 1/50
//        and 1/300. CGAL's own example uses 1/20 and 1/600. Guarantee (CGAL 5.5 manual): the result is a watertight,
//        intersection-free, orientable 2-manifold that strictly contains the input, with
//        its vertices on the offset surface at distance `offset`; concavities narrower
//        than about alpha are filled. It is what a self-intersecting or non-manifold mesh
//        needs: PMP's autorefinement is not in CGAL 5.5, and removing self-intersections
//        locally (PMP's experimental remove_self_intersections) has no guarantee.
//        The wrap is the boundary of the union of the outside-facing Delaunay cells, so
//        overlapping shells become one surface and a cavity (a shell inside another) is
//        lost: step 3 runs only when 1 and 2 cannot give a solid. An enclosed shell in
//        the wrap can only come from CGAL's manifold fix (relabelled cells); such shells
//        are removed (counted in dropped_cavities), which only adds volume.
//    Why steps 1 and 2 first: they do not move the surface (distance 0 on what was
//    there), keep cavities, and keep the mesh's size; the wrap resamples the whole
//    surface at about alpha and offsets it by `offset`. A hole wider than alpha is not
//    closed by the wrap (the alpha ball enters it and the wrap hugs both sides of the
//    surface: a thin solid), which step 2 closes correctly.
//  - the Hausdorff distance between the input triangles (zero-area ones left out) and the
//    repaired surface, both one-sided ones and the two-sided (their maximum), by CGAL's
//    PMP::bounded_error_Hausdorff_distance: each value returned is within
//    `hausdorff_error` (1e-4 of the diagonal by default) of the true distance (the
//    algorithm's bound: a lower and an upper bound of the distance are refined by
//    subdividing triangles until they are at most that far apart; Sequential_tag).
//    Computed in doubles: a measurement, no decision depends on it.
// Contract: mesh coordinates finite, indices in range, three distinct indices per
// triangle (what the readers and generators guarantee); alpha > 0 and offset > 0 when set.
// Errors: std::invalid_argument "<source>: <problem>" when a step fails for a reason the
// input explains (fewer than 4 triangles); the wrap's result not passing the check would
// be a CGAL bug and is reported with the file name too.
// Complexity: the census O(n log n + k) (k overlapping bounding boxes); the wrap grows
// with (area / alpha^2) (its Delaunay refinement); the Hausdorff distance with the number
// of subdivided triangles.
// Section: 2.1 (the shape whose medial axis is built).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>

#include "geometry3/triangle_mesh.h"

namespace grassfire {

struct MeshDefects {
  std::size_t vertices = 0, triangles = 0;
  std::size_t duplicate_vertices = 0;     // vertices at the same point as an earlier one
  std::size_t zero_area_triangles = 0;    // three distinct collinear vertices
  std::size_t border_edges = 0;           // in exactly one triangle
  std::size_t non_manifold_edges = 0;     // in three or more triangles
  std::size_t inconsistent_edges = 0;     // in two triangles that use it in the same direction
  std::size_t non_manifold_vertices = 0;  // triangles around it form more than one fan
  std::size_t self_intersecting_pairs = 0;
  std::size_t shells = 0;                 // edge-connected components
  // The first problem require_closed_manifold reports ("" when the mesh bounds a solid).
  std::string refusal;
  bool any() const { return !refusal.empty(); }
};

MeshDefects mesh_defects(const TriangleMesh3& mesh);
// "3 border edges, 2 non-manifold vertices, 366 self-intersecting pairs, 2 shells" (the
// non-zero counts), or "none".
std::string describe_defects(const MeshDefects& d);

struct MeshRepairOptions {
  bool enabled = false;         // false: a defective mesh is refused (with a hint)
  double alpha = 0;             // 0: diagonal / 50
  double offset = 0;            // 0: diagonal / 300
  double hausdorff_error = 0;   // 0: diagonal * 1e-4
  bool allow_fill = true;       // step 2 (tests and the study turn it off to wrap)
};

// The options as the program's --repair, --repair-alpha A, --repair-offset D give them (and
// the Python module's repair, repair_alpha, repair_offset): std::invalid_argument with the
// program's message when alpha or offset is given without repair or is not a positive
// finite number.
MeshRepairOptions mesh_repair_options(bool repair, std::optional<double> alpha, std::optional<double> offset);

struct MeshRepair {
  TriangleMesh3 mesh;           // the repaired mesh (the input when nothing was needed)
  MeshDefects defects;          // of the input
  std::string method = "none";  // "none", "weld", "fill" or "alpha_wrap"
  double diagonal = 0, alpha = 0, offset = 0;  // alpha, offset: of the wrap (0 otherwise)
  std::size_t filled_holes = 0, added_triangles = 0;  // step 2
  std::size_t dropped_cavities = 0;  // step 3: enclosed shells of the wrap (artifacts), removed
  std::size_t repaired_shells = 0;
  // One-sided Hausdorff distances (the farthest point of one from the other), each within
  // hausdorff_error of the true value; hausdorff = the larger (two-sided). Input to
  // repaired is large where the wrap dropped parts of the input inside the solid (the
  // inner caps of overlapping shells); repaired to input is the wrap's own distance.
  double hausdorff = 0, input_to_repaired = 0, repaired_to_input = 0, hausdorff_error = 0;
  double repair_cpu_seconds = 0, hausdorff_cpu_seconds = 0;
};

// The steps above; returns the input unchanged (method "none") when it bounds a solid.
MeshRepair repair_mesh(const TriangleMesh3& mesh, const MeshRepairOptions& options = {});

// require_closed_manifold (mesh_checks.h); when it refuses, the refusal names the file and
// the first problem as before, then lists the census and says that --repair exists.
void require_solid(const TriangleMesh3& mesh);

// {"method", "defects": {...}, "alpha", "offset", "diagonal", "filled_holes",
//  "added_triangles", "vertices", "triangles", "shells", "hausdorff": {"distance",
//  "error_bound", "method"}, "repair_cpu_seconds", "hausdorff_cpu_seconds"}.
nlohmann::json mesh_repair_json(const MeshRepair& repair);
// One line: "repaired by alpha_wrap (alpha 0.01, offset 0.0003): 2 self-intersecting
// pairs; 4210 vertices, 8416 triangles, 1 shell; Hausdorff 0.0031 (+- 1e-05)".
std::string describe_repair(const MeshRepair& repair);

// The CGAL steps (mesh_repair_cgal.cpp). fill_holes: step 2, false when the soup cannot be
// oriented into a mesh; alpha_wrap: step 3; hausdorff_distance: the one-sided bounded-error
// distance from a to b (the farthest point of a from b), zero-area triangles left out.
bool fill_holes(const TriangleMesh3& mesh, TriangleMesh3& filled, std::size_t& holes);
TriangleMesh3 alpha_wrap(const TriangleMesh3& mesh, double alpha, double offset);
double hausdorff_distance(const TriangleMesh3& a, const TriangleMesh3& b, double error_bound);

}  // namespace grassfire
