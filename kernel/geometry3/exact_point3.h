// exact_point3.h -- a point of R^3 with exact rational coordinates (gmpxx).
//
// The coordinate type of every exact 3D construction: the vertices of a RawComplex
// (complex3/raw_complex.h), the centres of a BallSet, the arguments of the exact
// predicates (exact_predicates3.h). Contract: none beyond finite rationals.
#pragma once

#include <gmpxx.h>

namespace grassfire {

struct ExactPoint3 {
  mpq_class x, y, z;
};

}  // namespace grassfire
