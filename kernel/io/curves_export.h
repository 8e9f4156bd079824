// curves_export.h -- medial curve graphs (curves3/medial_curves.h) as JSON and polylines.
//
// JSON, format "grassfire-curves3d", version 1 (later versions add members, never remove
// or change one):
//   {"format": "grassfire-curves3d", "version": 1, "input": NAME, "method": FIELD,
//    "nodes": [{"x", "y", "z", "R", "bt", "et"}, ...],        node id = array index
//    "edges": [{"u", "v", "length", "kind"}, ...],            kind: "end" (a raw end,
//             medial_curves.h step 1) | "join" (kept to connect, or a dangling segment)
//    "betti": [b0, b1],                                     of the graph
//    "axis_betti": [b0, b1, b2],                            of the axis (simplicial homology)
//    "options": {"arrive_cosine", "depart_cosine", "time_margin", "min_et_fraction"}, "stats": {refinement and construction counts, seconds},
//    "analysis": {"planar_tubularity", "planar_area", "tubular_area", "tubular_curve_length",
//                 "planar_curve_length", "sheet_areas": [...], "curve_lengths": [...]}}
// (curves3/shape_analysis.h: the split of 5.3 and the signature; lists sorted descending).
// "bt" and "et" are null where the point never burns (BT = infinity); R is exact at the
// axis' vertices and interpolated linearly elsewhere; numbers are doubles.
// Polylines: each edge a 2-point line; scalars R, BT, ET per node (polyline_export.h).
//
// Burning paths (curves3/burning_paths.h), format "grassfire-paths3d", version 1:
//   {"format": "grassfire-paths3d", "version": 1, "input": NAME, "method": FIELD,
//    "from": "vertices" | "curves" | "ends" | "points",
//    "paths": [{"bt", "length", "points": [[x, y, z], ...]}, ...]}
// points[0] is the point the path leads to, the last point where its fire started; "bt"
// is null where the point never burns (then the path is that point alone). Polylines: one
// line per path of two or more points, with the scalar BT along it (BT at the path's end
// minus the arclength walked back: the time the fire passed each point).

#include <nlohmann/json.hpp>

#include <string>

#include "curves3/burning_paths.h"
#include "curves3/medial_curves.h"
#include "curves3/shape_analysis.h"
#include "io/polyline_export.h"

namespace grassfire {

nlohmann::json medial_curves_json(const MedialCurves& curves, const std::string& input);
nlohmann::json shape_analysis_json(const ShapeAnalysis& analysis, double planar_tubularity);
PolylineSet medial_curves_polylines(const MedialCurves& curves);

nlohmann::json burning_paths_json(const std::vector<BurningPath>& paths, const std::string& input,
                                  const std::string& method, const std::string& from);
PolylineSet burning_paths_polylines(const std::vector<BurningPath>& paths);


}  // namespace grassfire
