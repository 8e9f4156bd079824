// polygon_axis_symmetry.h -- exact symmetries of a polygon, local congruences of its
// site configurations, and the value classes they induce on its exact medial axis:
// nodes with provably equal R, edges with provably equal lengths (burn2/burn_times.h
// cancels them without building exact forms).
//
// Computes: (1) the isometries phi(X) = A X + t, A one of the seven non-identity signed
// permutation matrices (the lattice symmetries: reflections in axis-parallel and
// diagonal lines, rotations by 90, 180, 270 degrees), that map the polygon onto itself:
// every vertex to a vertex (phi fixes the centroid, so t = c - A c), every segment site
// to a segment site. (2) The image of every node's circle and every edge under each
// such phi, and the classes of the atoms joined by these maps (union-find, the smallest
// id represents a class).
// Why equal classes are equal values: R at a node and the length of an edge are values
// of the formulas of voronoi_circle.cpp at the node's representative circle (kind,
// sites in roles, root) and, for an edge, its two end circles and its two sites
// (polygon_axis_geometry.cpp). Those formulas are equivariant: solving the circle of the
// mapped configuration gives phi of the solved circle, as real numbers, once the roles
// and the root are mapped as follows (A reverses orientation when det A = -1, and then
// the left normal of a mapped segment is A n, the direction along it -A d):
//   PPP, SSS: any order (the circumcircle, the unique solution of a linear system);
//   PSS: the formula is symmetric in L1, L2 and the root (+1 the larger R) is a choice
//        between the two radii, which phi preserves;
//   PPS (P, Q, L, root): kept when det A = 1; (Q, P, L, root) when det A = -1 (the
//        bisector direction d = rot90(Q - P) maps to -A d, which flips the root's sign,
//        and swapping P and Q flips it back); PPS-linear: P and Q in any order;
//   PSS-parallel (P, L1, L2): kept when det A = 1; (P, L2, L1) when det A = -1.
// An edge's length (|X_u - X_v|, or the parabolic arc |S(xi_v) - S(xi_u)| with S odd and
// xi -> -xi when det A = -1) is invariant once its end circles and sites are mapped. So a
// node w whose circle is, under these rules, the image of node u's has R(w) = R(u), and
// an edge between the images of an edge's ends, separating the images of its two sites,
// has the same length. w is found by the canonical key of the image circle (a key names
// a value: it only applies swaps the formulas are symmetric under) among the
// representative circles and their aliases (circles of a contracted group proved to
// have the same centre and R, polygon_axis.cpp). A degenerate vertex that phi maps onto
// itself is often split by Boost into triples whose images are other triples of the
// same sites; then w is the node whose site set is the image of u's, and its circle is
// proved to be the image circle c by uniqueness: w's circle touches all of w's sites,
// so it is one of the circles tangent to c's three sites, of which there is one (PPP,
// SSS, PPS-linear, or a point site on a segment site's line) or two, c and the other
// root, whose centre enclosure must then be disjoint from w's (is_circle_of).
// (3) Local congruence (polygon_axis_congruence.cpp): the same equivariance, applied to
// one atom at a time. The configuration behind R at a node is its circle's sites in
// roles: points, and segment sites as their lines oriented with the interior on the left
// (primitive direction d and cross(d, p) for a point p of the line; the values depend on
// the lines only, so the segments of one straight run are one line); behind an edge's
// length, its two end circles (any of a contracted group's aliases) and, for an arc, its
// focus and directrix. Under each of the eight signed permutations A the configuration is
// mapped (a reflection runs a segment end -> start and maps roles and roots as above),
// put in the order its formula is symmetric under (by coordinates; the root is dropped
// and the roles sorted when at most one circle meets the conditions, voronoi_circle.h),
// and translated so that its least point site (least segment end if none) is the origin;
// the least of these is the atom's key. Equal keys mean an isometry X -> A X + t maps
// one configuration onto the other, so the values are equal. Every apex has R = 0 (one
// class). Only atoms whose enclosure overlaps one of another class get a key. Generic smooth polygons with integer vertices have many
// such local mirror images (three consecutive segments symmetric about the middle
// one's bisector), whose burn times tie exactly; without the keys each tie would reach
// the exact stage with transcendental or nested-radical constants.
// Nothing here relies on the Voronoi topology being right: only on the formulas and on
// exact predicates (contractions, orientation) and certified enclosures.
// Contract: nodes and edges come from exact_polygon_axis on `sites`. Frames whose
// coordinates are not all integers below 2^31 (the CGAL path on arbitrary doubles) get
// no symmetries: every atom is then its own class.
// Complexity: O(n) expected (hash maps) for n sites, nodes and edges (the keys: 8 maps
// per node, 16 per edge, more for contracted groups).
#pragma once

#include <array>
#include <cstdint>
#include <algorithm>
#include <unordered_map>
#include <vector>

