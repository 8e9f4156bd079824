// exact_burning.h -- the burning time BT on a medial complex by exact window propagation
// (4.2.3, Definitions 9-10; 5.2 "sweep-event engine"; docs/design.md 5, 5a; docs/exact-engine.md).
//
// Computes BT as an exact piecewise function: per triangle, the windows that can realise
// it (each a pseudo-source image, an offset and a wedge; windows.h), built by
// WindowPropagation from point sources and the border ignition rules, with the junction
// rule of Definition 9 on singular edges (edge_junction.cpp: the (k-1)-th arrival, pieces
// rotated into the other sheet sides, kinks as point sources) and the link rule at vertices
// on singular curves, singular points and segment ends (vertex_burning.cpp); or with
// singular edges as walls when ExactBurningOptions::singular_walls asks. From it:
//  - burn_time(t, x): a certified enclosure of BT at a point of a triangle (the minimum of
//    the enclosures of every window whose closed wedge contains x; membership certified
//    by Certifier::side, and an undecided membership widens the upper end by twice the
//    certified distance to the wedge ray, which keeps the enclosure rigorous because BT
//    and each window's time are 1-Lipschitz there);
//  - exact_burn_time(t, x): BT as an exact sum of square roots where every candidate
//    window is exact (planar sheets with rational sources; ties proved exactly), else none;
//  - per-vertex values (BT and ET = BT - R, +infinity where nothing burns);
//  - counts of windows, events and certification stages.
// Contract: a validated MedialComplex that outlives this object; sources added before
// run(); queries after run(). Points given to queries lie in the closed triangle
// (std::invalid_argument otherwise, checked exactly).
// Complexity: see window_propagation.h; a query costs O(windows of the triangle).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "burn3/exact/window_propagation.h"
#include "complex3/point_location.h"

namespace grassfire {

struct QueryCounts {
  std::uint64_t queries = 0;
  std::uint64_t candidates = 0;  // windows tested
  std::uint64_t widened = 0;     // memberships no stage decided (enclosure widened)
};

// What the engine cannot burn as Definition 9 asks, or none. Since docs/exact-engine.md nothing
// structural: every validated complex (singular edges and points included) is burned; kept
// for callers that ask (sources inside segments are refused by add_point_source instead).
std::optional<std::string> exact_engine_unsupported(const MedialComplex& mc);

class ExactBurning {
 public:
  explicit ExactBurning(const MedialComplex& mc, const ExactBurningOptions& o = {});
  ~ExactBurning();

  void add_point_source(std::uint32_t triangle, const ExactPoint3& point, const mpq_class& start);
  // A source located by complex3/point_location.h: at a vertex (any vertex, also one
  // with no triangle), inside an edge with triangles, or inside a triangle. A point inside
  // a segment is refused (std::invalid_argument): fire on segments is derived from their
  // ends only (the 2D rule), so the engine has no source kind there.
  void add_point_source(const ComplexPoint& x, const mpq_class& start);
  void add_border_ignition();
  void run();

  Interval burn_time(std::uint32_t t, const Target& x);
  Interval burn_time(std::uint32_t t, const ExactPoint3& x) { return burn_time(t, Target{kNoIndex, &x}); }
  std::optional<ExactSum> exact_burn_time(std::uint32_t t, const ExactPoint3& x);
  Interval vertex_burn_time(std::uint32_t v);
  // BT at the point (1 - s) v0 + s v1 of a segment (dangling edge), 0 <= s <= 1: fire runs
  // along it from its burned ends (the 2D rule, 3.3.1).
  Interval segment_burn_time(std::uint32_t e, const mpq_class& s);
  // BT at a point inside edge e (exact, on the edge): the minimum over its triangles'
  // closures on a manifold or border edge; on a singular edge with k sides the (k-1)-th
  // smallest of them (the junction rule: each side's value is its own arrival or the
  // curve's emission, whichever is earlier).
  Interval edge_burn_time(std::uint32_t e, const ExactPoint3& x);
  // BT at a located point (vertex, edge, triangle; any edge stratum): the minimum over the
  // closed cells that contain it (edge_burn_time inside edges).
  Interval burn_time(const ComplexPoint& x);
  std::vector<Interval> vertex_burn_times();

  const MedialComplex& complex() const { return mc_; }
  const Unfolding& unfolding() const { return *unfolding_; }
  const WindowPropagation& propagation() const { return *prop_; }
  const CertificationCounts& certification() const { return prop_->certifier().counts; }
  Certifier& certifier() { return prop_->certifier(); }
  // The switch points of the singular edges' (k-1)-th arrival (after run(); junction_points.h).
  std::vector<WindowPropagation::JunctionSwitch> junction_switches() { return prop_->junction_switches(); }
  const QueryCounts& query_counts() const { return queries_; }
  // The live windows covering triangle t (roots and entered windows).
  std::vector<std::uint32_t> triangle_windows(std::uint32_t t) const;

 private:
  void index_windows();
  int membership(std::uint32_t w, const Target& x, double* widen);

  const MedialComplex& mc_;
  std::unique_ptr<Unfolding> unfolding_;
  std::unique_ptr<WindowPropagation> prop_;
  std::vector<std::uint32_t> first_, list_;  // CSR: windows per triangle
  QueryCounts queries_;
};

}  // namespace grassfire
