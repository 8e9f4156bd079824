// polygon_axis.h -- the exact medial axis of a polygon with holes (2.1.1; docs/design.md 4;
// docs/exactness.md).
//
// Computes: the medial graph M of a polygon: the interior part of the segment Voronoi
// diagram of its vertices (point sites) and edges (open segment sites), without the
// edges that separate a segment from its own endpoint. Convex vertices are leaves with
// R = 0; reflex vertices are point sites whose regions contribute parabolic arcs
// (EdgeKind::ParabolicArc, focus = the vertex, directrix = the segment's line) and
// straight edges. Nodes are Voronoi vertices, contracted exactly where several coincide
// (cocircular sites: regular polygons, rectangles' centres, the two sides of a collinear
// vertex); degree-2 nodes where a collinear vertex's normal meets the axis are kept. Two
// circles of one kind whose conditions are the same (point sites, and segment lines with
// the segments of one straight run through collinear vertices taken as one line) and
// admit at most one circle (voronoi_circle.h) are contracted without exact forms.
// Exactness: topology by exact predicates (Boost.Polygon on integers, or CGAL SDG with
// filtered exact traits). R at a node is exact: a rational, a sum of square roots of
// rationals (PPP, PPS, SSS and many PSS circles: voronoi_circle.h) or, for nested
// radicals, a sum with square roots of sums of square roots (solve_radical), which
// number/root_separation.h compares exactly. Straight edge lengths are exact (projections
// on the bisector, square roots of sums for crossing lines); parabolic arc lengths are
// differences of certified constants S[p;xi] (closed form with asinh, Arb) at exact focal
// parameters and abscissas (polygon_axis_geometry.h). The graph's double enclosures
// of R and lengths are rigorous and tight: double interval formulas, re-evaluated in
// double-double (number/dd_ball.h) and then in Arb when wider than kTightBits relative
// bits (a node's centre coordinates: kTightBits bits of its circle's scale, the largest of
// |x|, |y| and R, since a coordinate that is 0 has no relative accuracy); exact values are
// built lazily,
// only when the burning engine's filter cannot decide.
// Input policy (which construction runs): a coordinate that is the double nearest to a
// decimal with at most 9 fractional digits is taken as that decimal (the smallest such
// digit count k, per coordinate; the shape's K is the largest k). If every coordinate
// is such a decimal and the integers x 10^K fit in int32, Boost.Polygon runs on those
// integers and the axis is exact for the decimal polygon (the one the file wrote).
// Otherwise, if the doubles scaled by the power of two 2^K that makes them all integers
// (the binary policy: exact, K = minus the smallest lowest-set-bit exponent) fit int32,
// Boost.Polygon runs on those integers (dyadic inputs: binary fractions, float data, large
// integers with trailing zero bits). Otherwise, if those integers lie within 2^62 of the
// centre of their bounding box (the wide binary policy: any double polygon whose
// coordinates span at most 62 bits between the largest magnitude and the smallest lowest
// set bit, e.g. full-mantissa coordinates away from 0), Boost.Polygon's builder runs on them
// with wide coordinate traits (boost_wide_traits.h: 64-bit input, exact integer parts,
// quadruple-precision filters). Otherwise (the mp binary policy: any finite doubles, e.g. a
// full-mantissa coordinate near 0 beside large ones) Boost.Polygon's builder runs on the
// same exact integers of any size with the mp traits (boost_mp_traits.h: exact big integer
// parts, MPFR filters with 64 guard bits beyond the integers' span). CGAL's SDG runs on the
// exact double values only when asked for (PolygonAxisOptions::construction).
// Every policy gives the axis of the exact input polygon (the decimal one for the first),
// and every combinatorial decision is exact.
// Checked diagrams: Boost's builder has known wrong outputs on valid polygons (a missing
// Voronoi vertex at a reflex corner, an interior edge to infinity); every diagram it
// returns is checked (segment_voronoi_check.h) and one that fails is rebuilt by CGAL's SDG
// on the same exact frame, counted in PolygonAxisReport::voronoi_fallbacks. Its hang on
// vertices merged in a cycle cannot occur: the merging post-pass is switched off
// (boost_voronoi_extract.h). When CGAL's diagram fails too, the error names the shape and
// both defects (std::runtime_error); no valid polygon ends in an internal message.
// Contract: a validated Shape2 (shapes/validate_shape.h). Throws std::invalid_argument
// for an empty shape.
// Complexity: O(n log n) (Boost, every traits) plus O(n) circle work; CGAL SDG is superlinear on dense
// samples of smooth curves with full-mantissa coordinates (its interval filter fails on the
// near-degenerate incircle tests; measured in experiments/bench_polygon_axis.cpp).
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "medial2/medial_graph.h"
#include "geometry2/shape2.h"

