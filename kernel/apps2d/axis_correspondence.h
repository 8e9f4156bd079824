// axis_correspondence.h -- nearest points between two medial graphs of (nearly) one shape,
// to compare an approximate axis and its EDF with a reference (docs/exactness.md: convergence of the
// sampled axis to the exact polygon axis; 3.4 and 5.1.3: stability under perturbation).
//
// Computes:
//  - AxisLocator: for a query point q, the nearest point of a medial graph, as an edge, an
//    arc length s from the edge's end u, and a position. Straight edges are exact segments;
//    curved edges (parabolic arcs) are replaced by chords between points at arc lengths at
//    most `step` apart (MedialGeometry::point_along), so the answer is within the chords'
//    sagitta (<= curvature * step^2 / 8) of the true nearest point.
//  - compare_axes: every node x of the approximate axis A is mapped to the nearest point
//    y(x) of the reference axis B; the EDF error at x is |EDF_A(x) - EDF_B(y(x))| where
//    EDF_B inside an edge is GrassfireResult::edf_along (exact piecewise-linear form);
//    reported as max and mean over the nodes of A with finite EDF on both sides, divided
//    by the shape's diameter. Also the distance between the two EMA points and the
//    Hausdorff distance between the axes, both divided by the diameter. The Hausdorff
//    distance is evaluated at points spaced at most `step` along each axis (nodes included),
//    so it is within step / 2 (plus the sagitta) of the true one.
// Exactness: none needed and none claimed: this is measurement for studies, in double
// precision from the midpoints of the certified enclosures of EDF, R and lengths. No
// combinatorial decision of the kernel depends on it.
// Contract: the graphs are validated; the GrassfireResults were computed on them; step > 0.
// Complexity: building a locator O(p) for p chord pieces (a uniform grid of about p cells);
// a query visits the grid cells in square rings around q until the best distance found is
// below the ring's distance: O(1) expected for query points near the axis.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "medial2/medial_graph.h"
#include "geometry2/shape2.h"

namespace grassfire {

struct AxisPoint {
  std::uint32_t edge = 0;
  double s = 0;        // arc length from the edge's end u
  Point2 position;
  double distance = std::numeric_limits<double>::infinity();  // to the query
};

class AxisLocator {
 public:
  AxisLocator(const MedialGraph& g, double step);
  // The nearest point of the graph to q (distance infinity for a graph without edges).
  AxisPoint nearest(const Point2& q) const;
  // Calls f(edge, s0, s1) for every chord piece with a point within distance r of q, with
  // [s0, s1] the arc lengths (from the edge's u) of the part of the piece within r.
  template <class F>
  void for_each_within(const Point2& q, double r, F&& f) const;
  // Points along every edge at arc-length spacing <= step, both ends included.
  std::vector<Point2> dense_points() const;
  const MedialGraph& graph() const { return g_; }

 private:
  struct Piece {
    Point2 a, b;
    std::uint32_t edge;
    double sa, sb;  // arc lengths of a and b from the edge's u
  };
  void build_grid();
  void scan_cell(long ix, long iy, const Point2& q, AxisPoint& best) const;
  // The part of the piece within distance r of q as parameters [t0, t1] of a..b; false if none.
  static bool clip_to_disk(const Piece& p, const Point2& q, double r, double* t0, double* t1);

  const MedialGraph& g_;
  double step_;
  std::vector<Piece> pieces_;
  double x0_ = 0, y0_ = 0, cell_ = 1;
  long nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> cell_start_, cell_items_;  // CSR lists of pieces per cell
};

template <class F>
void AxisLocator::for_each_within(const Point2& q, double r, F&& f) const {
  if (pieces_.empty()) return;
  const auto cell = [&](double v, double o, long n) { return std::clamp(static_cast<long>(std::floor((v - o) / cell_)), 0L, n - 1); };
  const long ax = cell(q.x - r, x0_, nx_), bx = cell(q.x + r, x0_, nx_);
  const long ay = cell(q.y - r, y0_, ny_), by = cell(q.y + r, y0_, ny_);
  std::vector<std::uint32_t> seen;
  for (long ix = ax; ix <= bx; ++ix)
    for (long iy = ay; iy <= by; ++iy) {
      const auto c = static_cast<std::size_t>(iy * nx_ + ix);
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) seen.push_back(cell_items_[k]);
    }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  for (std::uint32_t i : seen) {
    const Piece& p = pieces_[i];
    double t0, t1;
    if (clip_to_disk(p, q, r, &t0, &t1)) f(p.edge, p.sa + t0 * (p.sb - p.sa), p.sa + t1 * (p.sb - p.sa));
  }
}

// The EDF at a point of the graph (midpoint of the certified enclosure; infinity on the 2-core).
double edf_at(const GrassfireResult& burning, const AxisPoint& p);

// The EMA point used to compare axes: that of the component with the most nodes; false
// when that component's EMA is a set of cycles.
bool ema_position(const MedialGraph& g, const GrassfireResult& burning, Point2* out);

struct AxisComparison {
  std::size_t nodes = 0;          // nodes of A compared
  std::size_t infinite = 0;       // nodes of A skipped: EDF infinite on A or at y(x) on B
  double max_edf_error = 0;       // max |EDF_A(x) - EDF_B(y(x))| / diameter
  double mean_edf_error = 0;      // mean of the same
  double p95_edf_error = 0;       // 95th and 99th percentiles of the same (nearest rank)
  double p99_edf_error = 0;
  // max over x of min |EDF_A(x) - EDF_B(y)| over the points y of B within |x - y(x)| +
  // match_radius of x: the error once a node may match any branch near a junction.
  double max_edf_error_near = 0;
  double max_node_offset = 0;     // max |x - y(x)| / diameter
  double ema_distance = std::numeric_limits<double>::quiet_NaN();  // NaN: an EMA is cycles
  double hausdorff = 0;           // between the axes, / diameter
};

AxisComparison compare_axes(const MedialGraph& a, const GrassfireResult& burning_a, const MedialGraph& b,
                            const GrassfireResult& burning_b, double diameter, double step, double match_radius = 0);

// Largest distance between two vertices of the shape's outer ring (double precision,
// convex hull then all pairs of hull vertices).
double shape_diameter(const Shape2& shape);

}  // namespace grassfire
