// ball_exact_sum.cpp -- see ball_exact_sum.h.
#include "number/ball_exact_sum.h"

#include <stdexcept>

namespace grassfire {

Ball ball_of(const ExactSum& s) {
  if (!s.constant_terms().empty()) throw std::invalid_argument("ball_of: the sum has certified constants");
  Ball r = ball_of(s.rational_part());
  for (const SqrtTerm& t : s.sqrt_terms()) r += ball_of(t.coef) * sqrt(ball_of(t.radicand));
  return r;
}

}  // namespace grassfire
