// windows.h -- pseudo-sources and windows of the exact burning engine (ch. 4, 5.2).
//
// A pseudo-source is a place where fire starts at a known time: a point source given by
// the caller, a vertex that burns (ignition f(v), or reached by a window where the front
// must bend: border, wall and saddle vertices), the rotated point of a DistanceToPoint
// border edge, or a plane wave along a Linear border edge with slope below 1.
// A window is one front piece inside one triangle t: the pseudo-source's image S in t's
// frame (after unfolding), its offset (time at S; for a plane wave time = c + u.X), and its
// wedge, bounded by the rays from S through two vertex images B0 (clockwise side, as seen
// from S in t's frame) and B1; it covers t's points in the closed wedge, entering through
// its entry edge (or starting inside t: a root window). Windows live on (edge, side)
// pairs: the entry edge and the triangle entered (one window set per sheet side of an edge,
// as the junction rules of 4.2 need).
// Exact definition (what the certified stages re-evaluate): S is the root position mapped
// by the unfoldings of the windows' chain (parent links back to the pseudo-source's first
// window); bound j is the vertex bound[j] taken exactly in the frame of the chain window at
// depth bound_depth[j], then unfolded the same way. The double members are disc enclosures.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "complex3/medial_complex.h"
#include "number/disc_point.h"
#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

enum class SourceOrigin : std::uint8_t {
  GivenPoint,   // a caller's point source (point location: data = given source index)
  Vertex,       // a vertex: `vertex`, sigma given (spawn == kNoIndex) or a window's value there
  BorderPoint,  // DistanceToPoint: the rule point rotated into the sheet (data = border edge)
  BorderPlane,  // Linear with |slope| < 1: a plane wave (data = border edge)
  EdgePoint     // a burned point of a singular edge (a kink of the junction rule, or the end
                // of a burned stretch): a point source into every sheet side (data = edge point)
};

// A point of an edge, (1 - lambda) v[0] + lambda v[1]: the kinks and piece ends of the
// junction rule (4.2.1). lambda is exact (exact_times[exact]: a sum of square roots, e.g.
// the board-and-fin kink's sqrt2 - 1) or, where no closed form was found, only a certified
// enclosure (exact < 0; the decisions that depend on it then stop at the Arb stage).
struct EdgePoint {
  std::uint32_t edge = kNoIndex;
  Interval lambda;
  std::int32_t exact = -1;
  // Without an exact value: the certified bracket lo <= lambda <= hi with rational ends
  // (narrower than `lambda`, a double enclosure), for the Arb stage; none when !bracketed.
  bool bracketed = false;
  mpq_class lo, hi;
  // A certified crossing (kink_parameter): the two windows whose times are equal here by the
  // point's defining equation (the only root of their difference in the bracket); else none.
  std::array<std::uint32_t, 2> equal_windows{kNoIndex, kNoIndex};
};
// A wedge bound or a TimeExpr::WindowAt target with this bit set names edge_points[id & ~bit]
// instead of a vertex.
constexpr std::uint32_t kEdgePointBound = 0x80000000u;
inline bool is_edge_point(std::uint32_t id) { return id != kNoIndex && (id & kEdgePointBound); }

// A time as an exact expression (the offsets of vertex sources, the burn times of
// vertices): evaluated as an Interval (cached), in Arb, and exactly when its parts are.
struct TimeExpr {
  enum class Kind : std::uint8_t {
    Exact,     // exact_times[a]: an ignition f(v), a source's start, 0
    WindowAt,  // the time of window a at vertex b (or at an edge point: kEdgePointBound)
    Plus,      // time a plus the length of edge b (fire along a segment)
    Min,       // min(time a, time b): an unprovable tie kept as both
    Enclosure  // known only as its certified enclosure `value` (no exact or Arb refinement)
  };
  Kind kind = Kind::Exact;
  std::uint32_t a = kNoIndex, b = kNoIndex;
  Interval value;
};

struct PseudoSource {
  SourceOrigin origin = SourceOrigin::GivenPoint;
  std::uint32_t vertex = kNoIndex;  // Vertex
  std::uint32_t data = kNoIndex;    // GivenPoint: source index; Border*: edge id
  std::uint32_t sector = kNoIndex;  // Vertex: the sector it emits into
  std::uint32_t time = kNoIndex;    // its offset as a TimeExpr (plane waves: their R at the edge)
  std::int32_t exact = -1;          // index of its ExactSource, or -1
  std::uint32_t first_root = kNoIndex, root_count = 0;  // its first windows, consecutive
  Interval sigma;                   // the offset's enclosure given to its windows
};

