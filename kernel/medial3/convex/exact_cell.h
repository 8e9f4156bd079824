// exact_cell.h -- a convex polytope cut by half-spaces, every decision certified.
//
// Computes: the cell  P ∩ {h_1 <= 0} ∩ ... ∩ {h_m <= 0}  of a convex polytope P, as
// outward-oriented polygonal faces, where each h is a plane with coefficients in a
// multiquadratic field (number/multiquadratic.h, RadicalNumber). Both medial-axis builders are cell
// computations: the cell of a face of a convex polyhedron (the points for which that face
// is the nearest, bounded by bisector planes), and the Voronoi cell of a vertex of the
// boundary of a union of balls inside one tetrahedron of its alpha complex.
// Every vertex keeps its support: the set of planes known to pass through it (those that
// created it, and every later plane that evaluated to exactly zero at it). Builders turn
// supports into global keys, so that the same point computed in different cells is
// recognised without comparing coordinates.
// Decisions (docs/design.md 3): side of a vertex = the support test, then a double interval
// filter, then a caller-supplied structural zero (a plane known to contain the point:
// the filter can never certify a nonzero sign there, so asking it first changes no
// decision and spares the oracle on most tests), then the exact sign of  a X + b Y + c Z + d W  over the field (X, Y, Z, W homogeneous
// coordinates of the vertex from its three defining planes, by Cramer's rule).
// Contract: the initial polytope is bounded, full-dimensional, with outward
// counter-clockwise faces; planes of one cell live in one PlaneSet.
// Complexity: O(vertices of the cell) sign tests per clip; exact work only when the
// filter fails (counted in ClipStats).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "number/multiquadratic.h"
#include "complex3/raw_complex.h"

namespace grassfire {

constexpr std::uint32_t kNoPlane = std::numeric_limits<std::uint32_t>::max();

// The plane a x + b y + c z + d = 0; the kept side is a x + b y + c z + d <= 0. The exact
// coefficients may be given, or made on first use by `make` (most planes are only ever
// evaluated by the interval filter). The enclosures may be taken in local coordinates
// x - o about an origin o of the caller's choice (then d is enclosed as d + (a, b, c) . o),
// which keeps them tight far from the global origin; the vertex enclosures of the cells
// are then local too. Exact coefficients are always global.
class CellPlane {
 public:
  using Coefficients = std::array<RadicalNumber, 4>;
  CellPlane(Coefficients coef, std::uint64_t label);
  CellPlane(std::function<Coefficients()> make, const std::array<Interval, 4>& approx, std::uint64_t label);
  CellPlane(Coefficients coef, const std::array<Interval, 4>& approx, std::uint64_t label);
  const Coefficients& coef() const;
  const std::array<Interval, 4>& approx() const { return approx_; }
  std::uint64_t label() const { return label_; }

 private:
  mutable std::shared_ptr<const Coefficients> coef_;
  std::function<Coefficients()> make_;
  std::array<Interval, 4> approx_;
  std::uint64_t label_ = 0;  // the builder's name for the plane
};
CellPlane make_cell_plane(std::array<RadicalNumber, 4> coef, std::uint64_t label);
// The plane a x + b y + c z + d = 0 with rational coefficients.
CellPlane rational_plane(const mpq_class& a, const mpq_class& b, const mpq_class& c, const mpq_class& d,
                         std::uint64_t label);

struct HomogeneousPoint {
  std::array<RadicalNumber, 4> c;  // X, Y, Z, W: the point (X/W, Y/W, Z/W), W != 0
  int w_sign = 1;
};

// The point on three independent planes, by Cramer's rule (exact; W != 0 is checked).
HomogeneousPoint point_on_planes(const std::array<RadicalNumber, 4>& a, const std::array<RadicalNumber, 4>& b,
                                 const std::array<RadicalNumber, 4>& c, NumberStats* stats = nullptr);

// A vertex kept beyond the life of its cell: an interval enclosure now, the exact
// coordinates (from copies of its three planes, whose exact coefficients are themselves
// made on first use) when asked. Not thread-safe.
class LazyPoint3 {
 public:
  explicit LazyPoint3(const ExactPoint3& p);  // a rational point
  LazyPoint3(std::array<CellPlane, 3> planes, const std::array<Interval, 3>& approx);
  explicit LazyPoint3(std::shared_ptr<const HomogeneousPoint> exact, const std::array<Interval, 3>& approx);
  const HomogeneousPoint& exact() const;
  const std::array<Interval, 3>& approx() const { return approx_; }
  const ExactPoint3* rational() const { return rational_ ? &point_ : nullptr; }

