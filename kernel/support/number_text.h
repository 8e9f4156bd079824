// number_text.h -- doubles printed so that they read back exactly.
//
// Computes: the shortest decimal text that converts back to exactly x (std::to_chars),
// e.g. "0.31466", "1e-300", "inf". The one printer of doubles for every writer (shapes,
// meshes, complexes) and message. Complexity: O(1).
#pragma once

#include <string>

namespace grassfire {

std::string shortest_double(double x);

}  // namespace grassfire
