// ball_rational.h -- Arb balls of exact rationals and of sums of square roots.
//
// Computes: the ball enclosing an mpq_class (exact when the denominator is a power of two
// and the precision suffices, else one rounding) and an ExactSum without constants, at
// the current BallPrecision. Used by the exact burning engine (kernel/burn3/exact/) to
// re-evaluate an unfolding chain from its exact data at rising precision (DESIGN.md 3).
// Contract: ExactSum arguments carry no certified constants (std::invalid_argument).
// Complexity: O(M(p)) per term at p bits.
#pragma once

#include <gmpxx.h>

#include "number/ball.h"
#include "number/exact_sum.h"

namespace grassfire {

Ball ball_of(const mpq_class& q);
Ball ball_of(const ExactSum& s);

}  // namespace grassfire
