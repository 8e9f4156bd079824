// polygon_axis_geometry.h -- the exact values behind an exact polygon axis (see
// polygon_axis.h): R at nodes and edge lengths as ExactSums, built lazily.
//
// Computes, per node, the exact R of its Voronoi circle (voronoi_circle.h) scaled from
// the exact frame to input coordinates (a nested-radical PSS circle in its radical form,
// solve_radical); per edge, the exact length: for a straight edge
// sqrt(|X_u - X_v|^2) when both ends are sums of square roots (a rational square root,
// a denested root, or a constant identified by the exact squared length), a constant
// identified by the two circles otherwise; for a parabolic arc the closed-form length
// sigma (S(xi_v) - S(xi_u)) as two constants S[p;xi] (number/parabolic_arc.h) of the exact
// focal parameter and abscissas, so that arcs split differently telescope; a constant
// identified by the two circles when an end has no exact form. Constants evaluate in Arb
// at the requested precision. Identities built from site indices carry a token unique to
// the geometry (indices name values only inside one axis).
// Value classes: nodes and edges that an exact symmetry of the polygon maps onto each
// other (polygon_axis_symmetry.h), so that equal burn times cancel without exact forms.
// Also: rigorous double / Arb enclosures of lengths from circle values (used by the
// construction and the validation), and points along parabolic arcs for drawing.
// Contract: node and edge data come from exact_polygon_axis.
// Complexity: O(1) per value (Arb work grows with the precision asked for).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "medial2/medial_graph.h"
#include "medial2/polygon/voronoi_circle.h"

namespace grassfire {

struct AxisValueClasses;

struct AxisNodeData {
  VoronoiCircle circle;              // a representative circle of the contracted group
  std::vector<std::uint32_t> sites;  // every defining site of the group, sorted
  // The other circles of the group, when they are proved to have the representative's
  // centre and R exactly (polygon_axis.cpp); empty otherwise.
  std::vector<VoronoiCircle> aliases;
  bool all_aliased = true;  // every circle of the group is `circle` or in `aliases`
  Interval radius;          // encloses R in the frame
};

struct AxisEdgeData {
  std::uint32_t u = 0, v = 0;        // node ids (as in the graph)
  std::uint32_t site_a = 0, site_b = 0;
  bool parabolic = false;            // focus = the point site, directrix = the segment's line
  Interval length;                   // encloses the length in the frame
};

// A parabolic arc's length |S(xv) - S(xu)| (number/parabolic_arc.h) is a function of
// these three exact numbers.
struct ArcForm {
  ExactSum p, xu, xv;
};

// Length of an edge from its end circles, in the frame (T = Interval or Ball).
Interval edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Interval>& a,
                     const CircleValue<Interval>& b);
Ball edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Ball>& a,
                 const CircleValue<Ball>& b);
// From double-double circles (number/dd_ball.h): as tight as double endpoints allow
// when the circles are accurate, without Arb.
Interval edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<DDBall>& a,
                     const CircleValue<DDBall>& b);

class PolygonAxisGeometry : public MedialGeometry {
 public:
  PolygonAxisGeometry(std::shared_ptr<const PolygonSites> sites, mpq_class to_input,
                      std::vector<AxisNodeData> nodes, std::vector<AxisEdgeData> edges);

