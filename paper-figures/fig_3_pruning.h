// fig_3_pruning.h -- what Figs. 3.6 and 3.7 share: the pruning thresholds of 3.5.1 taken
// relative to the shape's size, a shape pruned with them, and the caption numbers.
#pragma once

#include <gmpxx.h>

#include <string>

#include "burn2/axis_pruning.h"
#include "fig_3_panels.h"
#include "render/svg_pruned2.h"

namespace grassfire::figures {

// "0.05 of the dimension of the shape" (3.5.1) is 0.05 of shape_dimension (geometry2/shape2.h:
// the larger side of the bounding box), as `grassfire prune2d --relative` takes it.

// The ST threshold of Figs. 3.6 (e) and 3.7: 3/10, just above 1 - 1/sqrt(2) ~ 0.2929, the
// ST all along a branch into a right-angled corner, so that such branches are removed.
const mpq_class& tubularity_threshold();

// T = relative_et * shape_dimension, rounded to 1e-6 so that the threshold is a short
// rational (the printed value), S as given.
PruningThresholds relative_thresholds(const Shape2& shape, double relative_et, const mpq_class& st, bool topology);

struct PrunedShape {
  PruningThresholds thresholds;
  PrunedAxis axis;
  PruningSummary summary;
};
PrunedShape prune_shape(const Chapter3Shape& s, const PruningThresholds& t);

// "kept 6.29 of 29.4 (21%), 3 edges, 1 component" (the axis' components when `with_axis`).
std::string kept_summary(const PruningSummary& s, bool with_axis);

// A pruned panel of `s` drawn at (x, y, w, h).
void pruned_panel(SvgCanvas& c, double x, double y, double w, double h, const Chapter3Shape& s,
                  const PrunedShape& p, const Pruned2SvgOptions& o);

}  // namespace grassfire::figures
