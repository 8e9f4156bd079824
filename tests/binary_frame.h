// The binary frame of a test polygon (the binary policy of medial2/polygon/polygon_axis.h):
// its sites scaled by 2^K, K = minus the smallest lowest-set-bit exponent of its
// coordinates, so that every coordinate is an exact integer.
#pragma once

#include <algorithm>
#include <cmath>

#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/segment_voronoi.h"

namespace grassfire::testing {

inline PolygonSites binary_frame(const Shape2& s) {
  int low = 1 << 20;
  for (const Ring& r : s.rings)
    for (const Point2& p : r.points)
      for (double x : {p.x, p.y})
        if (x != 0) low = std::min(low, lowest_bit_exponent(x));
  return make_sites(s, std::ldexp(1.0, -low));
}

}  // namespace grassfire::testing
