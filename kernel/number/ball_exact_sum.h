// ball_exact_sum.h -- Arb balls of sums of square roots (ExactSum).
//
// Computes: the ball enclosing an ExactSum without certified constants at the current
// BallPrecision (rationals: ball_of(mpq_class) in number/ball.h). Used by the exact burning
// engine (kernel/burn3/exact/) to re-evaluate an unfolding chain from its exact data at
// rising precision (docs/design.md 3).
// Contract: the sum carries no certified constants (std::invalid_argument).
// Complexity: O(M(p)) per term at p bits.
#pragma once

#include "number/ball.h"
#include "number/exact_sum.h"

namespace grassfire {

Ball ball_of(const ExactSum& s);

}  // namespace grassfire
