// medial2_json.h -- the JSON output of `grassfire edf2d` (format "grassfire-medial2d").
//
// Format, version 1 (documented in docs/formats.md; later versions add members, never remove
// or change one):
//   {"format": "grassfire-medial2d", "version": 1,
//    "shape": NAME, "variant": "exact"|"dissertation", "samples": N,
//    "nodes": [{"x", "y", "R", "edf", "et", "st"}, ...],       ids = array index
//    "edges": [{"u", "v", "length", "kind"}, ...],             kind: "segment"|"parabolic-arc"
//    "ema": {"kind": "point", "x", "y", "edf", "node": id}                 (at a node)
//         | {"kind": "point", "x", "y", "edf", "edge": id, "offset": s}   (s from edge.u)
//         | {"kind": "cycles", "nodes": [ids], "edges": [ids]}
//         | {"kind": "components", "parts": [one of the above per component]},
//    "error_bound": {"position", "R", "edf", "et", "st", "length", "ema", "pr"},
//    "certification": {filter/exact counters}}
// With a potential residue (burn2/potential_residue.h), also: per node "pr" (a number, or
// "inf" where the closest points lie on different rings), and at the top level
//    "pr_max": {"x", "y", "pr", "closest": [[x, y], [x, y]]}  (the PR maximum point).
// "edf" and "et" are the string "inf" where infinite. Every printed number is the
// midpoint of a certified enclosure; "error_bound" gives, per quantity, the largest
// distance from a printed value to the exact one ("position": node coordinates; "ema":
// the EMA's edf and offset; the EMA's x, y inside an edge are interpolated for display).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include <string>

#include "burn2/extended_grassfire.h"
#include "burn2/measures.h"
#include "burn2/potential_residue.h"

namespace grassfire {

struct Medial2dJsonInput {
  std::string shape_name;
  std::size_t samples = 0;
  const MedialGraph* graph = nullptr;
  const GrassfireResult* burning = nullptr;
  const NodeMeasures* measures = nullptr;
  const PotentialResidue* residue = nullptr;  // optional
  std::uint64_t voronoi_fallbacks = 0;        // exact polygon axis: diagrams rebuilt (polygon_axis.h)
};

std::string medial2d_json(const Medial2dJsonInput& in);

// A certified value as JSON: its midpoint, or "inf"; `bound` collects its error bound
// (radius). The 2D documents (grassfire-medial2d, grassfire-pruned2d) write values so.
nlohmann::ordered_json certified_json(const Interval& x, double& bound);

}  // namespace grassfire
