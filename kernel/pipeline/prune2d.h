// prune2d.h -- the 2D pruning pipeline: shape -> medial axis -> EDF -> the axis pruned by ET
// and ST thresholds (burn2/axis_pruning.h, 3.5.1), and the "grassfire-pruned2d" JSON.
//
// Computes what `grassfire prune2d` computes and what the Python module's grassfire.prune2d
// returns (both call prune2d() below): the axis (sampled, or the exact polygon axis), its
// EDF (pipeline/edf2d.h), the thresholds (ET absolute, or a fraction of the shape's size,
// the larger side of its bounding box; ST in [0, 1]), the pruned graph, and the document:
//   {"format": "grassfire-pruned2d", "version": 1, "shape": NAME, "axis": "sampled"|"exact",
//    "thresholds": {"et": T (absolute), "st": S, "relative": bool, "size": D, "topology": bool},
//    "nodes": [{"x", "y", "R", "edf", "et", "st", "source": {"node": id} | {"edge": id, "offset": s}}],
//    "edges": [{"u", "v", "length", "kind", "source_edge", "from", "to"}],
//    "error_bound": {"position", "offset", "R", "edf", "et", "st", "length"}}
// Nodes and edges read like those of "grassfire-medial2d" (io/medial2_json.h): ids are array
// indices, "edf" and "et" are "inf" on the 2-core. A node comes from an original node, or is
// a cut point at distance "offset" from the source edge's end u; "from" and "to" delimit the
// kept stretch of the source edge the same way. R at cut points is linear along the edge (the
// piecewise-linear graph, burn2/axis_pruning.h); x, y of cut points are for drawing.
// Contract: a validated shape; thresholds >= 0, S <= 1 (std::invalid_argument otherwise).
// Complexity: that of compute_edf2d and prune_axis.
// Section: 3.5.1.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <string>

#include "burn2/axis_pruning.h"
#include "io/decimal_text.h"  // nearest_double
#include "pipeline/edf2d.h"

namespace grassfire {

struct Prune2dSetup {
  mpq_class erosion = 0, tubularity = 0;  // T (a fraction of the size if relative), S
  bool relative = false;
  bool topology = false;  // peel failing leaves only (3.3.2)
  Edf2dOptions options;
};

struct Prune2dRun {
  PruningThresholds thresholds;  // absolute
  double size = 0;
  Edf2dResult edf;
  PrunedAxis pruned;
  std::uint64_t components = 0;
  std::string json;  // the document above
};

Prune2dRun prune2d(const Shape2& shape, const Prune2dSetup& setup);

}  // namespace grassfire
