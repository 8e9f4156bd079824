// edf2d_json.h -- the "grassfire-medial2d" JSON of one run of the 2D pipeline.
//
// Computes: for a shape and the result of compute_edf2d on it, the document that
// `grassfire edf2d --json` writes (format: io/medial2_json.h, docs/formats.md): the medial
// graph, EDF, ET, ST, the EMA and, for polygon axes (sampled or exact), the potential
// residue PR with its maximum (burn2/potential_residue.h). The program and the Python
// module (grassfire.edf2d) both call this, so their outputs are the same document.
// Contract: `result` was computed from `shape` with `options`.
// Complexity: O(n log n) for the closest points of PR, O(n) for the document.
#pragma once

#include <string>

#include "pipeline/edf2d.h"

namespace grassfire {

std::string edf2d_json(const Shape2& shape, const Edf2dOptions& options, const Edf2dResult& result);

}  // namespace grassfire