  ExactSum exact_radius(std::uint32_t node) const override;
  ExactSum exact_length(std::uint32_t edge) const override;
  // The burning engine's extended-precision and 128-bit stages (burn2/burn_times.h):
  // enclosures from the node circles evaluated once in double-double (R and straight
  // lengths at 80 bits) or in Arb at kBallBits, not from the exact forms (which are built
  // only when a comparison reaches the exact stage). Requests above 128 bits go to the
  // exact forms.
  void enclose_radius(std::uint32_t node, mpfr_ptr lo, mpfr_ptr hi) const override;
  void enclose_length(std::uint32_t edge, mpfr_ptr lo, mpfr_ptr hi) const override;
  LongInterval enclose_radius_long(std::uint32_t node) const override;
  LongInterval enclose_length_long(std::uint32_t edge) const override;
  // Classes of atoms with provably equal values under the polygon's exact symmetries
  // (medial2/polygon/polygon_axis_symmetry.h), computed on the first call.
  std::uint32_t radius_class(std::uint32_t node) const override;
  std::uint32_t length_class(std::uint32_t edge) const override;
  std::uint32_t joined_length_class(std::uint32_t first, std::uint32_t second) const override;
  const AxisValueClasses& value_classes() const;
  Point2 point_along(const MedialGraph& g, std::uint32_t edge, std::uint32_t from, double s) const override;
  std::vector<Point2> polyline(const MedialGraph& g, std::uint32_t edge) const override;
  std::string description() const override { return "exact polygon medial axis"; }

  const PolygonSites& sites() const { return *sites_; }
  const mpq_class& to_input() const { return to_input_; }
  const AxisNodeData& node_data(std::uint32_t i) const { return nodes_[i]; }
  const AxisEdgeData& edge_data(std::uint32_t e) const { return edges_[e]; }
  // Names the node's circle by its sites, prefixed with a token unique to this geometry
  // (indices name values only inside one axis: CertifiedConstant identities must be global).
  std::string node_identity(std::uint32_t i) const;
  // The node's circle as exact sums in the frame, or nullopt for a nested radical.
  const std::optional<CircleValue<ExactSum>>& exact_circle(std::uint32_t i) const;
  // exact_circle, or for a nested radical its form with square roots of sums
  // (voronoi_circle.h: solve_radical); nullopt when neither exists.
  const std::optional<CircleValue<ExactSum>>& radical_circle(std::uint32_t i) const;

 private:
  ExactSum frame_length(std::uint32_t edge) const;
  std::optional<ExactSum> straight_length(const AxisEdgeData& e, const CircleValue<ExactSum>& a,
                                          const CircleValue<ExactSum>& b) const;
  // The arc's focal parameter and its ends' abscissas, exactly (radical forms allowed), or
  // nullopt when an end circle has no exact form.
  std::optional<ArcForm> arc_form(const AxisEdgeData& e) const;
  static constexpr long kBallBits = 192;
  const CircleValue<Ball>& ball_circle(std::uint32_t i) const;  // kBallBits, memoised
  const CircleValue<DDBall>& dd_circle(std::uint32_t i) const;   // memoised
  DDBall scaled_to_input(const DDBall& frame_value) const;
  Ball ball_length(std::uint32_t edge) const;
  // lo <= frame_value * to_input <= hi, rounded outwards at the precision of lo and hi.
  void scaled_to_input(const Ball& frame_value, mpfr_ptr lo, mpfr_ptr hi) const;

  std::string identity_token_;  // prefixes identities built from site indices (see the .cpp)
  std::shared_ptr<const PolygonSites> sites_;
  mpq_class to_input_;
  std::vector<AxisNodeData> nodes_;
  std::vector<AxisEdgeData> edges_;
  // Memoised values, one pointer per node or edge (null: not computed yet), allocated when
  // asked for: the few that are (the engine's filters decide most comparisons) cost no
  // zeroed slot of their size for every node.
  mutable std::vector<std::unique_ptr<const std::optional<CircleValue<ExactSum>>>> circles_;
  mutable std::vector<std::unique_ptr<const std::optional<CircleValue<ExactSum>>>> radicals_;
  mutable std::vector<std::unique_ptr<const ExactSum>> lengths_;
  mutable std::vector<std::unique_ptr<const CircleValue<Ball>>> ball_circles_;
  mutable std::vector<std::unique_ptr<const CircleValue<DDBall>>> dd_circles_;
  mutable std::shared_ptr<const AxisValueClasses> classes_;
};

}  // namespace grassfire
