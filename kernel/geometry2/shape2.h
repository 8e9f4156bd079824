// shape2.h -- a planar shape: an outer boundary ring and zero or more hole rings.
//
// Contract of a validated Shape2 (shapes/validate_shape.h): every ring has at least 3
// distinct vertices, no repeated closing vertex, is simple (no two edges meet except
// consecutive edges at their shared vertex), no two rings meet, every hole lies inside
// the outer ring and outside every other hole; the outer ring is counter-clockwise and
// holes are clockwise (the interior is on the left of every edge).
#pragma once

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "geometry2/point2.h"

namespace grassfire {

struct Ring {
  std::vector<Point2> points;  // vertices in order; the closing edge is implicit
};

struct Shape2 {
  std::string name;          // file path or built-in name, used in messages
  std::vector<Ring> rings;   // rings[0] is the outer boundary, the rest are holes
};

// The larger side of the bounding box: "the dimension of the shape" that 3.5.1 scales the
// ET pruning threshold by (0.05 of it). A measurement in doubles; O(vertices).
inline double shape_dimension(const Shape2& shape) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const Ring& r : shape.rings)
    for (const Point2& p : r.points)
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  return std::max(x1 - x0, y1 - y0);
}

}  // namespace grassfire
