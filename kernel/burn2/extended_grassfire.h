// extended_grassfire.h -- the extended grassfire transform on a medial graph (3.3).
//
// Computes: the extended distance function EDF (3.1.2, Definition 3) at every node, its
// piecewise-linear form along every edge, the extended medial axis EMA (Definition 4),
// and the log of burning events, by the arrival-ordered event simulation of docs/design.md 4:
// each leaf z ignites at R(z); fire runs along edges at unit speed; a node burns when at
// most one incident edge is still unarrived, and fire continues into that edge; fronts
// arriving while two or more edges are unarrived annihilate; two fronts on one edge
// quench at distance (w + Tj - Ti)/2 from i. What never burns (the 2-core) has EDF =
// infinity and is the EMA; otherwise the EMA is the single last quench point.
//
// The variant Dissertation is the thinning algorithm of 3.3.2: it removes the leaf of
// smallest value and gives the exposed neighbour value + edge length. It orders by the
// leaf's value rather than by arrival time and can differ from the definition (see
// tests/test_dissertation_variant.cpp for a constructed case and the measured bound).
//
// Certification: every order decision is a BurnTimes::compare (interval filter, then
// exact). Ties in the event queue are broken by the rank (time, kind, node, edge), which
// is deterministic; exact ties change no EDF value (a node that receives its last two
// fronts at the same time burns at that time either way), and the quench point is
// normalised to a node exactly when it lies on one.
// Contract: a validated MedialGraph. Components are burnt independently; the EMA is
// reported per component.
// Complexity: O((n + m) log(n + m)) comparisons.
#pragma once

#include <cstdint>
#include <vector>

#include "burn2/burn_times.h"
#include "medial2/medial_graph.h"

namespace grassfire {

enum class GrassfireVariant { Exact, Dissertation };
const char* to_string(GrassfireVariant v);

// A point of the graph: a node, or the point at distance `offset` from `from` along `edge`.
struct GraphPoint {
  bool at_node = true;
  std::uint32_t node = 0;  // valid when at_node
  std::uint32_t edge = 0;  // valid when !at_node
  std::uint32_t from = 0;  // end of `edge` the offset is measured from
  Interval offset;         // certified enclosure, strictly inside (0, length)
};

enum class BurnEventType { Ignite, Annihilate, Quench };
const char* to_string(BurnEventType t);

struct BurnEvent {
  BurnEventType type;
  Interval time;
  GraphPoint place;
  // The exact time: a burn-time record for events at nodes; kNoTime for a quench inside
  // an edge, whose time is (from_u + from_v + length) / 2 of that edge (see event_time).
  TimeId time_id = kNoTime;
};

// Fire entering an edge: the time its end node burnt and sent fire into it (kNoTime if
// that end never sent fire into it).
struct EdgeFire {
  TimeId from_u = kNoTime;
  TimeId from_v = kNoTime;
};

struct ExtendedMedialAxis {
  enum class Kind { Point, Cycles } kind = Kind::Point;
  std::uint32_t component = 0;
  GraphPoint point;                    // Kind::Point
  Interval edf;                        // Kind::Point: EDF at the point
  // Kind::Point inside an edge: the times at which point.from and the other end sent
  // fire into the edge; offset = (w + other - from) / 2, EDF = (from + other + w) / 2.
  TimeId sent_from = kNoTime;
  TimeId sent_other = kNoTime;
  std::vector<std::uint32_t> nodes;    // Kind::Cycles: the 2-core of the component
  std::vector<std::uint32_t> edges;
};

struct GrassfireResult {
  GrassfireVariant variant = GrassfireVariant::Exact;
  BurnTimes times;
  std::vector<TimeId> burn;        // per node; kNoTime where the EDF is infinite
  std::vector<EdgeFire> fire;      // per edge
  std::vector<BurnEvent> events;   // in certified time order, ties by processing order (Exact variant)
  std::vector<ExtendedMedialAxis> ema;  // one per connected component
  std::uint64_t queue_ties = 0;    // exactly equal times met in the event queue

  explicit GrassfireResult(const MedialGraph& g) : times(g) {}
  bool is_infinite(std::uint32_t node) const { return burn[node] == kNoTime; }
  // Enclosure of the EDF at a node (the infinite interval where it is infinite).
  Interval edf(std::uint32_t node) const;
  // Enclosure of the EDF at distance s (a double in [0, length]) from `from` along an edge.
  Interval edf_along(std::uint32_t edge, std::uint32_t from, double s) const;
  const NumberStats& stats() const { return times.stats(); }
};

GrassfireResult extended_grassfire(const MedialGraph& g, GrassfireVariant variant = GrassfireVariant::Exact);

// The exact time of a logged event, as a sum of the graph's atoms.
GraphSum event_time(const GrassfireResult& r, const BurnEvent& e);

// Position of a graph point (drawing and reports).
Point2 position_of(const MedialGraph& g, const GraphPoint& p);

}  // namespace grassfire
