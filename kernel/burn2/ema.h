// ema.h -- the extended medial axis from the outcome of a burning (Definition 4, Prop 3).
//
// Computes: per connected component, the EMA: the 2-core (the cycles, EDF infinite) when
// the component has one, else its single quench point with its EDF. Shared by both
// variants of extended_grassfire.
// Contract: `quenches` lists every quench of the burning; a tree component has exactly
// one (a counting argument: n nodes send fire into n - 1 edges with one meeting), and a
// component with cycles has none. Violations throw std::logic_error.
// Complexity: O(n + m).
#pragma once

#include <vector>

#include "burn2/extended_grassfire.h"

namespace grassfire {

struct QuenchRecord {
  GraphPoint place;
  Interval edf;
  TimeId sent_from = kNoTime;   // see ExtendedMedialAxis
  TimeId sent_other = kNoTime;
};

void assign_extended_medial_axis(const MedialGraph& g, GrassfireResult& result,
                                 const std::vector<QuenchRecord>& quenches);

}  // namespace grassfire
