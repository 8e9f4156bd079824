// bt_bracket.h -- BT bracketed from both sides by computations that share nothing with the
// exact engine (4.2.3, Definitions 9-10; docs/design.md 5): a lower bound derived below and two
// upper bounds.
//
// Upper bound: the smaller of two, each the time of a burning process Definition 9 allows,
// so >= BT (up to double rounding), and each converging as h shrinks: the discrete baseline
// at spacing h (discrete_burning.h), read at any point by discrete_query.h (polygonal
// non-crossing paths between graph points, on every complex); and fire that crosses the
// singular set only at samples at spacing h, with exact (straight) distances inside the
// convex planar sheets (bt_bracket_upper.h; +infinity where it needs another sheet).
//
// Lower bound (BtLowerBound). Let Sigma be the singular set: the singular edges, the dangling
// segments and the vertices on them or on two or more sheets. Cut each edge of Sigma into
// ceil(|e| / h) cells of equal length; each vertex of Sigma is a cell of length 0. Let r > 0
// (the reach; 32 h by default).
//  (a) Fire inside a sheet S comes from an ignition of S (border point y at f(y), source s
//      at t0) or leaves a point w of Sigma on the closure of S after w burned, and travels at
//      most at unit speed along a path no shorter than the Euclidean distance. So for x in S
//      off Sigma, BT(x) >= min(I_S(x), min over cells c of cl(S) of L(c) + dist(x, c)), with
//      I_S(x) = min over ignitions of S of f(y) + |x - y| and L(c) <= min of BT over c.
//  (b) Non-local arrivals. At y in Sigma, an arrival through a side t (sheet S) that comes
//      from an ignition of S, or from a point w of Sigma with |w - y| >= r, is at least
//      n_t(c) = min(I_S(c), min over cells c' of cl(S) of L(c') + max(r, dist(c, c')))
//      for every y in the cell c (I_S(c): a lower bound of I_S over c: exact segment
//      distances for constant f, else the value at c's midpoint minus half c's length).
//      N(c) = the (k-1)-th smallest n_t(c) over the k triangles of a singular edge (the
//      junction rule of Definition 9); at a vertex of Sigma, the first time at which its link
//      rule holds (MedialComplex::link_burns) when each sector arrives at n of its sheet and
//      no pole arrives (fire along an edge of Sigma is local: the envelope's), or at its
//      first such arrival at a border point; min with f at a border vertex and t0 of a
//      source in c; +infinity on segments except at sources. So N(c) is at most the time
//      at which y would burn from non-local arrivals alone, for every y of c.
//  (c) Local arrivals (from Sigma within r, along the curve or through a sheet) are the
//      envelope: Lemma. BT(y) >= G(y) := min over cells c of N(c) + dist(y, c) on Sigma.
//      Proof, by induction on the burning time (Definition 9 is causal: an arrival at y at
//      time t is carried by fire that left a point burned strictly before t). Take the first
//      y with BT(y) < G(y). It burns at its (k-1)-th arrival (or f, or a source, both in N).
//      If those k-1 arrivals are non-local, BT(y) >= N(y's cell) >= G(y). Otherwise one
//      comes from w in Sigma, BT(w) < BT(y), so BT(w) >= G(w), and the arrival is at least
//      G(w) + |y - w| >= G(y) (G is 1-Lipschitz): BT(y) >= G(y) either way. Non-local
//      arrivals are at least r later than their origin, which makes the induction on time
//      well founded (steps of r). So L(c) := min over c' of N(c') + dist(c, c').
//  The system L, n, N is monotone; BT (with L its cell minima) satisfies it as an
//  inequality (Phi(BT) <= BT), so every iterate of Phi from 0, and its least fixed point,
//  lies below BT. That least fixed point is computed by a Dijkstra over the cells (values
//  are order statistics of non-negative increments: a cell's value is final when popped).
// Convergence: on complexes whose sheets are planar and convex, Euclidean distances are the
// sheet distances and the bound tends to BT as h shrinks. Its losses: up to one cell (h)
// where a cell's minimum stands for its points (measured: exactly h on the junction books at
// h = 0.05, 0.0125, 0.003125); a fraction about 3 h / r of the length of each non-local hop
// through Sigma (with r = h the cell loss compounds to a slope of 1/2 along a singular edge
// and the bound does not converge); and up to r near vertices of Sigma where a needed
// arrival comes through a sheet from Sigma within r. Measured on the proof-check corpora
// (mean width at h / 2): r = 4 h 0.051 (generated), 0.171 (convex); 8 h 0.023, 0.083;
// 16 h 0.016, 0.056; 32 h 0.013, 0.050; 64 h the same: hence 32 h. On curved or
// non-convex sheets the Euclidean distance undercuts the sheet distance and the bracket
// keeps a width that does not vanish (reported, not hidden).
// Values are doubles: every number is within double rounding (relative 1e-15 per step) of
// the quantity named above; golden-section minima along border edges with non-constant f
// stop at 1e-15 in the parameter (bracket_support.h). Callers allow 1e-9.
// Contract: a validated MedialComplex that outlives this object; sources located on it;
// spacing h > 0 and at most max_cells cells (std::invalid_argument otherwise).
// Complexity: O(C^2 k + C B) for C cells, k sides per cell, B border edges per sheet;
// a query O(C + B).
#pragma once

