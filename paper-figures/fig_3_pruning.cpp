// fig_3_pruning.cpp -- see fig_3_pruning.h.
#include "fig_3_pruning.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grassfire::figures {

const mpq_class& tubularity_threshold() {
  static const mpq_class s(3, 10);
  return s;
}

PruningThresholds relative_thresholds(const Shape2& shape, double relative_et, const mpq_class& st, bool topology) {
  PruningThresholds t;
  t.erosion = mpq_class(static_cast<long>(std::lround(relative_et * shape_dimension(shape) * 1e6)), 1000000);
  t.erosion.canonicalize();
  t.tubularity = st;
  t.topology = topology;
  return t;
}

PrunedShape prune_shape(const Chapter3Shape& s, const PruningThresholds& t) {
  PrunedShape p;
  p.thresholds = t;
  p.axis = prune_axis(*s.result.graph, *s.result.burning, t);
  p.summary = pruning_summary(*s.result.graph, p.axis);
  return p;
}

std::string kept_summary(const PruningSummary& s, bool with_axis) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "kept %.3g of %.3g (%.0f%%), %zu edges, %llu component%s", s.kept_length.mid(),
                s.axis_length.mid(), 100 * s.kept_fraction(), s.kept_edges,
                static_cast<unsigned long long>(s.kept_components), s.kept_components == 1 ? "" : "s");
  std::string out = buf;
  if (with_axis)
    out += " (axis: " + std::to_string(s.axis_edges) + " edges, " + std::to_string(s.axis_components) +
           (s.axis_components == 1 ? " component)" : " components)");
  return out;
}

void pruned_panel(SvgCanvas& c, double x, double y, double w, double h, const Chapter3Shape& s,
                  const PrunedShape& p, const Pruned2SvgOptions& o) {
  draw_pruned2(c, x, y, w, h, s.shape, *s.result.graph, *s.result.burning, s.result.measures, p.axis, o);
}

}  // namespace grassfire::figures
