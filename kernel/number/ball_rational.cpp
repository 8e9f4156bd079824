// ball_rational.cpp -- see ball_rational.h.
#include "number/ball_rational.h"

#include <flint/fmpq.h>

#include <stdexcept>

namespace grassfire {

Ball ball_of(const mpq_class& q) {
  Ball b;
  fmpq_t f;
  fmpq_init(f);
  fmpq_set_mpq(f, q.get_mpq_t());
  arb_set_fmpq(b.get(), f, BallPrecision::bits());
  fmpq_clear(f);
  return b;
}

Ball ball_of(const ExactSum& s) {
  if (!s.constant_terms().empty()) throw std::invalid_argument("ball_of: the sum has certified constants");
  Ball r = ball_of(s.rational_part());
  for (const SqrtTerm& t : s.sqrt_terms()) r += ball_of(t.coef) * sqrt(ball_of(t.radicand));
  return r;
}

}  // namespace grassfire
