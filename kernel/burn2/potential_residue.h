// potential_residue.h -- the potential residue PR of Ogniewicz and Ilg (1992), the
// measure the dissertation compares the EDF with (3.4.2, Fig. 3.5, Fig. 3.8).
//
// Computes: PR(x) = the shortest distance along the shape boundary between the two
// boundary points closest to x (burn2/closest_points.h): min(|s - t|, L - |s - t|) for arc
// lengths s, t on a ring of length L. Points whose generators lie on different rings
// have PR = infinity (no boundary path joins them; PR is defined for simply connected
// shapes).
//  - Along an edge the generators are the edge's two closest points: fixed on a sampled
//    axis (PR constant on the edge), moving on an exact polygon axis. There |s - t| is
//    monotone along the edge (each foot moves monotonically and the feet never meet inside
//    an edge), so PR rises to its largest possible value L / 2 inside the edge exactly when
//    |s - t| - L / 2 changes sign between the ends: a peak.
//  - At a node with three or more closest points PR is discontinuous (3.4.2). We define
//    PR(node) = the largest of the limits of PR along its incident edges (the branch whose
//    generators are farthest apart along the boundary), which makes PR upper
//    semicontinuous like the EDF; a node without edges takes the largest pairwise value.
//  - The PR maximum: the point where PR is largest (a peak, else a node; ties to the
//    smallest id), with its two closest boundary points (the crosses of Fig. 3.5). On a
//    sampled axis, whose PR is constant on edges, it is an end of the best edge.
//  - local_maxima: the number of local maximum regions (a peak, or a connected plateau of
//    nodes and constant edges with no higher point next to it); Ogniewicz and Ilg's
//    uniqueness claim says 1 on a simply connected shape.
// Certification: values are enclosures, plus the exact value: a number of sample spacings
// on a sampled axis, a sum of square roots on a polygon axis where the node's circle is exact;
// comparisons use the enclosures, then the exact values; undecided ones count as equal
// and are counted.
// Contract: cp = closest_points(g, ...) with has_arc_length. Complexity: O(n + m) plus the
// exact work on near-ties.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "burn2/closest_points.h"
#include "medial2/medial_graph.h"

namespace grassfire {

struct ResidueValue {
  Interval value;                  // the infinite interval for generators on different rings
  std::optional<ExactSum> exact;   // polygon axis, when the closest points are exact
  // Sampled axis: PR = steps L / m exactly on `ring` (m samples, perimeter L); -1 otherwise.
  std::int64_t sample_steps = -1;
  std::uint32_t ring = 0;
};

struct EdgeResidue {
  ResidueValue at_u, at_v;  // limits at the two ends
  bool peak = false;        // PR reaches L / 2 strictly inside the edge
  Interval peak_fraction;   // where, as a fraction of the way from u to v (linear model)
};

struct ResidueMaximum {
  bool at_node = true;
  std::uint32_t node = 0;           // at_node
  std::uint32_t edge = 0;           // !at_node: a peak inside this edge
  Interval fraction;                //   at this fraction from edge.u
  Point2 position;                  // for drawing (inside a parabolic arc: approximate)
  ResidueValue value;
  std::array<Point2, 2> closest{};  // its two closest boundary points
};

struct PotentialResidue {
  std::vector<ResidueValue> node;
  std::vector<EdgeResidue> edge;
  ResidueMaximum maximum;
  std::uint32_t local_maxima = 0;
  std::uint64_t undecided = 0;  // comparisons left undecided (treated as equal)
};

PotentialResidue potential_residue(const MedialGraph& g, const ClosestPoints& cp);

// Monotonicity of PR from the ends inward (3.4.2): on a tree, every path from a leaf to the
// PR maximum should see PR never decrease. Counts the decreases inside edges and at
// degree-2 nodes ("away from junctions"), and separately at junctions, with the largest
// drop of each kind.
struct ResidueMonotonicity {
  std::uint64_t edges_checked = 0, regular_nodes = 0, junctions = 0;
  std::uint64_t edge_decreases = 0, regular_decreases = 0, junction_decreases = 0;
  double worst_regular_drop = 0, worst_junction_drop = 0;
};
ResidueMonotonicity residue_monotonicity(const MedialGraph& g, const PotentialResidue& pr);

}  // namespace grassfire