 private:
  std::vector<CellPlane> planes_;  // three, or none for a rational or given point
  std::array<Interval, 3> approx_;
  bool rational_ = false;
  ExactPoint3 point_;
  mutable std::shared_ptr<const HomogeneousPoint> exact_;
};

struct CellVertex {
  std::vector<std::uint32_t> support;  // sorted ids of the planes through the point
  std::array<std::uint32_t, 3> defining{kNoPlane, kNoPlane, kNoPlane};
  std::array<Interval, 3> approx;
  std::shared_ptr<const HomogeneousPoint> exact;  // computed on demand
};

struct CellFace {
  std::vector<std::uint32_t> vertices;  // counter-clockwise seen from outside
  std::vector<std::uint32_t> planes;    // planes containing the face; [0] made it
};

struct ClipStats {
  std::uint64_t sign_tests = 0;
  std::uint64_t by_support = 0;
  std::uint64_t by_structure = 0;
  std::uint64_t by_filter = 0;
  std::uint64_t by_exact = 0;
  std::uint64_t exact_points = 0;
  NumberStats number;
  void merge(const ClipStats& o);
};

// The planes of one computation, the optional structural-zero oracle and the counters.
class PlaneSet {
 public:
  using StructuralZero = std::function<bool(std::uint32_t plane, const CellVertex& v)>;

  std::uint32_t add(CellPlane p);
  const CellPlane& operator[](std::uint32_t id) const { return planes_[id]; }
  std::size_t size() const { return planes_.size(); }
  void set_structural_zero(StructuralZero f) { structural_zero_ = std::move(f); }

  // Exact side (-1, 0, +1) of v with respect to plane `id`.
  int side(std::uint32_t id, const CellVertex& v);
  // The exact homogeneous coordinates of v (cached in v).
  const HomogeneousPoint& exact(const CellVertex& v);
  // A vertex on three independent planes, with its interval enclosure.
  CellVertex vertex_on(std::array<std::uint32_t, 3> defining, std::vector<std::uint32_t> support);

  ClipStats stats;

 private:
  std::vector<CellPlane> planes_;
  StructuralZero structural_zero_;
};

// A vertex at a given rational point (a corner of the initial polytope), enclosed in local
// coordinates about `origin`.
CellVertex rational_vertex(const ExactPoint3& p, std::vector<std::uint32_t> support,
                           const std::array<double, 3>& origin = {0, 0, 0});

class ConvexCell {
 public:
  enum class Clip { Untouched, Cut, Emptied };

  // The polytope with these vertices and faces (vertex ids into `vertices`).
  ConvexCell(PlaneSet& planes, std::vector<CellVertex> vertices, std::vector<CellFace> faces);

  // Intersects the cell with the kept side of plane `id`.
  Clip clip(std::uint32_t id);

  bool empty() const { return faces_.empty(); }
  const std::vector<CellFace>& faces() const { return faces_; }
  const CellVertex& vertex(std::uint32_t v) const { return vertices_[v]; }
  PlaneSet& planes() const { return *planes_; }

 private:
  std::uint32_t crossing_vertex(std::uint32_t a, std::uint32_t b, std::uint32_t face_plane);
  void finish_crossings(std::uint32_t id);

  PlaneSet* planes_;
  std::vector<CellVertex> vertices_;
  std::vector<CellFace> faces_;
  // Per clip: side of each vertex, and the vertices created on cut edges.
  std::vector<int> side_;
  struct Crossing {
    std::uint32_t a, b, vertex;
    std::array<std::uint32_t, 2> face_planes;
  };
  std::vector<Crossing> crossings_;
  std::vector<char> used_;                                      // vertices on some face
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cap_next_;  // edges of the new face
};

}  // namespace grassfire
