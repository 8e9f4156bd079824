// mesh_axis.h -- the medial axis of the solid bounded by a closed triangle mesh, with the
// solid's homotopy type checked exactly (2.1.2 in 3D).
//
// Computes, for a closed mesh M bounding the solid S (even-odd rule, mesh_solid.h):
//  1. the Betti numbers of S from the mesh alone (shells, genera, nesting);
//  2. samples of M at spacing h (mesh_samples.h), h = mean edge length / samples_per_edge;
//  3. the inner Voronoi complex V_in of the samples (inner_voronoi.h), which is homotopy
//     equivalent to the interior of the Delaunay cells with inner circumcentres;
//  4. the pruned axis: Voronoi faces of samples p, q whose angle at every vertex x,
//     angle(p x q), is below theta (and Voronoi edges of triangles pqr whose angles are all
//     below theta at both ends) are collapsed away while they have a free side
//     (axis_pruning.h), so the homotopy type of V_in is kept; angle(p x q) >= theta is the
//     exact rational test |p - q|^2 >= 2 (1 - cos theta) R(x)^2, R(x) = |x - p|, with
//     2 (1 - cos theta) taken as the rational value of its double;
//  5. its Betti numbers by exact simplicial homology (simplicial_homology.h) on the
//     triangulated axis. When they differ from S's, h is halved and steps 2-5 repeat, at
//     most max_refinements times; then, unless step 7 accepts a round, MeshAxisTopologyError
//     says what was reached. A wrong axis is never returned.
//  6. the thickness rule: the separation test (|p - q| >= lambda h) removes every face of a
//     part thinner than about lambda h / 2, so a coarse sampling of a thin part (a tripod's
//     arm, a cross's bar) prunes the part away and leaves the right Betti numbers on a
//     useless axis (a point). So once the Betti numbers are right, a triangle is refined
//     when its spacing exceeds 2 f / lambda, f the largest inner pole distance of its
//     samples (the half-thickness of the part it bounds), to spacing 2 rho f / lambda,
//     rho = feature_ratio (at most 4 times finer per round); and, since the samples
//     touching a wedge-shaped sheet of object angle alpha at depth R are only
//     2 R sin(alpha / 2) apart (the octahedron's sheets: 1.15 R, not 2 R), also when the
//     pruning left no polygon or segment at that deepest pole, to half its spacing (and
//     the triangles of the samples bounding the polygons at that pole too).
//     Steps 2-5 repeat until no triangle is too coarse, the next round would add under
//     min_thickness_growth (10%) samples, a round misses the solid's Betti numbers, or max_refinements or max_samples
//     is reached; the last round with the solid's Betti numbers is returned (axis_round;
//     later rounds are listed too). What is kept: a sheet survives where its touching
//     samples are >= lambda h apart, so the points of depth R >= lambda h are found and a
//     band along convex edges and corners (within about lambda h / sin(alpha / 2) of them)
//     is missing; tests/test_builders3_mesh_axis_convex.cpp checks this against the exact
//     convex axis (Hausdorff <= 2 lambda h on the cube, octahedron and random hulls).
//  7. the resolution rule (axis_resolution.h): a component of the pruned axis whose every
//     vertex x has R(x) < (lambda / 2) h (h the spacing of its samples) lies within that
//     distance of the surface, where the samples cannot certify depth; along a sharp wedge
//     (a filled hole meeting a thin cap, an alpha wrap's crease, a thin lens) such
//     components multiply as h shrinks, so the Betti rounds diverge. In a round with the
//     wrong Betti numbers they are counted, and the round is a candidate when the axis
//     without them has the solid's Betti numbers. The last candidate is accepted (its
//     unresolved components dropped) when the rounds show they do not converge: a Betti
//     round no closer to the solid's Betti numbers than the one before (the sum of the
//     differences), or the next round over max_samples or max_refinements. From then on
//     every round drops its unresolved components, the thickness rounds included. A
//     refinement that converges without it is run as before, so its axis is unchanged.
// Output: a RawComplex with exact rational vertices (the circumcentres, from the double
// samples; distinct because equal circumcentres are one Delaunay cell), exact R^2 (the
// squared circumradius), the Voronoi faces fanned into triangles (they are convex, and
// strictly so once equal circumcentres are one vertex), the remaining Voronoi edges as
// segments, and on every border edge the ignition R(x) = |x - p| (p a sample of the face).
// The complex is embedded: it is a subcomplex of the Voronoi diagram, triangulated inside
// its convex faces; nothing is rounded.
// Approximation (what is known; step 6 for what the pruning removes): for an epsilon-sample of a smooth surface, the Voronoi
// faces passing the angle test lie within O(epsilon) lfs of the medial axis and converge to
// it in Hausdorff distance as epsilon -> 0 (Dey-Zhao 2004, for theta fixed); every vertex x
// is the centre of an empty ball of radius R(x) through four samples. Mesh edges have lfs
// 0 and no theorem covers them; the error study (experiments/study_mesh_axis_sampling)
// measures the axis against itself and against known axes as h shrinks.
// Contract: a closed 2-manifold mesh (require_closed_manifold), shells disjoint.
// Complexity: per round, O(n log n) expected for n samples (the Delaunay triangulation),
// then linear work plus one exact locator query per Delaunay cell; the rounds grow n by
// about 4 each.
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "medial3/mesh/mesh_samples.h"
#include "medial3/mesh/mesh_solid.h"
#include "complex3/simplicial_homology.h"
#include "complex3/raw_complex.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