#include <cstdint>
#include <vector>

#include "burn3/bt_bracket_upper.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"
#include "number/interval.h"

namespace grassfire {

struct BtLowerBoundOptions {
  double spacing = 0.05;  // h: the cells' length
  double reach = 0;       // r: arrivals from Sigma within r are local (0: the default, 32 h)
  std::vector<PointSource> sources;
  std::uint64_t max_cells = 20000;
};

class BtLowerBound {
 public:
  BtLowerBound(const MedialComplex& mc, const BtLowerBoundOptions& options);
  // A lower bound of BT at x (+infinity where nothing can reach x).
  double at(const ComplexPoint& x) const;
  std::size_t cells() const { return cells_.size(); }
  double seconds() const { return seconds_; }

 private:
  struct Cell {
    Vec3d a{}, b{};  // ends (a == b for a vertex)
    std::uint32_t edge = kNoIndex, vertex = kNoIndex;
    std::vector<std::uint32_t> side_sheet;  // per side (triangle; at a vertex, link element)
    std::uint32_t need = 1;                 // which order statistic burns it (0: the link rule)
    double floor = 0;                       // min of f at a border vertex and sources in it
  };
  void build_cells();
  void add_sources();
  double ignition_bound(std::uint32_t sheet, const Vec3d& a, const Vec3d& b) const;
  void solve();
  bool on_sigma(const ComplexPoint& x) const;

  const MedialComplex& mc_;
  BtLowerBoundOptions o_;
  std::vector<Cell> cells_;
  std::vector<std::vector<std::uint32_t>> sheet_cells_;   // cells in the closure of each sheet
  std::vector<std::vector<std::uint32_t>> sheet_border_;  // border edges of each sheet
  std::vector<std::vector<std::uint32_t>> sheet_sources_;
  std::vector<Vec3d> source_point_;
  std::vector<std::uint32_t> vertex_cell_;  // kNoIndex off Sigma
  std::vector<std::uint32_t> edge_first_cell_;  // per edge, kNoIndex off Sigma
  std::vector<double> n_value_, l_value_;
  double seconds_ = 0;
};

// The bracket at one spacing h: [BtLowerBound, min(the discrete baseline read by
// discrete_query.h, ChordUpperBound)] (all with the same sources; the border ignites as the
// complex says).
class BtBracket {
 public:
  BtBracket(const MedialComplex& mc, double spacing, const std::vector<PointSource>& sources = {});
  // [lower, upper] at x; lower may exceed upper only by rounding (checked by callers).
  Interval at(const ComplexPoint& x) const;
  const BtLowerBound& lower() const { return lower_; }
  // The construction times of the upper bounds: the discrete baseline, the chords.
  double seconds_upper() const { return upper_.stats.seconds + chords_.seconds(); }

 private:
  const MedialComplex& mc_;
  std::vector<PointSource> sources_;
  BtLowerBound lower_;
  DiscreteBurning upper_;
  ChordUpperBound chords_;
};

}  // namespace grassfire
