// medial_complex.h -- the medial axis of a 3D shape as a non-manifold PL 2-complex (ch. 4).
//
// Computes, from a RawComplex: the edges (with their stratum: dangling segment, border,
// manifold, singular = M1 of 4.2.2), the cyclic order of the triangles around every edge,
// the sheets (components of triangles joined across manifold edges; joining only across
// manifold edges already splits sheets at pinch vertices), an exact planar frame per
// planar sheet (else per triangle), the link of every vertex with its sectors (fans of
// triangles between consecutive pole directions, 4.2.2 and Fig. 4.5), the vertex kinds
// (interior, border, singular curve, singular point, ...), and the ignition function f
// on border points (RawComplex rules; f = R by default). docs/design.md 5.
//
// Vocabulary of the link (the graph a small sphere around a point cuts out of M):
//  - link nodes are the incident edges (directions), link arcs are the incident triangles;
//  - a pole is an incident edge that is singular (>= 3 triangles) or a dangling segment;
//  - a sector is a maximal fan of incident triangles joined across non-pole edges; its two
//    ends are poles or free ends (border edges), or it is closed (a full circle without
//    poles, the neighbourhood of an interior point);
//  - the burning condition at a point (docs/design.md 5, Definition 9): with the arrived link
//    elements removed, the link contains no cycle (every disk type of Definition 8 is a
//    cycle of the link and must have received fire), and at most one segment direction is
//    left (the 2D rule of 3.3.1 for 1-dimensional parts). The condition is monotone: more
//    arrivals never falsify it (Lemma 2).
//  - a border point is a point at which the condition already holds with nothing arrived:
//    it ignites at f. The corner c of the board and fin (docs/design.md 5) has a circle in its
//    link and is not a border point, as Fig. 4.4 requires.
//
// Exactness: every combinatorial decision (degeneracy, duplicates, angular order around an
// edge, coplanarity of sheets) is an exact predicate on rational coordinates: an interval
// filter first, the rationals (gmpxx) only where the filter cannot decide
// (filtered_predicates3.h); the answers are those of the rational predicates of
// exact_predicates3.h. The double members are nearest approximations for drawing and for
// the approximate baseline.
// Contract (the constructor throws std::invalid_argument naming raw.source and the first
// violation): indices in range; no repeated vertex in a cell; distinct vertex positions;
// no degenerate (collinear) triangle; no duplicate triangle or segment; no segment that is
// also a triangle edge; R^2 >= 0; two triangles on one edge never lie in the same
// half-plane (a local overlap); border rules name border edges; no two cells meet outside
// their common faces (complex_intersections.h: CGAL box intersection and filtered exact
// predicates; can be skipped by the caller that already knows the complex is embedded).
// Frames are exact and computed when first asked for (triangle_frame, frames): a curved
// sheet has one per triangle, which most users never read.
// Complexity: construction O(n log n) filtered predicates (n = cells; a sort of the
// vertices, one per corner and per edge-triangle pair) plus O(k) filtered predicates for k
// overlapping bounding boxes; rational arithmetic only for the decisions the filter leaves
// (exact coplanarity in planar sheets, degenerate configurations); validate() the same
// without the embedding; a frame O(1) rationals; accessors O(1).
// Measured (bench_complex_build, Loop-refined closed meshes): see docs/benchmarks.md.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <memory>

#include "geometry3/exact_predicates3.h"
#include "geometry3/filtered_predicates3.h"
#include "complex3/raw_complex.h"
#include "geometry3/vec3.h"

