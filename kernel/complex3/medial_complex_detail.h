// medial_complex_detail.h -- a piece shared by the translation units of MedialComplex
// (construction and validate()); not part of its interface.
//
// SheetPlanarity decides whether every vertex of a sheet lies in the plane of the sheet's
// first triangle (Sheet::planar): the orientation of each distinct vertex against that
// plane, filtered, exact where the filter cannot decide (every vertex of a planar sheet).
// Complexity: O(corners of the sheet) index work, one filtered predicate per distinct
// vertex, stopping at the first vertex off the plane.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry3/filtered_predicates3.h"
#include "complex3/medial_complex.h"

namespace grassfire {

class SheetPlanarity {
 public:
  SheetPlanarity(const FilteredPoints& points, const std::vector<ComplexTriangle>& triangles)
      : points_(points), triangles_(triangles), seen_(points.size(), 0) {}

  bool planar(const Sheet& s) {
    ++round_;
    const auto& t0 = triangles_[s.triangles.front()].v;
    const FilteredPlane plane(points_, t0[0], t0[1], t0[2]);
    for (std::uint32_t t : s.triangles)
      for (std::uint32_t v : triangles_[t].v) {
        if (seen_[v] == round_) continue;
        seen_[v] = round_;
        if (plane.side(v) != 0) return false;
      }
    return true;
  }

 private:
  const FilteredPoints& points_;
  const std::vector<ComplexTriangle>& triangles_;
  std::vector<std::uint64_t> seen_;  // the round (sheet test) that last saw each vertex
  std::uint64_t round_ = 0;
};

}  // namespace grassfire
