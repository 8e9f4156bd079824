// axis_resolution.h -- what the sampling of a surface resolves of its inner Voronoi axis:
// the tests of the pruning (which Voronoi polygons and edges may not be collapsed away) and
// the resolution rule (which components of the pruned axis lie below the sampling's
// resolution) (2.1.2 in 3D; mesh_axis.h, steps 4 and 7; docs/limitations.md).
//
// Computes, for the inner Voronoi complex V_in of surface samples (inner_voronoi.h):
//  - sample_spacing: per sample, the smallest spacing of the triangles it lies on (lattice
//    units): the local sampling density h, which the separation and resolution tests share;
//  - AngleTest: angle(u x v) >= theta for a vertex x and samples u, v on its sphere, as
//    |u - v|^2 >= 2 (1 - cos theta) R(x)^2 (2 (1 - cos theta) the rational value of its double);
//  - SeparationTest: |u - v| >= lambda max(h_u, h_v);
//  - KeepTests: a polygon pq is kept when p, q are apart and the angle is wide at each of its
//    vertices; an edge (a triangle pqr's Voronoi edge) when some pair of p, q, r is apart
//    and some pair's angle is wide at both ends;
//  - ResolutionTest: whether a vertex x is unresolved, R(x) < (lambda / 2) h(x), h(x) the
//    smallest spacing of the four samples of x's Delaunay tetrahedron;
//  - unresolved_components: the connected components of a polygonal 2-complex (vertices
//    joined by polygon sides and segments; a vertex with no cell is a component) whose
//    every vertex is unresolved.
// Exactness: every test is exact on the lattice samples and circumcentres (inner_voronoi.h:
// R(x)^2 = |N|^2 / D^2 in lattice units), the thresholds (kappa, lambda h, (lambda / 2) h)
// being the rational values of doubles: an interval filter first, then integers or GMP.
// Why an unresolved component is below the resolution (the stated guarantee): every vertex
// x of V_in is the centre of a ball of radius R(x) empty of samples with samples on its
// sphere, so its distance d(x) to the surface is at most R(x); and every point of the
// surface is within about h of a sample (mesh_samples.h), so d(x) >= R(x) - h. When
// R(x) < h (lambda = 2) that lower bound is void: the samples cannot tell x from a point of
// the surface. A component made of such vertices lies within (lambda / 2) h of the surface
// (a polygon's points are within its vertices' R of its two samples), and it is the scale
// the pruning already ignores: a polygon of samples p, q at x has |p - q| <= 2 R(x) <
// lambda h, so no polygon of such a component passes the separation test, and the pruning
// keeps it only because a component cannot collapse to nothing. Such components appear
// along edges where the solid is a sharp wedge (interior dihedral angle well below 90
// degrees: a filled hole meeting a thin cap at 14-30 degrees, an alpha wrap's creases, a
// thin lens): near its edge the wedge is thinner than h, its Delaunay cells alternate
// between inside and outside circumcentres, and halving h halves the band but doubles the
// edge's samples, so their number grows as the sampling is refined instead of vanishing
// (mesh lfs is 0 on an edge, where the sampling theorems of inner_voronoi.h do not hold).
// Contract: the samples and V_in of one round; spacings positive; for
// unresolved_components, vertex ids < vertex_count and `unresolved` defined on every id.
// Complexity: O(1) per test; unresolved_components linear in the complex (union-find).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "complex3/polygon_rings.h"
#include "medial3/mesh/axis_pruning.h"
#include "medial3/mesh/inner_voronoi.h"
#include "number/interval.h"

namespace grassfire {

// Per sample, the smallest spacing of the triangles it lies on, in lattice units.
std::vector<double> sample_spacing(const SurfaceSamples& samples, const std::vector<double>& triangle_spacing);

// An enclosure of a 128-bit integer: its nearest double, widened outwards.
inline Interval enclose_integer(__int128 x) {
  const double d = static_cast<double>(x);
  return {round_down(d), round_up(d)};
}

// The angle test of a Voronoi vertex x against two samples u, v on its empty sphere:
// |u - v|^2 >= kappa R(x)^2. In lattice units R(x) = |N| / |D| (the centre is
// n_0 + N / D and n_0 lies on the sphere), so the test is D^2 |u - v|^2 >= kappa |N|^2:
// an interval filter, then exact integers.
class AngleTest {
 public:
  AngleTest(const InnerVoronoi& vor, double angle_degrees)
      : vor_(vor), kappa_(2 * (1 - std::cos(angle_degrees * M_PI / 180))), exact_kappa_(kappa_) {}