#include "medial2/polygon/polygon_axis_geometry.h"
#include "support/union_find.h"

namespace grassfire {

// The roles of a circle's sites under an isometry (voronoi_circle.h roles): a reflection
// exchanges the two points of a PPS circle (P, Q keep the segment on the same side only
// in the other order) and the two parallel lines of a PSS-parallel circle.
template <class T>
void reflect_roles(CircleKind kind, std::array<T, 3>& s) {
  if (kind == CircleKind::PPS || kind == CircleKind::PPSLinear) std::swap(s[0], s[1]);
  if (kind == CircleKind::PSSParallel) std::swap(s[1], s[2]);
}

// Puts the roles the circle's formula is symmetric in into sorted order and returns the
// root that names the same circle (PPS: exchanging P and Q flips the root's sign); kinds
// with one circle per set of conditions get root 0. `unique`: at most one circle meets
// the conditions, so the root is no part of the value and is dropped, and the two lines of
// a PSS-parallel circle are symmetric too. For Apex only s[0] is a role.
template <class T>
int canonical_roles(CircleKind kind, int root, std::array<T, 3>& s, bool unique) {
  switch (kind) {
    case CircleKind::Apex: root = 0; break;
    case CircleKind::PPP:
    case CircleKind::SSS:
      std::sort(s.begin(), s.end());
      root = 0;
      break;
    case CircleKind::PSS:
      if (s[2] < s[1]) std::swap(s[1], s[2]);
      break;
    case CircleKind::PPS:
      if (s[1] < s[0]) {
        std::swap(s[0], s[1]);
        root = -root;
      }
      break;
    case CircleKind::PPSLinear:
      if (s[1] < s[0]) std::swap(s[0], s[1]);
      root = 0;
      break;
    case CircleKind::PSSParallel:
      if (unique && s[2] < s[1]) std::swap(s[1], s[2]);
      root = 0;
      break;
  }
  return unique ? 0 : root;
}

struct PolygonSymmetry {
  int a00 = 1, a01 = 0, a10 = 0, a11 = 1;  // the linear part A
  long long tx = 0, ty = 0;                // the translation t
  bool reverses = false;                   // det A = -1
  std::vector<std::uint32_t> vertex;       // vertex i maps to vertex[i]
};

// The non-identity lattice symmetries of the polygon (at most seven).
std::vector<PolygonSymmetry> polygon_symmetries(const PolygonSites& sites);

struct AxisValueClasses {
  std::vector<std::uint32_t> node;  // radius class of every node (the smallest member id)
  std::vector<std::uint32_t> edge;  // length class of every edge
  std::uint32_t symmetries = 0;
  std::uint64_t nodes_in_shared_classes = 0, edges_in_shared_classes = 0;
  // Over all symmetries: nodes and edges whose image was not found (their classes miss
  // that member; values stay exact either way, the engine then builds exact forms).
  std::uint64_t unmapped_nodes = 0, unmapped_edges = 0;
  // Pairs of edges that meet at a degree-2 node and separate the same two conditions (a
  // point or a line; the segments of one straight run are one line): pieces of one
  // bisector, e.g. split where a collinear vertex's normal meets it. Their summed length
  // is the length of the curve between their far ends, which gets a key like an edge's;
  // by joined_key(e1, e2), the class of the sum (in the edge classes' id space).
  std::unordered_map<std::uint64_t, std::uint32_t> joined;
};

inline std::uint64_t joined_key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// A bisector run through a degree-2 node: edges `first` and `second` meeting at `middle`.
struct JoinedEdges {
  std::uint32_t first = 0, second = 0, middle = 0;
};

// For every site id: itself for a point site; for a segment site, the first segment of
// the straight run it lies in (consecutive segments through vertices where the boundary
// goes straight on): one line, one tangency condition.
std::vector<std::uint32_t> conditions_of_sites(const PolygonSites& sites);

// The joinable pairs (see AxisValueClasses::joined).
std::vector<JoinedEdges> joinable_edges(const PolygonSites& sites, const std::vector<AxisNodeData>& nodes,
                                        const std::vector<AxisEdgeData>& edges);

// Unites congruent atoms (3): equal keys. Integer frames only (otherwise nothing).
// edge_uf has one element per edge and then one per joined pair (in `joined` order).
void unite_congruent_atoms(const PolygonSites& sites, const std::vector<AxisNodeData>& nodes,
                           const std::vector<AxisEdgeData>& edges, const std::vector<JoinedEdges>& joined,
                           UnionFind& node_uf, UnionFind& edge_uf);

// Classes from (1) and (3) together (union-find: the transitive closure of proved equalities).
AxisValueClasses axis_value_classes(const PolygonSites& sites, const std::vector<AxisNodeData>& nodes,
                                    const std::vector<AxisEdgeData>& edges);

}  // namespace grassfire
