// discrete_burning.h -- the discrete burning baseline on a medial complex (docs/design.md 5).
//
// Computes: an approximation of the burning time BT (Definitions 9-10, 4.2.3) at every
// vertex of a MedialComplex and at Steiner points placed on every edge at spacing <= h,
// and ET = BT - R per vertex; +infinity where nothing burns. It re-implements the idea
// of the authors' later erosion-thickness code (Yan et al. 2016): Dijkstra over vertices
// plus Steiner points, with sector bookkeeping at junctions.
//
// The rule (our discretisation of Definition 9; docs/design.md 5 gives the operational form):
//  * Graph: vertices, and n_e = ceil(|e| / h) - 1 equally spaced Steiner points inside
//    each edge e. Moves are straight segments: between consecutive points of one edge, and
//    across a triangle between a point of one of its edges and a point of another edge
//    (each move is a non-crossing curve of Definition 9: it lies in one closed triangle
//    and meets the singular set at most at its ends, or runs along an edge).
//  * An arrival at point x at time t through a link element: through a triangle, the
//    sector of x containing it (at an edge point: that triangle's arc); along an edge, the
//    direction of that edge (a pole if the edge is singular or dangling, else the sector
//    the edge lies in). Arrivals are processed in time order (Dijkstra).
//  * x burns at the first arrival after which its link, with all arrived elements removed,
//    has no cycle and at most one segment direction left (MedialComplex::link_burns). On a
//    singular curve with k sheets that is the (k-1)-th sector arrival or the first arrival
//    along the curve; in a manifold region, the first arrival. A border point (where the
//    condition holds before any arrival) also burns at f(x): BT = min(f, first arrival).
//    Each cycle of the link is a disk type of Definition 8, so "no cycle left" is "every
//    disk type has a burning path"; the segment clause is the 2D rule (3.3.1) for
//    1-dimensional parts (a three-segment junction burns at its second arrival).
//  * When x burns at time T it emits T + |x - y| to every graph neighbour y, through every
//    element (Definition 9 admits any non-crossing path ending at a burned point, whichever
//    sector it leaves into; fire re-entering an arrived sector cannot beat that sector's
//    own front, whose arrival was already <= T, by the 1-Lipschitz property, Prop. 4).
//
// Error behaviour (floating point is acceptable here: the baseline is approximate by
// construction). Every discrete BT is realised by polygonal non-crossing paths between
// burned points, so by Definition 9 and Lemma 2, by induction in the processing order,
// BT_discrete(x) >= BT(x) at every graph point, up to double rounding (relative 1e-15 per
// move). The excess comes from snapping the crossing points of a burning path to Steiner
// points: O(h^2 / l) per edge crossed where the path is straight (l = the local segment
// length), O(h) where it bends (around a vertex or into a singular curve), plus the
// sampling of f on border edges. On the board and fin the measured maximum error
// shrinks linearly in h (experiments/study_board_fin_convergence.cpp).
// Stated bounds: the construction gives no constant in general. On a planar convex sheet
// snapping the straight optimal path to graph points gives BT_h(x) <= BT(x) + 2 |y* y'| +
// 2 sum delta_i (foot y* moved to the nearest graph point y' of its edge, each edge
// crossing moved by delta_i <= h/2 to the nearest graph point; proofs-checks
// snapping_bound). On the reference cases the tests assert these stated constants, from
// which their tolerances are derived: BT_h - BT <= h/2 on the board and fin, <= 0.3 h on
// planar convex fans (random_planar_fan) and on books at h = 1/8; the first arrival of
// each sheet along the junction N of the board and fin <= its exact value + 0.75 h (the
// fin reaches N only from inside the fin, from Steiner points up to h above N).
// Mutation hook: options.rule_override (nullptr by default) replaces the link rule and the
// ignition times, so that proofs-checks can run the engine with a deliberately broken rule
// (a junction burning at its first or at its last sector arrival, a late ignition) and
// show that its checks detect it. The default path pays one pointer test per arrival.
// Contract: a validated MedialComplex; spacing h > 0 and the point budget respected.
// Complexity: O(N log N + sum over triangles of (points on its boundary)^2) with N graph
// points; memory O(N (2 + average edge degree)). BT at points that are not graph points:
// discrete_query.h.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"