struct MeshAxisOptions {
  double samples_per_edge = 1;   // h = mean edge length / samples_per_edge
  int max_refinements = 5;       // halvings of h after the first round
  double angle_degrees = 0;      // theta of the pruning (0: no angle test)
  double separation = 2;         // lambda: pq must be >= lambda local spacings apart; 0: no test
  double feature_ratio = 0.5;    // refinement: spacing <= ratio * (pole distance) where refined;
                                 // thickness rule: spacing <= ratio * 2 (inner pole distance) / lambda,
                                 // halved where the deepest pole lost its sheets
  std::size_t max_samples = 2000000;  // per round (memory: about 2 GB per million samples); a round
                                      // needing more ends the thickness rounds, or, before the
                                      // solid's Betti numbers are reached, MeshAxisTopologyError
                                      // with every round's samples and Betti numbers and the
                                      // option's name (medial3d --max-samples)
  double min_thickness_growth = 0.10;  // a thickness round adding fewer samples (a fraction) is not run
  bool resolution_rule = true;         // step 7 (false: diverging rounds end in MeshAxisTopologyError)
};

struct MeshAxisRound {
  double spacing = 0, max_spacing = 0;  // the finest and the coarsest triangle's
  std::size_t samples = 0, tetrahedra = 0, cells = 0, inner_cells = 0;
  std::size_t interior_samples = 0;  // samples whose Voronoi cell is inside (inner_voronoi.h)
  std::size_t polygons = 0, segments = 0, kept_polygons = 0, kept_segments = 0;
  std::size_t coarse_triangles = 0;  // too coarse for the thickness rule (rounds with the right Betti numbers)
  BettiNumbers betti;                 // of the round's axis (without its unresolved components when resolution_rule)
  BettiNumbers all_components_betti;  // of every component of the pruned axis
  std::size_t unresolved_components = 0;  // below the sampling's resolution (axis_resolution.h; counted when
                                          // all_components_betti is not the solid's)
  bool resolution_rule = false;           // the round's axis is without them (step 7)
  double sample_seconds = 0, delaunay_seconds = 0, classify_seconds = 0, extract_seconds = 0, prune_seconds = 0,
         betti_seconds = 0, refine_seconds = 0;  // refine: the next spacing (thickness or Betti rule)
};

struct MeshAxis {
  RawComplex complex;
  SolidTopology solid;
  BettiNumbers axis_betti;
  std::vector<MeshAxisRound> rounds;  // every round run
  std::size_t axis_round = 0;         // the round whose axis is returned (the last with the solid's Betti numbers)
  SurfaceSamples samples;             // of that round
  std::size_t exact_locator_tests = 0;
  double check_seconds = 0;  // manifold check, solid topology and locator, before the rounds
  double assemble_seconds = 0, total_seconds = 0;
  int refinements() const { return static_cast<int>(rounds.size()) - 1; }
};

class MeshAxisTopologyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

MeshAxis mesh_medial_axis(const TriangleMesh3& mesh, const MeshAxisOptions& options = {});

nlohmann::json mesh_axis_json(const MeshAxis& axis);

}  // namespace grassfire
