// parabolic_arc.h -- certified length of a parabolic arc (the focus-directrix bisector of
// a point site and a segment site, docs/exactness.md), and a rigorous double asinh.
//
// Computes: for a parabola with focal parameter p > 0 (distance from the focus to the
// directrix), parametrised by xi, the signed coordinate along the directrix measured
// from the foot of the focus, the arc-length primitive
//     S(xi) = (xi / 2) sqrt(1 + (xi/p)^2) + (p / 2) asinh(xi / p),
// so the arc between xi1 and xi2 has length |S(xi2) - S(xi1)| (closed form).
// Two evaluations: in double intervals (rigorous: asinh through log1p by an alternating-
// free atanh series with an explicit remainder bound, every operation outward rounded;
// no libm transcendental is trusted), and in Arb balls (ball.h) at any precision.
// And S(xi) as a certified constant of exact p and xi (arc_primitive_constant): an arc's
// length is then sigma (S(xi2) - S(xi1)), so arcs of one parabola split at different
// points telescope, and pieces of congruent parabolas cancel, exactly.
// Contract: p > 0 (intervals: p.lo > 0).
// Complexity: O(1) double operations (about 40), or O(M(bits)) in Arb.
#pragma once

#include <memory>

#include "number/ball.h"
#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

// Rigorous enclosures of log1p(w) for w >= 0 and of asinh(z) for any z.
Interval log1p_enclosure(const Interval& w);
Interval asinh_enclosure(const Interval& z);

Interval parabola_arc_primitive(const Interval& xi, const Interval& p);
Ball parabola_arc_primitive(const Ball& xi, const Ball& p);

// S(xi) at exact p > 0 and xi (sums that may hold square roots of sums: sqrt_field.h),
// evaluated in Arb from their MPFR enclosures. Identity "S[p;xi]" (equal strings, equal p
// and xi, equal values); equals() is true when p and xi are proved equal exactly (sign()
// of the differences, decided by root_separation.h), nullopt otherwise.
std::shared_ptr<const CertifiedConstant> arc_primitive_constant(ExactSum p, ExactSum xi);

}  // namespace grassfire
