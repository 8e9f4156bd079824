// bt_bracket_upper.h -- an upper bound of BT with exact distances inside convex planar
// sheets: fire restricted to cross the singular set at sample points (4.2.3, Definition 9;
// the upper side of bt_bracket.h).
//
// Samples: the vertices of the singular set Sigma (as in bt_bracket.h) and points of every
// edge of Sigma at spacing <= h. A sheet S is *convex* when it is planar, the union of its
// triangles is convex (exact: its area equals its hull's, in the sheet's rational frame),
// and Sigma meets it only on its boundary (each singular edge of S has one triangle in S,
// each vertex of Sigma on S lies on a boundary edge of S). In a convex sheet the segment
// between two points p, q of its closure lies in its interior, except where p and q lie on
// one supporting line of its boundary (decided exactly: collinear boundary edges share a line
// id); such a segment is a non-crossing path (it meets Sigma at most at its ends). Along one
// edge of Sigma, fire runs from sample to sample (an interior point of a singular edge burns
// at its first arrival along the edge).
// The bound: a Dijkstra over the samples in which each arrival is the time of one such path
// from a burned sample, a border point (f(y) + |y - p|, y a point of the edge found by golden
// section: any point gives a valid path) or a source; a sample on a singular edge burns at its
// (k-1)-th side arrival or its first arrival along the edge, a vertex by its link rule
// (MedialComplex::link_burns) over its sectors' and poles' arrivals. Every value is the time
// of a burning process that Definition 9 allows, so it is >= BT (Lemma 2), up to double
// rounding; non-convex sheets carry no arrival (their sides never arrive: the bound is then
// +infinity where it needs them, never wrong). As h shrinks it tends to BT on complexes whose
// sheets are all convex (the crossing points move to the samples: O(h) per crossing).
// Contract: a validated MedialComplex that outlives this object; sources located on it.
// Complexity: O(P^2) for P samples (each pop relaxes the samples of its sheets), plus the
// border edges of each sheet per sample; a query O(P + B).
#pragma once

#include <cstdint>
#include <vector>

#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"

namespace grassfire {

class ChordUpperBound {
 public:
  ChordUpperBound(const MedialComplex& mc, double spacing, const std::vector<PointSource>& sources);
  // An upper bound of BT at x (+infinity where no convex sheet carries fire to x).
  double at(const ComplexPoint& x) const;
  std::size_t convex_sheets() const;
  double seconds() const { return seconds_; }

 private:
  struct Sample {
    Vec3d p{};
    std::uint32_t edge = kNoIndex, vertex = kNoIndex;
  };
  // A point of a sheet's closure: its position and the boundary lines of S through it.
  struct Where {
    Vec3d p{};
    std::vector<std::uint32_t> lines;
    std::uint32_t edge = kNoIndex, vertex = kNoIndex;  // the Sigma edge / vertex it lies on
  };
  void classify_sheets();
  void place_samples();
  std::vector<std::uint32_t> lines_at(std::uint32_t sheet, const ComplexPoint& x) const;
  std::vector<std::uint32_t> sample_lines(std::uint32_t sheet, std::uint32_t i) const;
  bool chord(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) const;
  double ignition(std::uint32_t sheet, const Vec3d& p, const std::vector<std::uint32_t>& lines) const;
  double burn_time(std::uint32_t i, const std::vector<double>& side, double along) const;
  void solve();
  // The sides of sample i: per triangle of its edge, or per link element of its vertex.
  std::vector<std::uint32_t> side_sheets(std::uint32_t i) const;

  const MedialComplex& mc_;
  double spacing_;
  std::vector<PointSource> sources_;
  std::vector<char> convex_;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> line_;  // per sheet: (edge, line id)
  std::vector<Sample> samples_;
  std::vector<std::vector<std::uint32_t>> sheet_samples_;
  std::vector<std::vector<std::uint32_t>> edge_samples_;  // per Sigma edge
  std::vector<std::uint32_t> vertex_sample_;
  std::vector<double> value_;
  std::vector<double> floor_;
  double seconds_ = 0;
};

}  // namespace grassfire
