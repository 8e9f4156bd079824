// segment_voronoi.h -- the interior segment Voronoi diagram of a polygon with holes, as
// exact topology over named sites (2.1.1; docs/exactness.md).
//
// Computes: the Voronoi vertices and edges of the sites of a polygon (each polygon
// vertex is a point site, each polygon edge an open segment site) that lie inside the
// polygon, without the edges that separate a segment from its own endpoint (their
// points have a single closest boundary point, so they are not medial). Every vertex
// lists its defining sites in counter-clockwise order around it; convex polygon vertices
// are apex vertices (R = 0, leaves of the medial axis, docs/design.md 4).
// Two constructions with exact topology: Boost.Polygon's voronoi builder (integer input
// up to int32 with its default traits, or within 2^62 of the frame's centre with the wide
// traits of boost_wide_traits.h, or any finite doubles with the mp traits of
// boost_mp_traits.h), and CGAL's Segment_Delaunay_graph_2 with filtered exact
// traits (any double input; exact kernel Gmpzf, segments in seeded random order). Boost's post-pass that merges vertices within 128 ulps is
// switched off: coincident vertices (cocircular sites) come out as zero-length edges and
// are contracted later by an exact test (polygon_axis.cpp), never by a tolerance.
// Interior/exterior is decided combinatorially: from the apex of every convex vertex,
// a search along primary edges never leaves the polygon (a Voronoi edge meets the
// boundary only at an endpoint shared by its two sites).
// Contract: a validated Shape2 (shapes/validate_shape.h) mapped to the exact frame.
// Complexity: O(n log n) for n polygon vertices (Boost; the wide traits cost 8-13x the
// default's in bench_polygon_axis, the mp traits more); CGAL SDG is superlinear on dense
// samples of smooth curves with full-mantissa coordinates, where its interval filter fails
// more and more often (measured: experiments/bench_polygon_axis.cpp, notes fast2d2.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry2/point2.h"
#include "geometry2/shape2.h"

namespace grassfire {

// Sites in the exact frame: coordinates are exact doubles (scaled integers for Boost).
// Site ids: 0..n-1 are the polygon vertices (point sites); n + i is the segment from
// vertex i to next[i], with the polygon interior on its left.
struct PolygonSites {
  std::vector<Point2> vertex;
  std::vector<std::uint32_t> next;
  std::vector<std::uint32_t> prev;

  std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(vertex.size()); }
  std::uint32_t site_count() const { return 2 * vertex_count(); }
  bool is_point(std::uint32_t site) const { return site < vertex_count(); }
  // Endpoints of a segment site (start, end), interior on the left.
  std::uint32_t seg_start(std::uint32_t site) const { return site - vertex_count(); }
  std::uint32_t seg_end(std::uint32_t site) const { return next[site - vertex_count()]; }
  // Is point site p an endpoint of segment site s?
  bool is_endpoint(std::uint32_t p, std::uint32_t s) const { return seg_start(s) == p || seg_end(s) == p; }
};

// The rings of a shape, scaled by `scale` (exact when the products are exact).
PolygonSites make_sites(const Shape2& shape, double scale);

struct VoronoiTopology {
  struct Vertex {
    std::array<std::uint32_t, 3> sites{};  // counter-clockwise around the vertex
    bool apex = false;                     // a convex polygon vertex (sites[0] is its point)
  };
  struct Edge {
    std::uint32_t u = 0, v = 0;            // vertex ids
    std::uint32_t site_a = 0, site_b = 0;  // the two sites the edge separates
  };
  std::vector<Vertex> vertices;
  std::vector<Edge> edges;
};

// How the Boost constructions read the builder's output: from its events (the default,
// boost_voronoi_events.h), or from the full voronoi_diagram it would write (the reference
// the tests compare the events with; boost_voronoi_extract.h).
enum class BoostReader { Events, Diagram };

// Boost.Polygon construct_voronoi; every frame coordinate must be an integer in int32.
VoronoiTopology boost_segment_voronoi(const PolygonSites& sites, BoostReader reader = BoostReader::Events);
// Boost.Polygon's voronoi builder with the wide coordinate traits (boost_wide_traits.h):
// every frame coordinate an integer, each within 2^62 of the centre of the frame's bounding
// box (fits_wide_boost); throws std::invalid_argument otherwise, std::overflow_error if an
// exact intermediate exceeds 4096 bits (boost_wide_traits.h).
bool fits_wide_boost(const PolygonSites& sites);
VoronoiTopology boost_segment_voronoi_wide(const PolygonSites& sites, BoostReader reader = BoostReader::Events);
// Boost.Polygon's voronoi builder with the mp traits (boost_mp_traits.h): any finite double
// frame, taken exactly as integers x 2^K (no limit on the coordinates' span); O(n log n).
// `tier` reports the bits of those integers about the frame's centre and of the floats.
// `filtered`: the construction ran in the double-interval filter stage (number/
// filter_float.h), which takes exactly the MPFR run's branches; `fallbacks`: its node
// comparisons and circle events decided by the MPFR predicates (boost_mp_traits.h).
struct MpTier {
  int input_bits = 0;
  int float_bits = 0;
  bool filtered = false;
  std::uint64_t fallbacks = 0;
  // Verification mode only: decisions of the filter stage checked against the MPFR
  // predicates, and those that differ (or circles whose enclosures miss MPFR's values).
  std::uint64_t verified = 0, verify_mismatches = 0;
};
// filter = false skips the filter stage (the MPFR run alone: the reference it must equal);
// verify = true (tests; several times slower) checks every decision the filter stage takes
// itself against the MPFR predicates' (MpTier::verified, verify_mismatches).
VoronoiTopology boost_segment_voronoi_mp(const PolygonSites& sites, MpTier* tier = nullptr, bool filter = true,
                                         bool verify = false, BoostReader reader = BoostReader::Events);
// CGAL Segment_Delaunay_graph_2 (filtered exact traits, no intersecting segments).
VoronoiTopology cgal_segment_voronoi(const PolygonSites& sites);

// Is polygon vertex v strictly convex (interior angle < pi)?
bool is_convex_vertex(const PolygonSites& sites, std::uint32_t v);

}  // namespace grassfire