namespace grassfire {

// The arrivals at a graph point when the link rule is evaluated, for a BurnRuleOverride.
struct LinkArrivals {
  std::size_t sectors = 0, sectors_arrived = 0;  // disk-type elements: sectors of a vertex, triangles at an edge point
  std::size_t poles = 0, poles_arrived = 0;      // segment directions
  bool junction = false;  // an edge point with three or more triangles, or a vertex of kind SingularCurve/SingularPoint
  bool rule = false;      // what the rule of this header decides
};

// A different burning rule (mutation tests of the proof checks; see the header comment).
class BurnRuleOverride {
 public:
  virtual ~BurnRuleOverride() = default;
  // Whether the point burns now, given its arrivals (called after every arrival).
  virtual bool burns(const LinkArrivals& a) const = 0;
  // The ignition time of a border graph point whose f is `f`.
  virtual double ignition(double f) const { return f; }
};

// The arrivals at vertex v (arrived: per link element) and at an interior point of an edge
// with `triangles` triangles.
LinkArrivals vertex_link_arrivals(const MedialComplex& mc, std::uint32_t v, const std::vector<bool>& arrived, bool rule);
LinkArrivals edge_link_arrivals(std::size_t triangles, bool pole0, bool pole1, std::size_t arcs, bool rule);

struct DiscreteBurningOptions {
  double spacing = 0.25;                   // h
  std::uint64_t max_points = 200'000'000;  // refuse (std::invalid_argument) above this
  const BurnRuleOverride* rule_override = nullptr;  // nullptr: the rule of this header
  // Points that ignite at their t0 (point_sources.h), besides the border. A source at a
  // vertex or exactly at a Steiner point ignites that graph point; a source inside an edge
  // or a triangle is joined by straight moves to the graph points of the closed triangles
  // that hold it (SteinerGraph::for_each_move_from_*_point), which it reaches at
  // t0 + distance through the link element of that move. Every such move is a
  // non-crossing segment, so the upper-bound argument above holds unchanged.
  std::vector<PointSource> sources{};
  // Called now and then during the run with (graph points burned, graph points in all).
  std::function<void(std::uint64_t, std::uint64_t)> progress{};
};

struct DiscreteBurningStats {
  std::uint64_t steiner_points = 0;
  std::uint64_t pushes = 0;
  std::uint64_t pops = 0;
  double seconds = 0.0;
};

class DiscreteBurning {
 public:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  double spacing = 0.0;
  std::vector<double> vertex_bt;  // per vertex
  std::vector<double> vertex_et;  // BT - R per vertex
  std::vector<double> steiner_bt;  // per Steiner point, edge by edge
  std::vector<std::uint64_t> edge_first_steiner;  // size edges + 1
  DiscreteBurningStats stats;

  std::uint32_t steiner_count(std::uint32_t e) const {
    return static_cast<std::uint32_t>(edge_first_steiner[e + 1] - edge_first_steiner[e]);
  }
  // BT at Steiner point i (1 <= i <= steiner_count(e)) of edge e, at parameter
  // s = i / (steiner_count(e) + 1) from e.v[0]; i = 0 and i = count + 1 are the vertices.
  double bt_on_edge(const MedialComplex& mc, std::uint32_t e, std::uint32_t i) const;
  static Vec3d point_on_edge(const MedialComplex& mc, std::uint32_t e, double s);

  // First arrival times through the link elements (kInfinity if none before burning):
  // at vertex v, per element of mc.link_elements(v); at a Steiner point of edge e, the
  // direction towards e.v[0], towards e.v[1], then one per triangle of edge_triangles(e).
  std::vector<double> vertex_arrivals(std::uint32_t v) const;
  std::vector<double> steiner_arrivals(const MedialComplex& mc, std::uint32_t e, std::uint32_t i) const;

  // Slot layout of the arrival times (first arrival per link element, kInfinity if none
  // before the point burned): vertex v owns slots [vertex_slot[v], vertex_slot[v + 1]);
  // Steiner point i of edge e owns 2 + k slots from edge_slot[e] + (i - 1) (2 + k),
  // k = edge_triangles(e).size().
  std::vector<double> arrival_time;
  std::vector<std::uint64_t> vertex_slot;
  std::vector<std::uint64_t> edge_slot;

  // Burning paths (burning_field.h): per slot, the graph point whose move gave the slot's
  // recorded arrival (kNoIndex when arrival_time is kInfinity); per graph point (vertices,
  // then Steiner points edge by edge), the local slot of the arrival that burned it, or
  // kIgnited when it burned at its own ignition f (a border point, or a source at the
  // point), kNoIndex if never. An arrival carried from point source i straight to a graph
  // point records kFromSource + i (its position: source_points[i]).
  // Following arrival_from[slot(x, burn_slot[x])] from x back to an ignited point is the
  // discrete burning path of x (a polygonal non-crossing path, Definition 9).
  static constexpr std::uint32_t kIgnited = std::numeric_limits<std::uint32_t>::max() - 1;
  static constexpr std::uint32_t kFromSource = 0x80000000u;  // graph points stay below 2^31
  std::vector<Vec3d> source_points;
  std::vector<std::uint32_t> arrival_from;
  std::vector<std::uint32_t> burn_slot;
};

DiscreteBurning burn_discrete(const MedialComplex& mc, const DiscreteBurningOptions& options);

}  // namespace grassfire
