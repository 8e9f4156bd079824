// prune3d.h -- the 3D pruning pipeline: input -> medial complex -> burning field -> the axis
// pruned by ET and ST thresholds (curves3/axis_pruning3.h).
//
// Computes what `grassfire prune3d` computes and what the Python module's grassfire.prune3d
// returns (both call prune3d() below): the complex and burning field an input names by a
// method (pipeline/burn3d_field.h; default the exact engine), the point times BT at the
// vertices and the side times BT_t at every triangle's corners (BurningField::
// vertex_burn_time, sample_in_triangle), the thresholds (ET absolute, or relative to the
// largest R of the axis; ST in [0, 1]), the pruned complex, validated as a MedialComplex,
// and the report `prune3d --json` writes (format grassfire-pruned3d, version 1):
//   {"format", "version", "input", "method", "spacing",
//    "thresholds": {"et": T (absolute) | null, "st": S | null, "relative": bool, "max_R"},
//    "axis": {"vertices", "edges", "triangles", "segments", "betti": [b0, b1, b2]},
//    "refined": {"vertices", "edges", "triangles", "cut_points", "failing_vertices",
//                "failing_edges", "failing_triangles"},
//    "removed": {"vertices", "edges", "triangles"},
//    "pruned": {"vertices", "edges", "triangles", "segments", "betti", "kept_failing":
//               {"vertices", "edges", "triangles"}},
//    "uncertified": n | null (discrete: nothing certified),
//    "seconds": {"burning", "pruning"},
//    "vertex_values": {"x", "y", "z", "R", "BT", "ET", "on" ("vertex" | "edge" |
//                      "triangle"), "cell"}, "triangles": [[i, j, k]], "segments": [[i, j]]}
// with null for BT and ET where nothing burns. Vertex coordinates are the nearest doubles
// of the exact points (the --complex output has them exactly).
// Progress: the field's stages (pipeline/burn3d_field.h), then "pruning" (support/progress.h).
// Contract: errors are exceptions naming the input and the problem (std::invalid_argument
// for bad thresholds, method or spacing); nothing is returned then.
// Complexity: the field's, then that of prune_axis3.
// Section: 3.4.1, 3.5.1, ch. 4, 5.1.2.
#pragma once

#include <gmpxx.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>

#include "curves3/axis_pruning3.h"
#include "pipeline/burn3d_field.h"

namespace grassfire {

struct Prune3dSetup {
  FieldSetup field;                  // method "exact" unless set
  std::optional<mpq_class> erosion;  // ET threshold T (a fraction of the largest R if relative)
  std::optional<mpq_class> tubularity;
  bool relative = false;
};

struct Prune3dRun {
  FieldRun field;
  PruningThresholds3 thresholds;  // absolute
  PrunedAxis3 pruned;
  std::unique_ptr<MedialComplex> pruned_complex;  // validated
  nlohmann::json report;
};

Prune3dSetup default_prune3d_setup();  // field.method = "exact", field.command = "prune3d"
Prune3dRun prune3d(const Prune3dSetup& setup);

}  // namespace grassfire
