// Helpers shared by the [exact3] tests: small complexes with known burning times, point
// sampling inside triangles, and a run of the exact engine.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "burn3/exact/exact_burning.h"
#include "burn3/exact/junction_points.h"
#include "burn3/point_sources.h"
#include "complex3/complex_builder.h"
#include "test_complex3_support.h"

namespace grassfire::testing {

// The grid sheet [0, w] x [0, h] in the plane z = 0 (cells of side 1/g, each split in two
// along alternating diagonals), without the cells listed in `holes` (cell column, row at
// resolution g). Border edges get `rule`.
RawComplex grid_sheet(int w, int h, int g, const std::vector<std::pair<int, int>>& holes = {},
                      IgnitionRule rule = IgnitionRule::Never);

// The point with barycentric weights (a, b, 1 - a - b) of triangle t (exact).
ExactPoint3 triangle_point(const MedialComplex& mc, std::uint32_t t, const mpq_class& a, const mpq_class& b);
// `count` random exact points of t with denominator 64 (interior, edges and corners included).
std::vector<ExactPoint3> sample_triangle(const MedialComplex& mc, std::uint32_t t, int count, std::mt19937& rng);

Vec3d to_vec(const ExactPoint3& p);
double distance3(const Vec3d& a, const Vec3d& b);

// The discrete baseline at spacing h (with `sources`, and the border as the complex says)
// checked to be an upper bound of the exact vertex values; returns its largest gap to them.
double baseline_gap(const MedialComplex& mc, const std::vector<Interval>& exact, double h,
                    const std::vector<PointSource>& sources = {});

// The enclosure's width, and whether it contains x.
inline bool encloses(const Interval& i, double x, double slack = 0.0) { return i.lo - slack <= x && x <= i.hi + slack; }

// A complex burned by the exact engine from its border rules, with the junction points of
// its singular edges (junction_points.h).
struct BorderBurn {
  MedialComplex mc;
  std::unique_ptr<ExactBurning> eb;
  JunctionPoints points;
  explicit BorderBurn(const RawComplex& raw);
};

// x -> s R x + t with R = the rotation by the Pythagorean angle (3/5, 4/5) about y, then by
// (5/13, 12/13) about z: rational and orthogonal.
ExactPoint3 motion(const ExactPoint3& p, const mpq_class& s, const ExactPoint3& t);
// The complex moved by `motion` (radii scaled by s, rule points moved).
RawComplex moved(RawComplex raw, const mpq_class& s, const ExactPoint3& t);
// The same complex with vertices and triangles in a shuffled order (and each triangle's
// corners rotated): old triangle i is new triangle (*new_triangle)[i], old vertex v new
// vertex (*new_vertex)[v] (when asked).
RawComplex shuffled(RawComplex raw, std::mt19937& rng, std::vector<std::uint32_t>* new_triangle,
                    std::vector<std::uint32_t>* new_vertex = nullptr);

}  // namespace grassfire::testing
