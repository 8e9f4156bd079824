// vec3.h -- small double-precision vector helpers for drawing, sampling and approximate
// (baseline) computations on medial complexes. Never used for combinatorial decisions of
// exact geometry (those go through exact_predicates3.h).
#pragma once

#include <array>
#include <cmath>

namespace grassfire {

// A point or vector of R^3 in doubles (drawing, sampling, approximate baselines).
using Vec3d = std::array<double, 3>;

}  // namespace grassfire

namespace grassfire::v3 {

inline Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3d add(const Vec3d& a, const Vec3d& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3d scale(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }
inline double dist(const Vec3d& a, const Vec3d& b) { return norm(sub(a, b)); }
// (1 - s) a + s b
inline Vec3d lerp(const Vec3d& a, const Vec3d& b, double s) {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}
// a / |a|, or zero for the zero vector.
inline Vec3d unit(const Vec3d& a) {
  const double n = norm(a);
  return n > 0 ? scale(a, 1 / n) : Vec3d{0, 0, 0};
}

}  // namespace grassfire::v3