// A pseudo-source with rational data (docs/design.md 5a): a point (a vertex, or a rational 3D
// point) with an offset that is a sum of square roots, or a plane wave of slope 0 (time
// sigma + distance to the line of a border edge, on its triangle's side). A window whose
// chain crosses only rational unfoldings (Unfolding::rational_crossing; none at all inside
// a planar sheet) is evaluated exactly from it: rational local coordinates, squared
// distances rational, times in ExactSum (the offset comes from the pseudo-source's
// TimeExpr, exactly when its parts are exact).
struct ExactSource {
  bool line = false;
  std::uint32_t vertex = kNoIndex;  // point: a vertex, else `point`
  ExactPoint3 point;
  std::uint32_t edge = kNoIndex;    // line: the border edge
};

// A caller's point source, located in a triangle (closed), igniting at `start`.
struct GivenSource {
  std::uint32_t triangle = kNoIndex;
  ExactPoint3 point;
  mpq_class start;
};


struct Window {
  static constexpr std::uint8_t kPlane = 1;      // plane wave: source = unit direction u
  static constexpr std::uint8_t kDead = 2;       // dominated (evicted); skipped everywhere
  static constexpr std::uint8_t kProcessed = 16;

  std::uint32_t pseudo = kNoIndex;
  std::uint32_t parent = kNoIndex;   // kNoIndex: the pseudo-source's first window
  std::uint32_t triangle = kNoIndex; // t
  std::uint32_t edge = kNoIndex;     // entry edge; kNoIndex for root windows (S in closed t)
  std::array<std::uint32_t, 2> bound{kNoIndex, kNoIndex};
  std::array<std::uint32_t, 2> bound_depth{0, 0};
  std::uint32_t depth = 0;
  std::uint32_t first_child = kNoIndex, next_sibling = kNoIndex;
  std::uint32_t anchor = kNoIndex;   // the nearest ancestor-or-self where the frame changed
                                     // (or the first window): equal anchors, equal source image
  DiscPoint source;                  // S, or u for a plane wave
  std::array<DiscPoint, 2> image;    // images of bound[0], bound[1]
  Interval offset;                   // sigma, or c (time = c + u . X)
  double key = 0.0;                  // certified lower bound of the window's times
  std::uint8_t flags = 0;
  std::uint8_t exits = 0;            // root windows: bit i = exit through the edge t.e[i]

  bool plane() const { return flags & kPlane; }
  bool dead() const { return flags & kDead; }
  bool root() const { return edge == kNoIndex; }
};

struct WindowStore {
  std::vector<PseudoSource> pseudo;
  std::vector<ExactSource> exact;
  std::vector<Window> windows;
  std::vector<GivenSource> given;
  std::vector<TimeExpr> times;
  std::vector<ExactSum> exact_times;
  std::vector<EdgePoint> edge_points;
};

// An event of the sweep: a vertex source made (fire restarts at a vertex, through one
// sector), a vertex burned by the link rule, a kink of a singular edge (the (k-1)-th
// arrival switches window there: a point source into every side), or the end of a burned
// stretch of a singular edge next to a stretch with fewer than k - 1 arrivals (fire runs on
// along the curve from there); its time as a TimeExpr.
struct SweepEvent {
  enum class Kind : std::uint8_t { VertexSource, VertexBurn, Kink, StretchEnd };
  Kind kind = Kind::VertexSource;
  std::uint32_t id = 0;  // sector (VertexSource), vertex (VertexBurn), edge point (Kink, StretchEnd)
  std::uint32_t time = 0;
};

// Per-stage counts of the certified decisions (docs/design.md 3).
struct CertificationCounts {
  std::uint64_t filter = 0;         // decided by the double (disc / interval) filter
  std::uint64_t exact = 0;          // decided (nonzero) by exact rational / square-root arithmetic
  std::uint64_t arb = 0;            // decided by an Arb re-evaluation of the unfolding chain
  std::uint64_t exact_equal = 0;    // proved zero by exact arithmetic
  std::uint64_t structural_equal = 0;  // proved zero by identical expressions
  std::uint64_t kept_undecided = 0; // pruning comparisons left undecided: nothing pruned
  std::uint64_t uncertified = 0;    // wedge decisions no stage certified: taken as collinear
  std::uint64_t negligible_ties = 0;  // two fronts within 2^-64 on a stretch of an edge, no order
                                      // proved: each moves BT by at most 2^-64 (edge_crossings.h),
                                      // added to every bt_error (pipeline/burn3d_exact.cpp)
  std::uint64_t memo = 0;           // comparisons asked before (same fronts, point, cap): repeated
  long max_bits = 0;                // highest Arb precision used
  void merge(const CertificationCounts& o);
};

}  // namespace grassfire
