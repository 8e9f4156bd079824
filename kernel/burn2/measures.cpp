// measures.cpp -- see measures.h.
#include "burn2/measures.h"

namespace grassfire {

NodeMeasures node_measures(const MedialGraph& g, const GrassfireResult& burning) {
  NodeMeasures m;
  m.erosion_thickness.resize(g.node_count());
  m.tubularity.resize(g.node_count());
  const std::uint32_t n = g.node_count();
  for (std::uint32_t v = 0; v < n; ++v) {
    // The burn times are stored in burning order: prefetch the record read 8 nodes later.
    if (v + 8 < n && burning.burn[v + 8] != kNoTime) __builtin_prefetch(&burning.times.approx(burning.burn[v + 8]));
    if (burning.is_infinite(v)) {
      m.erosion_thickness[v] = Interval::infinity();
      m.tubularity[v] = Interval(1.0);
      continue;
    }
    const Interval edf = burning.edf(v), r = g.node(v).radius;
    m.erosion_thickness[v] = edf - r;
    // EDF >= R > 0 away from R = 0 leaves (Prop 1); at such leaves EDF = R = 0 and ST = 0.
    m.tubularity[v] = edf.lo > 0.0 ? Interval(1.0) - r / edf : Interval(0.0);
  }
  return m;
}

}  // namespace grassfire
