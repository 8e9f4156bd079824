// match2d.h -- boundary correspondence of two planar shapes guided by a boundary signature
// (3.5.3, Fig. 3.9e), and the "grassfire-match2d" JSON.
//
// Computes what `grassfire match2d` computes and what the Python module's grassfire.match2d
// returns (both call match2d() below): N boundary samples per shape with their signature
// (boundary eccentricity BE, local feature size on the exact polygon axis, or curvature;
// apps2d/boundary_matching.h), the dynamic-programming match and the correspondence, and
//   {"format": "grassfire-match2d", "version": 1, "a": NAME, "b": NAME,
//    "signature": "be"|"lfs"|"curvature", "samples": N, "stretch": S,
//    "cost": C, "offset": O, "stretch_steps": K,
//    "a_samples": [{"x", "y", "value"}...], "b_samples": [...],
//    "path": [[i, j], ...],            // sample i of a corresponds to sample j of b
//    "correspondence": [j_0, ..., j_{N-1}]}  // the first j matched to each i
// Values are the raw signatures; the matching compares them divided by their maxima.
// Contract: validated shapes; N in [8, 2000], S >= 0, a known signature
// (std::invalid_argument otherwise).
// Complexity: O(N^3) for the DP, plus the signatures' axes.
// Section: 3.5.3.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps2d/boundary_matching.h"
#include "geometry2/shape2.h"

namespace grassfire {

struct Match2dSetup {
  std::string signature = "be";
  std::size_t samples = 200;
  double stretch = 0.05;
};

struct Match2dRun {
  BoundarySignature a, b;
  BoundaryMatch match;
  std::vector<std::uint32_t> correspondence;
  std::string json;  // the document above
};

Match2dRun match2d(const Shape2& a, const Shape2& b, const Match2dSetup& setup);

}  // namespace grassfire
