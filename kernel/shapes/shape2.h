// shape2.h -- a planar shape: an outer boundary ring and zero or more hole rings.
//
// Contract of a validated Shape2 (shapes/validate_shape.h): every ring has at least 3
// distinct vertices, no repeated closing vertex, is simple (no two edges meet except
// consecutive edges at their shared vertex), no two rings meet, every hole lies inside
// the outer ring and outside every other hole; the outer ring is counter-clockwise and
// holes are clockwise (the interior is on the left of every edge).
#pragma once

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

}  // namespace grassfire
