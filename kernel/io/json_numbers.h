// json_numbers.h -- numbers of the project's JSON documents: a finite double as itself, any
// other (inf: an unburned or unbounded value) as null, as docs/formats.md says.
// Contract: none. Complexity: O(1) per number.
#pragma once

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace grassfire {

inline nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

inline nlohmann::json finite_or_null(const std::vector<double>& values) {
  nlohmann::json a = nlohmann::json::array();
  for (double v : values) a.push_back(finite_or_null(v));
  return a;
}

}  // namespace grassfire