namespace grassfire {

constexpr std::uint32_t kNoIndex = std::numeric_limits<std::uint32_t>::max();

enum class EdgeStratum : std::uint8_t { Dangling, Border, Manifold, Singular };
const char* to_string(EdgeStratum s);

enum class VertexKind : std::uint8_t {
  Isolated,         // empty link: a 0-dimensional part
  Interior,         // link = one circle of triangles (a point of M2)
  Border,           // link = one arc of triangles (a point of dM2)
  SegmentEnd,       // link = one segment direction: a leaf of a 1-dimensional part
  SegmentInterior,  // link = two segment directions and nothing else
  SingularCurve,    // link = two singular poles joined by k >= 3 sector arcs (a point of M1)
  SingularPoint     // anything else (M0): junctions of singular curves, pinches, curve ends
};
const char* to_string(VertexKind k);

struct ComplexVertex {
  ExactPoint3 exact;
  Vec3d approx{};
  mpq_class radius_squared;
  double radius = 0.0;  // nearest double to sqrt(radius_squared)
  VertexKind kind = VertexKind::Isolated;
};

struct ComplexEdge {
  std::array<std::uint32_t, 2> v{};  // v[0] < v[1]
  EdgeStratum stratum = EdgeStratum::Dangling;
  double length = 0.0;
  IgnitionRule rule = IgnitionRule::Linear;  // meaningful on border edges
  ExactPoint3 rule_point;                    // for DistanceToPoint
  Vec3d rule_point_approx{};
};

struct ComplexTriangle {
  std::array<std::uint32_t, 3> v{};
  std::array<std::uint32_t, 3> e{};  // e[i] is the edge opposite v[i]
  std::uint32_t sheet = 0;
};

// The corner of t at vertex v (0, 1, 2), or -1.
inline int corner_of(const ComplexTriangle& t, std::uint32_t v) {
  return t.v[0] == v ? 0 : t.v[1] == v ? 1 : t.v[2] == v ? 2 : -1;
}
// The two edges of t incident to its vertex v (v must be a vertex of t).
inline std::array<std::uint32_t, 2> edges_at(const ComplexTriangle& t, std::uint32_t v) {
  const int i = corner_of(t, v);
  return {t.e[(i + 1) % 3], t.e[(i + 2) % 3]};
}
// The vertex of t not on the edge with ends ab.
inline std::uint32_t third_vertex(const ComplexTriangle& t, const std::array<std::uint32_t, 2>& ab) {
  for (std::uint32_t v : t.v)
    if (v != ab[0] && v != ab[1]) return v;
  return t.v[0];
}

// An exact frame of a plane: p = origin + u e1 + v e2 with e1 . e2 = 0; squared lengths
// are u^2 |e1|^2 + v^2 |e2|^2, so local coordinates and squared distances stay rational.
struct PlanarFrame {
  ExactPoint3 origin, e1, e2, normal;  // normal = e1 x e2
  mpq_class e1_norm2, e2_norm2;
  std::array<mpq_class, 2> local(const ExactPoint3& p) const;  // exact for points of the plane
  bool contains(const ExactPoint3& p) const;                   // exact coplanarity test
};
// The frame of the plane of triangle abc: origin a, e1 = b - a.
PlanarFrame frame_of_triangle(const ExactPoint3& a, const ExactPoint3& b, const ExactPoint3& c);

struct Sheet {
  std::vector<std::uint32_t> triangles;
  bool planar = false;  // all vertices coplanar (exact); then frame is the sheet's plane
  std::uint32_t frame = kNoIndex;
};

struct Sector {
  std::uint32_t apex = 0;
  std::uint32_t sheet = 0;
  std::vector<std::uint32_t> triangles;  // in fan order
  // The incident edges that bound the fan, in fan order: poles, or border edges (free
  // ends); kNoIndex for both when the fan is closed (a circle without pole).
  std::array<std::uint32_t, 2> ends{kNoIndex, kNoIndex};
  bool closed = false;
};

// An element of the link of a vertex for the burning rule: a pole or a sector.
struct LinkElement {
  bool is_pole = false;
  std::uint32_t id = 0;  // edge id of a pole, sector id of a sector
};

class MedialComplex {
 public:
  explicit MedialComplex(const RawComplex& raw, bool check_embedding = true);

  // Re-checks the contract and every derived structure; throws std::logic_error naming
  // the first violation. Every test calls it after every construction.
  void validate() const;

  const std::string& source() const { return source_; }
  std::size_t vertex_count() const { return vertices_.size(); }
  std::size_t edge_count() const { return edges_.size(); }
  std::size_t triangle_count() const { return triangles_.size(); }
  const ComplexVertex& vertex(std::uint32_t v) const { return vertices_[v]; }
  const ComplexEdge& edge(std::uint32_t e) const { return edges_[e]; }
  const ComplexTriangle& triangle(std::uint32_t t) const { return triangles_[t]; }
  const std::vector<ComplexVertex>& vertices() const { return vertices_; }
  const std::vector<ComplexEdge>& edges() const { return edges_; }
  const std::vector<ComplexTriangle>& triangles() const { return triangles_; }

  // Triangles around an edge, in exact angular order about the directed line v[0] -> v[1].
  const std::vector<std::uint32_t>& edge_triangles(std::uint32_t e) const { return edge_triangles_[e]; }
  const std::vector<std::uint32_t>& vertex_edges(std::uint32_t v) const { return vertex_edges_[v]; }
  const std::vector<std::uint32_t>& vertex_triangles(std::uint32_t v) const { return vertex_triangles_[v]; }
  // The edge {a, b}, or kNoIndex.
  std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const;

