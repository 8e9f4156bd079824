// junction_tangents.h -- a structural proof that a switch point of the junction rule is a
// tangent handover: the two fronts realising the (k-1)-th arrival A on either side agree to
// first order there, so A is differentiable at the switch (no corner: neither a kink nor a
// quench nor a merge; 4.2.1, Definition 9; docs/exact-engine.md, junction_points.h).
//
// Computes, for two windows a and b of one triangle t (the records realising A just below
// and just above a switch point p of a singular edge, so a(p) = b(p) = A(p) by continuity),
// whether the point window b (source S_b, offset sigma_b) is proved to start on a's front:
// sigma_b = a(S_b), with a's time function taken over the whole plane of t's frame.
// Why that decides the switch: a's time has a unit gradient (a point window sigma + |X - S|,
// or a plane wave c + u.X with |u| = 1: plane_wave_in_frame gives u = s e + sqrt(1 - s^2) n
// with e, n orthonormal), so a is 1-Lipschitz and b(X) = a(S_b) + |X - S_b| >= a(X) on the
// whole plane, with equality on the ray from S_b along grad a (Huygens: b is the circle
// that a's front throws around S_b). With b(p) = a(p), p minimises b - a, so grad b(p) =
// grad a(p) (both smooth at p: the caller has p != S_b from b's certified slope): the
// slopes along the edge are equal, A is C^1 at p.
// The proof of sigma_b = a(S_b) is structural, on the expression of sigma_b (TimeExpr):
//  - a Min is proved when both terms are (each equal to a(S_b), so is their minimum);
//  - WindowAt(w, Q), Q the source point of b (a vertex or an edge point): w is an ancestor
//    of a, or of the same front (Certifier::front_id) as one in the same frame, and b's
//    source image reaches t by the same unfoldings as a's front from w (equal crossing lists:
//    edge, triangle entered, triangle left), starting in w's frame: then S_b is the image of
//    Q by the isometry that carries w's function to a's, and a(S_b) = w(Q);
//  - WindowAt(w, Q) at a kink's edge point Q that is a certified crossing of w and w2
//    (EdgePoint::equal_windows: Q is defined as the only root of w - w2 in its bracket, so
//    w(Q) = w2(Q)): proved when the term WindowAt(w2, Q) is;
//  - at a vertex Q that ends the border edge of a's plane wave, with a reaching t from its
//    root by the same unfoldings as b from its root (both roots in one frame): a(S_b) =
//    sqrt(R^2(Q)) (plane_wave_in_frame matches the ignition at both ends), and a term is
//    proved when it is exactly sqrt(R^2(Q)) (an exact expression, compared in the field of
//    square roots) or the value at Q of a plane wave whose border edge ends at Q, seen in its
//    root's frame.
// Anything else is not proved (false): the switch stays unclassified, never guessed.
// Contract: a, b windows of one triangle; eb has run. Complexity: O(depth of a's and b's
// chains x size of sigma_b's expression) plus O(1) exact comparisons of sums of square roots.
#pragma once

#include <cstdint>

#include "burn3/exact/exact_burning.h"

namespace grassfire {

// True when b is a point window whose offset is proved equal to a's time at b's source
// (then b >= a on t's plane, touching along a ray: a tangent handover wherever b(p) = a(p)).
bool starts_on_front(ExactBurning& eb, std::uint32_t a, std::uint32_t b);
// The same during the propagation (the crossings' isolation: then b - a >= 0 has no sign change).
bool starts_on_front(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t a, std::uint32_t b);

}  // namespace grassfire