  bool wide(std::uint32_t x, std::uint32_t u, std::uint32_t v) const {
    if (kappa_ <= 0) return true;
    const auto& a = vor_.samples.lattice[u];
    const auto& b = vor_.samples.lattice[v];
    const LatticeCentre& c = vor_.vertices[x].centre;
    std::int64_t d2 = 0;  // < 3 * 2^54
    for (int k = 0; k < 3; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
    Interval n2(0.0);
    for (int k = 0; k < 3; ++k) n2 += square(enclose_integer(c.num[k]));
    const int sign = certified_sign(square(enclose_integer(c.den)) * Interval(static_cast<double>(d2)) - Interval(kappa_) * n2);
    if (sign != kUndecided) return sign >= 0;
    mpq_class nn = 0;
    for (int k = 0; k < 3; ++k) nn += to_mpq(c.num[k]) * to_mpq(c.num[k]);
    const mpq_class den = to_mpq(c.den);
    return sgn(den * den * mpq_class(d2) - exact_kappa_ * nn) >= 0;
  }

 private:
  const InnerVoronoi& vor_;
  double kappa_;
  mpq_class exact_kappa_;
};

// The separation test of two samples: |u - v| >= lambda max(h_u, h_v), h the spacing of
// the triangles a sample lies on. Exact: |u - v|^2 is an integer in lattice units, compared
// with the ceiling of the double threshold.
class SeparationTest {
 public:
  SeparationTest(const InnerVoronoi& vor, const std::vector<double>& sample_spacing, double lambda)
      : vor_(vor), spacing_(sample_spacing), lambda_(lambda) {}

  bool apart(std::uint32_t u, std::uint32_t v) const {
    if (lambda_ <= 0) return true;
    const auto& a = vor_.samples.lattice[u];
    const auto& b = vor_.samples.lattice[v];
    std::int64_t d2 = 0;  // < 3 * 2^54
    for (int k = 0; k < 3; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
    const double h = lambda_ * std::max(spacing_[u], spacing_[v]);
    const double threshold = std::ceil(h * h);
    return threshold < 0x1p62 && d2 >= static_cast<std::int64_t>(threshold);
  }

 private:
  const InnerVoronoi& vor_;
  const std::vector<double>& spacing_;  // per sample, in lattice units (sample_spacing)
  double lambda_;
};

// The tests of the pruning: which polygons and edges may not be collapsed away.
struct KeepTests {
  const InnerVoronoi& vor;
  const AngleTest& angle;
  const SeparationTest& separation;

  bool polygon(std::uint32_t i) const {
    if (!separation.apart(vor.pq[i][0], vor.pq[i][1])) return false;
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k)
      if (!angle.wide(vor.polygons.ring(i)[k], vor.pq[i][0], vor.pq[i][1])) return false;
    return true;
  }

  bool edge(const EdgeOrigin& o) const {
    std::array<std::uint32_t, 2> ends;
    std::array<std::uint32_t, 3> t;
    if (o.segment) {
      ends = vor.segments[o.index].v;
      t = vor.segments[o.index].triangle;
    } else {
      ends = vor.polygons.side(o.index, o.side);
      t = {vor.pq[o.index][0], vor.pq[o.index][1], vor.apex[vor.polygons.offset[o.index] + o.side]};
    }
    if (!separation.apart(t[0], t[1]) && !separation.apart(t[1], t[2]) && !separation.apart(t[2], t[0])) return false;
    for (std::uint32_t x : ends)
      if (!angle.wide(x, t[0], t[1]) && !angle.wide(x, t[1], t[2]) && !angle.wide(x, t[2], t[0])) return false;
    return true;
  }
};


class ResolutionTest {
 public:
  // lambda: the separation factor; lambda <= 0 resolves every vertex (no test, as the pruning).
  ResolutionTest(const InnerVoronoi& vor, const std::vector<double>& sample_spacing, double lambda)
      : vor_(vor), spacing_(sample_spacing), half_lambda_(lambda / 2) {}
  bool unresolved(std::uint32_t vertex) const;

 private:
  const InnerVoronoi& vor_;
  const std::vector<double>& spacing_;
  double half_lambda_;
};

struct UnresolvedComponents {
  std::vector<bool> vertex_dropped;  // per vertex: in an unresolved component
  std::size_t components = 0;
};

UnresolvedComponents unresolved_components(std::size_t vertex_count, const PolygonRings& polygons,
                                           const std::vector<std::array<std::uint32_t, 2>>& segments,
                                           const std::function<bool(std::uint32_t vertex)>& unresolved);

}  // namespace grassfire