namespace grassfire {

// BoostPolygon: int32 frame (decimal or binary policy); BoostPolygonWide: the wide binary
// policy. Asking for BoostPolygon accepts either Boost frame; asking for BoostPolygonWide
// skips the decimal policy and the int32 frame (the wide traits on the binary frame).
// BoostPolygonMp: the mp binary policy (any finite doubles; asking for it skips the others).
// CgalSdg runs only when asked for.
enum class AxisConstruction { Auto, BoostPolygon, BoostPolygonWide, BoostPolygonMp, CgalSdg };
const char* to_string(AxisConstruction c);

struct PolygonAxisOptions {
  AxisConstruction construction = AxisConstruction::Auto;
  int max_decimal_digits = 9;  // the decimal policy's k <= 9
};

struct PolygonAxisReport {
  AxisConstruction construction = AxisConstruction::Auto;  // the one that ran
  int decimal_digits = -1;  // K when the decimal policy applied, else -1
  int binary_digits = std::numeric_limits<int>::min();  // K when the binary policy applied (frame = input x 2^K)
  // The mp policy: bits of its integers about their centre and of its floats; whether the
  // double-interval filter stage ran it, and how many decisions that stage handed to MPFR.
  int mp_input_bits = 0, mp_float_bits = 0;
  bool mp_filtered = false;
  std::uint64_t mp_fallbacks = 0;
  // Diagrams a Boost construction gave that failed the topology check
  // (segment_voronoi_check.h) and were rebuilt by CGAL's segment Delaunay graph (then
  // `construction` is CgalSdg): the construction rejected and the defect found.
  std::uint64_t voronoi_fallbacks = 0;
  AxisConstruction rejected_construction = AxisConstruction::Auto;
  std::string fallback_reason;
  double frame_scale = 1;   // frame coordinates = input coordinates x frame_scale
  std::uint64_t polygon_vertices = 0;
  std::uint64_t voronoi_vertices = 0;   // interior Voronoi vertices before contraction
  std::uint64_t nodes = 0, edges = 0, leaves = 0, parabolic_arcs = 0;
  std::uint64_t contracted_edges = 0;       // zero-length edges, proved zero exactly
  std::uint64_t contracted_by_conditions = 0;  // of those: same conditions, one solution (no exact forms)
  std::uint64_t uncertified_contractions = 0;  // zero to 1024 bits, no exact form
  std::uint64_t dd_refinements = 0;        // enclosures re-evaluated in double-double
  std::uint64_t ball_refinements = 0;      // of those, still too wide: re-evaluated in Arb
  std::uint64_t circles_by_kind[7] = {};   // indexed by CircleKind
  double voronoi_seconds = 0, values_seconds = 0, total_seconds = 0;  // thread CPU (support/cpu_clock.h)
};

MedialGraph exact_polygon_axis(const Shape2& shape, const PolygonAxisOptions& options = {},
                               PolygonAxisReport* report = nullptr);

// The binary policy: the exponent of the lowest set bit of a finite nonzero x (x is an odd
// integer times 2^result).
int lowest_bit_exponent(double x);

// The decimal policy: the smallest k <= max_digits such that x is the double nearest to
// m / 10^k for an integer m (which is stored), or -1.
int decimal_digits(double x, int max_digits, long long* m);

}  // namespace grassfire
