// ball_set.h -- a finite set of balls in R^3 (a union-of-balls shape), as read from ball
// lists `x y z w` with w the squared radius (CGAL's weighted points; kernel/io/mesh_io.h).
// Centres and squared radii are exact rationals (the decimals read, exactly), so the
// union-of-balls builder can compute its power diagram exactly; `approx_*` are the nearest
// doubles. Readers guarantee w > 0 and finite values.
#pragma once

#include <gmpxx.h>

#include <array>
#include <string>
#include <vector>

#include "geometry3/exact_point3.h"

namespace grassfire {

struct BallSet {
  std::string source;
  std::vector<ExactPoint3> centers;
  std::vector<mpq_class> squared_radii;
  std::vector<std::array<double, 3>> approx_centers;
  std::vector<double> approx_radii;
};

}  // namespace grassfire
