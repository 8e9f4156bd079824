// exact_burning_field.h -- the exact window-propagation engine as a BurningField
// (burning_field.h, "How an exact engine plugs in"; 4.2.3, 5.1.2; docs/exact-engine.md).
//
// Computes, from a finished ExactBurning and only its public API (windows, pseudo-sources,
// time expressions, certified queries):
//  - sample_in_triangle(t, p): p is first moved to the nearest point of closed t with
//    rational barycentric coordinates (the double barycentric coordinates, clamped to
//    [0, 1], taken exactly); BT_t(p) is the midpoint of ExactBurning::burn_time(t, p) (the
//    minimum over the windows that cover p, a certified enclosure); the path's last straight
//    piece is that of the window whose time at p is least: `from` is where the segment
//    S -> p (S the window's pseudo-source image, or for a plane wave the line back along
//    its direction u) enters closed t, the direction (p - from) / |p - from|;
//  - paths: the winning window's chain of parents walked backwards: in each triangle the
//    straight piece from the current point towards the pseudo-source's image until it
//    leaves the closed triangle (through the window's entry edge), then the parent window
//    in the triangle across that edge, down to the first window: at a border edge (the
//    path ends on the border, where the fire started at f), at a caller's point source, or
//    at a vertex source, where the path continues as the vertex's own: its time expression
//    (windows.h TimeExpr) says how the vertex burned (a window's arrival there, fire along a
//    segment from its other end, its ignition, the minimum of two); a pseudo-source of
//    another kind (a burned point of a singular edge, once the junction rule emits them)
//    continues the same way through its time expression;
//  - edge_points(e) = ceil(|e| / h) - 1 for the given spacing h (the resolution at which
//    medial curves are traced along edges; BT itself has no h), edge_point_burn_time the
//    engine's BT of the point itself (ExactBurning::burn_time(ComplexPoint): the min over
//    the edge's sides with walls, the junction rule once the engine applies Definition 9);
//  - resolution() = 0; method() says whether the engine burned the complex as
//    Definition 9 or with singular edges as walls (an upper bound, exact_engine_unsupported).
// Doubles are used only to draw the paths (the unfoldings' double images of each triangle's
// corners); no combinatorial decision of the engine is taken here. Ties between windows of
// equal time go to the first in the engine's order.
// Contract: `eb` has run and outlives this object; queries are not thread-safe (the
// engine's certifier keeps counters). Complexity: a sample O(windows of t); a path O(its
// windows + the vertices it passes).
#pragma once

#include <string>
#include <vector>

#include "burn3/burning_field.h"
#include "burn3/exact/exact_burning.h"

namespace grassfire {

class ExactBurningField final : public BurningField {
 public:
  // edge_spacing > 0: the spacing of edge_points (e.g. default_burn_spacing).
  ExactBurningField(ExactBurning& eb, double edge_spacing);

  const MedialComplex& complex() const override { return mc_; }
  std::string method() const override { return method_; }
  double resolution() const override { return 0.0; }

  double vertex_burn_time(std::uint32_t v) const override;
  std::uint32_t edge_points(std::uint32_t e) const override;
  double edge_point_burn_time(std::uint32_t e, std::uint32_t i) const override;

  FieldSample sample_in_triangle(std::uint32_t t, const Vec3d& p) const override;
  FieldSample sample_on_segment(std::uint32_t e, double s) const override;

  std::vector<Vec3d> path_in_triangle(std::uint32_t t, const Vec3d& p) const override;
  std::vector<Vec3d> path_on_segment(std::uint32_t e, double s) const override;
  std::vector<Vec3d> path_from_vertex(std::uint32_t v) const override;
  std::vector<Vec3d> path_from_edge_point(std::uint32_t e, std::uint32_t i) const override;

  // Whether the engine burned this complex as Definition 9 (else: walls, an upper bound).
  bool definition9() const { return definition9_; }
  // The point of closed t nearest to p in barycentric coordinates, exactly (see above).
  ExactPoint3 exact_point_in(std::uint32_t t, const Vec3d& p) const;
  // The point at parameter i / (edge_points(e) + 1) of edge e, exactly.
  ComplexPoint edge_complex_point(std::uint32_t e, std::uint32_t i) const;
  ExactBurning& engine() const { return eb_; }

 private:
  struct Frame2 {
    double x = 0.0, y = 0.0;
  };
  // The live window of t whose time at x is least (kNoIndex: none covers x).
  std::uint32_t best_window(std::uint32_t t, const Target& x) const;
  Frame2 to_frame(std::uint32_t t, const Vec3d& p) const;
  Vec3d from_frame(std::uint32_t t, const Frame2& q) const;
  // From p in w's triangle, back along w's burning path until it leaves the closed
  // triangle or reaches the pseudo-source image (3D).
  Vec3d back_step(std::uint32_t w, const Vec3d& p) const;
  void walk_window(std::uint32_t w, Vec3d at, std::vector<Vec3d>& path, int budget) const;
  void walk_time(std::uint32_t time, std::uint32_t vertex, std::vector<Vec3d>& path, int budget) const;
  void walk_vertex(std::uint32_t v, std::vector<Vec3d>& path, int budget) const;
  bool window_starts_at(std::uint32_t w, const Vec3d& p, const Vec3d& back) const;

  ExactBurning& eb_;
  const MedialComplex& mc_;
  double h_;
  bool definition9_;
  std::string method_;
};

}  // namespace grassfire
