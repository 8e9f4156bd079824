// unfolding.h -- the planar frames in which the exact burning engine lays out triangles,
// and the rigid motions that unfold one triangle onto the plane of its neighbour.
//
// Computes, for a MedialComplex:
//  - per triangle t, its frame: one exact PlanarFrame per coplanar patch (the components of
//    the triangles joined across manifold edges whose two triangles are coplanar, decided
//    exactly: a planar sheet is one patch, a flat region of a curved mesh too, so that fire
//    crossing it needs no unfolding), orthonormalised: a point with exact local coordinates
//    (u, v) has frame coordinates (u sqrt g1, v sqrt g2), g = |e|^2;
//  - the images of t's corners in its frame, three ways: double discs (certified radius,
//    from Interval arithmetic on the exact data), Arb balls at the current BallPrecision,
//    and exact rational local coordinates (u, v) with the frame's Gram diagonal (g1, g2)
//    (docs/design.md 5a: inside one planar frame everything stays rational);
//  - the unfolding across an edge from triangle t to triangle t2 (both on the edge): the
//    rigid motion of the plane of t's frame onto t2's frame that fixes the edge pointwise
//    and puts t on the side of the edge opposite t2 (a rotation, or a reflection where the
//    two frames are oriented differently). Identity when t and t2 share a frame.
//    In exact local coordinates it is rational up to one square root, sqrt(h_t^2 / h_t2^2)
//    (the ratio of the triangles' heights over the edge; docs/design.md 5a), rational itself
//    when the heights are equal (a cube's faces): exact_crossing() gives it, for the exact
//    stage of the certification.
// Why orthonormalised doubles: rigid motions keep discs discs (number/disc_point.h).
// Contract: t2 != t share edge e; a validated MedialComplex.
// Complexity: construction O(T) interval operations (every manifold crossing whose
// frames differ is computed once); Ball and exact queries O(1) GMP/Arb operations
// (exact local coordinates are cached per frame and vertex).
// Section: docs/design.md 5 and 5a.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "complex3/medial_complex.h"
#include "number/ball.h"
#include "number/disc_point.h"

namespace grassfire {

struct BallVec2 {
  Ball x, y;
};

struct BallMotion {
  Ball r00, r01, r10, r11, t0, t1;
  BallVec2 apply(const BallVec2& p) const;
  BallVec2 apply_vector(const BallVec2& p) const;
};

class Unfolding {
 public:
  explicit Unfolding(const MedialComplex& mc);

  const MedialComplex& complex() const { return mc_; }
  std::uint32_t frame(std::uint32_t t) const { return triangle_frame_[t]; }
  // Whether frame f is a planar sheet's frame (shared by all its triangles).
  bool shared_frame(std::uint32_t f) const { return shared_[f]; }
  // +1 when t's vertices v[0], v[1], v[2] turn counter-clockwise in its frame, else -1.
  int orientation(std::uint32_t t) const { return orientation_[t]; }
  // +1 when t's third vertex lies left of the directed edge e.v[0] -> e.v[1] in t's frame.
  int edge_side(std::uint32_t e, std::uint32_t t) const;

  // The image of corner i (vertex triangle(t).v[i]) of t in t's frame.
  const DiscPoint& corner(std::uint32_t t, int i) const { return corners_[3 * t + i]; }
  DiscPoint vertex_image(std::uint32_t t, std::uint32_t v) const;

  // The unfolding from t onto t2 across their common edge e (identity if same frame).
  const RigidMotion2& crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const;
  bool same_frame(std::uint32_t t, std::uint32_t t2) const { return triangle_frame_[t] == triangle_frame_[t2]; }

