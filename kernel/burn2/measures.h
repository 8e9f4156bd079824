// measures.h -- significance measures derived from the EDF at the nodes of a medial graph.
//
// Computes, per node: erosion thickness ET = EDF - R (3.4.1) and shape tubularity
// ST = 1 - R / EDF (3.5.1), as certified enclosures. Where the EDF is infinite (the
// 2-core, 3.1.2) ET is infinite and ST is exactly 1.
// Contract: `burning` was computed on `g`. Complexity: O(n).
#pragma once

#include <vector>

#include "burn2/extended_grassfire.h"

namespace grassfire {

struct NodeMeasures {
  std::vector<Interval> erosion_thickness;  // ET per node
  std::vector<Interval> tubularity;         // ST per node
};

NodeMeasures node_measures(const MedialGraph& g, const GrassfireResult& burning);

}  // namespace grassfire
