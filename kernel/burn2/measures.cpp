// measures.cpp -- see measures.h.
#include "burn2/measures.h"

namespace grassfire {

NodeMeasures node_measures(const MedialGraph& g, const GrassfireResult& burning) {
  NodeMeasures m;
  m.erosion_thickness.resize(g.node_count());
  m.tubularity.resize(g.node_count());
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
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
