// burning_state.h -- the extended grassfire frozen at a time t (3.3.1, Fig. 3.2).
//
// Computes: from a finished burning (the per-edge fire entry times and the event log of
// burn2/extended_grassfire.h), what the fire looks like at time t:
//  - the burnt part of every edge: a point x is burnt iff EDF(x) <= t (3.3.1: the EDF is
//    the time at which x burns). Along an edge e = (u, v) of length w the EDF is
//    min(Tu + s, Tv + w - s) over the ends that sent fire into e (Tu, Tv their send times),
//    so the burnt set is [0, t - Tu] from u and [0, t - Tv] from v, clipped to the edge;
//  - the burnt nodes (EDF(v) <= t);
//  - the fire fronts: a front sent into e from u at Tu sits at distance t - Tu from u,
//    moving towards v, for Tu <= t < T_stop, where T_stop is its arrival at v, Tu + w,
//    when v never sent fire into e, and the quench time (Tu + Tv + w) / 2 otherwise. The
//    half-open interval puts a front that reaches a node at t on the next edge (or nowhere,
//    when it annihilates or quenches), never on both;
//  - the events of the log (ignition, annihilation, quench) that happened at or before t.
// Exactness: every comparison of t with a burn, arrival or quench time is certified: the
// interval filter, then the exact sign of (time - t) with t taken as the rational value
// of the double (number/exact_sum.h). Lengths and offsets are certified enclosures.
// The time of an annihilation is not stored in the log; the k-th annihilation at a node j
// in the log (certified time order) happened at the k-th earliest arrival of a front at j
// (an edge into which the other end sent fire and j did not), because arrivals at j are
// processed in time order and the first ones to come while two or more edges are
// unarrived annihilate.
// Contract: `burning` is an Exact-variant result computed on `g` (the Dissertation variant
// keeps no event log); std::invalid_argument otherwise. t may be any finite double.
// Complexity: O(n + m + k) plus the exact work on near-ties, for k events; the arrivals at
// a node are sorted only when one of its annihilations is a near-tie with t.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "burn2/extended_grassfire.h"

namespace grassfire {

// The burnt part of one edge: [0, from_u] measured from u and [0, from_v] measured from
// v (enclosures, each in [0, length]); `whole` when the two cover the edge.
struct EdgeBurning {
  Interval from_u{0.0};
  Interval from_v{0.0};
  bool whole = false;
};

// A fire front on `edge`, at distance `offset` from `from`, moving away from `from`.
struct FireFront {
  std::uint32_t edge = 0;
  std::uint32_t from = 0;
  TimeId sent = kNoTime;  // when `from` sent fire into the edge; offset = t - sent
  Interval offset;
};

struct BurningState {
  double time = 0;
  std::vector<EdgeBurning> edges;   // per edge
  std::vector<bool> node_burnt;     // per node
  std::vector<FireFront> fronts;    // in edge order
  std::vector<std::size_t> events;  // indices into GrassfireResult::events, time <= t

  // Enclosure of the total burnt length of the edges.
  Interval burnt_length(const MedialGraph& g) const;
};

BurningState burning_state_at(const MedialGraph& g, const GrassfireResult& burning, double t);

}  // namespace grassfire