  // Arb versions at the current BallPrecision, from the exact data.
  BallVec2 vertex_ball(std::uint32_t t, std::uint32_t v) const;
  BallVec2 point_ball(std::uint32_t t, const ExactPoint3& p) const;  // p in t's plane
  // point_ball of the point a + l (b - a) of edge (a, b) of t (the same ball: the frame's
  // dot products are affine in l, their two rational coefficients cached per frame and edge).
  BallVec2 edge_param_ball(std::uint32_t t, std::uint32_t edge, const mpq_class& l) const;
  BallMotion crossing_ball(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const;
  // 1 / sqrt(g1), 1 / sqrt(g2) of t's frame as balls: frame coordinates = local * sqrt(g).
  std::array<Ball, 2> frame_scale_ball(std::uint32_t t) const;

  // Exact rational local coordinates (u, v) of a vertex in frame f, and the frame's Gram
  // diagonal: |p - q|^2 = g1 du^2 + g2 dv^2.
  const std::array<mpq_class, 2>& vertex_uv(std::uint32_t f, std::uint32_t v) const;
  std::array<mpq_class, 2> point_uv(std::uint32_t f, const ExactPoint3& p) const;
  const mpq_class& g1(std::uint32_t f) const { return planar_frame(f).e1_norm2; }
  const mpq_class& g2(std::uint32_t f) const { return planar_frame(f).e2_norm2; }
  std::size_t frame_count() const { return frames_.size(); }
  // The exact frame f (the frame of its patch's first triangle; built on first use for
  // one-triangle patches, whose double data come from interval arithmetic directly).
  const PlanarFrame& planar_frame(std::uint32_t f) const;

  // The crossing in exact local coordinates: X' = P(X) + k beta(X) w with P affine and
  // beta an affine functional, both rational, w rational and k = -sqrt(kk), kk rational
  // (the crossing's one generator, docs/design.md 5a); cached.
  struct ExactCrossing {
    mpq_class p00, p01, p10, p11, p0, p1;  // P(X) = [p00 p01; p10 p11] X + (p0, p1)
    mpq_class b0, b1, bc;                  // beta(X) = b0 x + b1 y + bc
    mpq_class w0, w1, kk;
  };
  const ExactCrossing& exact_crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const;

  // Interval enclosure of a vertex's coordinates.
  const std::array<Interval, 3>& vertex_interval(std::uint32_t v) const { return vertex_iv_[v]; }

  // Double images of an exact point in t's plane.
  DiscPoint point_image(std::uint32_t t, const ExactPoint3& p) const;

 private:
  void build_patches();
  void compute_corners();
  void compute_crossings();
  RigidMotion2 compute_crossing(std::uint32_t e, std::uint32_t t, std::uint32_t t2) const;
  int exact_orientation(std::uint32_t t) const;

  const MedialComplex& mc_;
  mutable std::vector<std::unique_ptr<PlanarFrame>> frames_;
  std::vector<std::uint32_t> frame_triangle_;  // the triangle whose frame_of_triangle it is
  std::vector<std::uint32_t> triangle_frame_;
  std::vector<bool> shared_;
  std::vector<int> orientation_;
  std::vector<DiscPoint> corners_;
  // Interval data: per vertex its coordinates, per frame origin, e1 / sqrt g1, e2 / sqrt g2.
  std::vector<std::array<Interval, 3>> vertex_iv_;
  struct FrameIv {
    std::array<Interval, 3> origin, a1, a2;
  };
  std::vector<FrameIv> frame_iv_;
  // Crossings across manifold edges whose frames differ: 3 per triangle (edge slot i).
  std::vector<RigidMotion2> crossing_;
  std::vector<bool> has_crossing_;
  mutable std::unordered_map<std::uint64_t, RigidMotion2> other_crossings_;
  mutable std::unordered_map<std::uint64_t, std::array<mpq_class, 2>> uv_cache_;
  mutable std::unordered_map<std::uint64_t, std::array<mpq_class, 4>> edge_dots_;  // (frame, edge)
  mutable std::unordered_map<std::uint64_t, std::unique_ptr<ExactCrossing>> exact_crossings_;
  // Arb data per precision (bits -> key -> value): crossings by (t, t2), vertex images by
  // (frame, vertex).
  mutable std::unordered_map<long, std::unordered_map<std::uint64_t, BallMotion>> ball_crossings_;
  mutable std::unordered_map<long, std::unordered_map<std::uint64_t, BallVec2>> ball_vertices_;
  mutable std::unordered_map<long, std::unordered_map<std::uint32_t, std::array<Ball, 2>>> ball_scales_;  // bits -> frame
};

}  // namespace grassfire