  const std::vector<Sheet>& sheets() const { return sheets_; }
  // Every frame, indexed as Sheet::frame and triangle_frame_index (computes those not yet
  // computed: one per planar sheet, one per triangle of every other sheet).
  const std::vector<PlanarFrame>& frames() const;
  // The sheet's frame when the sheet is planar, else the triangle's own frame (computed at
  // the first call, then kept; safe to call from several threads).
  const PlanarFrame& triangle_frame(std::uint32_t t) const;
  std::uint32_t triangle_frame_index(std::uint32_t t) const { return triangle_frame_[t]; }
  std::size_t frame_count() const { return frame_triangle_.size(); }

  const std::vector<Sector>& sectors() const { return sectors_; }
  // The link elements of vertex v: its poles (in vertex_edges order), then its sectors.
  const std::vector<LinkElement>& link_elements(std::uint32_t v) const { return link_elements_[v]; }
  // The local element index, at triangle t's corner i, of the sector containing t.
  std::uint32_t corner_element(std::uint32_t t, int i) const { return corner_element_[3 * t + i]; }
  // The local element index at edge e's end j (vertex e.v[j]) of the direction along e:
  // the pole itself, or the sector that contains (or ends at) e.
  std::uint32_t edge_end_element(std::uint32_t e, int j) const { return edge_end_element_[2 * e + j]; }

  // The burning condition at vertex v (see above) when the link elements flagged in
  // `arrived` have received fire: a removed pole takes its link node (and the arcs at it)
  // away, a removed sector its arcs. `arrived.size()` must equal link_elements(v).size().
  bool link_burns(std::uint32_t v, const std::vector<bool>& arrived) const;
  // The same at an interior point of an edge with `triangle_count` triangles, whose link is
  // two poles (the directions along the edge) joined by one arc per triangle; pole0/pole1:
  // fire arrived along the edge from the side of v[0] / v[1].
  static bool edge_link_burns(std::size_t triangle_count, bool pole0, bool pole1, std::size_t arrived_triangles);

  bool is_border_point(std::uint32_t v) const { return border_point_[v]; }
  bool is_singular_point(std::uint32_t v) const { return vertices_[v].kind == VertexKind::SingularPoint; }
  // f at a border vertex: the minimum over its border edges' rules (Linear gives R), R when
  // it has none; +infinity at a vertex that is not a border point (it never ignites).
  double ignition_at_vertex(std::uint32_t v) const { return vertex_ignition_[v]; }
  // f at the point (1 - s) v[0] + s v[1] of border edge e, 0 <= s <= 1 (+infinity for Never).
  double ignition_on_edge(std::uint32_t e, double s) const;

  std::size_t count(EdgeStratum s) const;
  std::size_t count(VertexKind k) const;
  // How the construction's predicates were decided: by the interval filter or exactly.
  const FilterCounts& filter_counts() const { return filter_counts_; }

 private:
  struct FrameStore;  // frames computed on demand (medial_complex_frames.cpp)
  void check_raw(const RawComplex& raw, const FilteredPoints& points) const;
  void build_edges(const RawComplex& raw, const FilteredPoints& points);
  void add_edge(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t> tris, int segments,
                std::uint32_t segment_id, const FilteredPoints& points);
  void build_incidences();
  void order_edge_triangles(const FilteredPoints& points);
  void build_sheets(const FilteredPoints& points);
  static std::shared_ptr<FrameStore> make_frame_store(std::size_t frames);
  const PlanarFrame& frame(std::uint32_t f) const;
  void validate_frames() const;
  void build_sectors();
  void classify_vertices();
  VertexKind classify_link(std::uint32_t v) const;
  Sector trace_fan(std::uint32_t v, std::uint32_t t) const;
  bool is_pole(std::uint32_t e) const;
  void apply_ignition(const RawComplex& raw);
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void fail_overlap(std::uint32_t t0, std::uint32_t t1, std::uint32_t e) const;

  std::string source_;
  std::vector<ComplexVertex> vertices_;
  std::vector<ComplexEdge> edges_;
  std::vector<ComplexTriangle> triangles_;
  std::vector<std::vector<std::uint32_t>> edge_triangles_;
  std::vector<std::vector<std::uint32_t>> vertex_edges_;
  std::vector<std::vector<std::uint32_t>> vertex_triangles_;
  std::vector<Sheet> sheets_;
  std::vector<std::uint32_t> triangle_frame_;  // frame index per triangle
  std::vector<std::uint32_t> frame_triangle_;  // per frame, the triangle whose plane it spans
  std::shared_ptr<FrameStore> frame_store_;
  FilterCounts filter_counts_;
  std::vector<Sector> sectors_;
  std::vector<std::vector<LinkElement>> link_elements_;
  std::vector<std::uint32_t> corner_element_;
  std::vector<std::uint32_t> edge_end_element_;
  std::vector<bool> border_point_;
  std::vector<double> vertex_ignition_;
};

}  // namespace grassfire
