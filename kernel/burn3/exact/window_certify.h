// window_certify.h -- certified decisions of the exact burning engine (docs/design.md 3, 5a).
//
// Computes the sign of the three quantities the window propagation decides with:
//  - side: where a point lies relative to a wedge ray of a window (the visibility
//    decisions; never over-extended);
//  - time difference: which of two windows reaches a vertex first (occupiers, vertex
//    pseudo-sources);
//  - direction order: the angular order of the rays of two windows at a vertex (the
//    one-angle-one-split rule of Xin and Wang 2009).
// Stages, each counted (CertificationCounts):
//  1. filter: Interval arithmetic on the windows' double discs;
//  2. structural: identical expressions are equal (the same pseudo-source through the same
//     sequence of frame changes, Window::anchor; a bound vertex that every later triangle
//     of the chain contains); along an edge, a point source S on it and the source it
//     relays at an edge point p (sigma = S's time at p) beyond which x lies, seen from S
//     (|x - S| = |x - p| + |p - S|: one value, even where p is known by a bracket only);
//  3. exact: windows of a rational pseudo-source whose chain crosses only rational
//     unfoldings (planar sheets, flat patches, cube-like meshes) are re-evaluated in
//     rational local coordinates, times as ExactSum (exact sign, ties included;
//     window_exact.cpp);
//  4. Arb: the chain is re-evaluated from the exact data (vertex coordinates, frames, the
//     root) at 128, 256, ... bits up to max_bits; each level is a rigorous enclosure;
//     Order: 1, 2, then Arb's first level (128 bits), then 3, then the rest of 4 (exact
//     sums of long rationals cost far more than one Arb evaluation; 3 settles the ties).
//  5. undecided: side decisions return 0 and count `uncertified` (the point is taken to lie
//     on the ray; right when the configuration is exactly collinear, the usual cause);
//     comparisons return kUndecided and the caller keeps every window (`kept_undecided`).
// Memo: a comparison that passes the filter is keyed by the identity of what it compares
// (front_id: windows with the same pseudo-source through the same frame changes, whose
// times are one expression; expression ids of time expressions built from them; the point
// by vertex or Certifier::point_key) and by the precision cap; asked again, the outcome of
// stages 2-5 is repeated (counted `memo`), not re-decided. The junction rule asks the same
// questions in every pass and for every window of the same front (exact ties between the
// sheets' fronts cost two or three Arb evaluations each time: 3 s of joint.ma's ...).
// Contract: windows in `store` as the engine builds them; targets are vertices of the
// window's triangle or exact points in its plane.
// Complexity: stage 1 O(1); stages 3-4 O(chain length) exact or Arb operations per level.
#pragma once

#include <memory>
#include <optional>
#include <unordered_map>

#include "burn3/exact/sources.h"
#include "burn3/exact/unfolding.h"
#include "burn3/exact/windows.h"

namespace grassfire {

// A point where a window is evaluated: a vertex of the window's triangle, an exact point,
// or a point of one of its edges (vertex = kEdgePointBound | edge point index).
struct Target {
  std::uint32_t vertex = kNoIndex;
  const ExactPoint3* point = nullptr;
  std::uint64_t key = 0;  // nonzero: names `point` for the memo (Certifier::point_key)
  // Set: `point` is a + *lambda (b - a) on this edge (a, b) (Arb images without the 3D point).
  std::uint32_t edge = kNoIndex;
  const mpq_class* lambda = nullptr;
};

struct WindowBall {
  BallVec2 source;  // S or u
  Ball offset;
  std::array<BallVec2, 2> image;
  bool plane = false;
};

class Certifier {
 public:
  // Side decisions escalate to max_bits; comparisons that only prune stop at prune_bits.
  Certifier(const Unfolding& u, const WindowStore& s, long max_bits, long prune_bits = 256)
      : u_(u), s_(s), max_bits_(max_bits), prune_bits_(prune_bits) {}

  int side(std::uint32_t w, int j, const Target& x);
  // side() without its last stage: kUndecided (nothing counted) where no stage decides; for
  // callers that stop there instead of taking the point as collinear (certified bisections).
  // arb_first: the Arb stage before the exact one (bisections: thousands of decisions near a
  // point that Arb settles at once, where the exact sums of long rationals cost far more).
  int side_if_certified(std::uint32_t w, int j, const Target& x, bool arb_first = false);
  // deciding: the outcome decides BT (the junction rule's order of arrivals), so the Arb
  // stage escalates to max_bits and an undecided outcome is the caller's to count as
  // `uncertified`; otherwise it only prunes (prune_bits; undecided counts kept_undecided).
  int compare_times(std::uint32_t w1, const Target& x1, std::uint32_t w2, const Target& x2, bool arb_first = false,
                    bool deciding = false);
  // Where w's ray j meets `edge` (an edge of w's triangle), from the Arb stage of
  // side_if_certified: its side function at the edge point a + l (b - a) is affine in l,
  // g0 + l g1, so one evaluation (at `bits`) gives a rational interval [lo, hi] holding the
  // root and the sign of the slope g1 (side = slope there for l > hi, -slope for l < lo);
  // nullopt where g1's sign is not certified.
  struct EdgeRoot {
    mpq_class lo, hi;
    int slope = 0;
  };
  std::optional<EdgeRoot> ray_root_on_edge(std::uint32_t w, int j, std::uint32_t edge, long bits);
  // Where w1's and w2's times cross along `edge` (an edge of both triangles) inside the
  // parameter interval [lo, hi]: the same Arb values as compare_times at a + l (b - a),
  // their difference f(l) proved monotone on [lo, hi] (the sign of f' over it) with
  // certified opposite signs at lo and hi, and its one root enclosed by interval Newton
  // steps (slope: the sign of f'; f = slope there for l > hi of the result, -slope for l <
  // its lo, both within [lo, hi]); nullopt where any of this is not certified.
  std::optional<EdgeRoot> crossing_root_on_edge(std::uint32_t w1, std::uint32_t w2, std::uint32_t edge, double lo,
                                                double hi, long bits);
  // The signs of f = time(w1) - time(w2) and of its derivative f' over the whole parameter
  // box [lo, hi] of `edge` (an edge of both triangles), in Arb at `bits`: {sign f, sign f'},
  // each kUndecided where its ball holds 0 (the exclusion and monotonicity proofs of the
  // crossings' isolation, edge_crossings.h).
  // bound (optional): an upper bound of |f| over the box from the same enclosures.
  std::array<int, 2> edge_difference_signs(std::uint32_t w1, std::uint32_t w2, std::uint32_t edge, const mpq_class& lo,
                                           const mpq_class& hi, long bits, double* bound = nullptr);
  // An upper bound of |time(w1) - time(w2)| over the whole parameter box [lo, hi] of `edge`,
  // from the same Arb enclosures at `bits` (inf where they are unbounded).
  double edge_difference_bound(std::uint32_t w1, std::uint32_t w2, std::uint32_t edge, const mpq_class& lo,
                               const mpq_class& hi, long bits);
  // A window's front along an edge a + l (b - a) of its triangle, in its frame (A + l D),
  // at the current BallPrecision.
  struct Along {
    WindowBall b;
    BallVec2 A, D;
  };
  Along along_edge(std::uint32_t w, std::uint32_t edge);
  long max_bits() const { return max_bits_; }
  int compare_directions(std::uint32_t w1, std::uint32_t w2, std::uint32_t v);
  // The identity of w's front (equal ids: the same source image and offset in the same
  // frame, as same_expression decides), and of a time expression (equal ids: one value).
  std::uint32_t front_id(std::uint32_t w);
  std::uint32_t expr_id(std::uint32_t expr);
  // A pseudo-source's offset expression was replaced (an absorbed tie): the front and
  // expression ids and the Arb chains, which name or hold offsets, are computed afresh.
  void source_time_changed() { front_ids_.clear(), expr_ids_.clear(), chain_memo_.clear(); }
  // A WindowAt target as the point it is: an edge point at parameter exactly 0 or 1 is that
  // end vertex of its edge.
  std::uint32_t canonical_point(std::uint32_t target) const;
  // A key naming the point of parameter `at` (a double, taken exactly) of an edge.
  std::uint64_t point_key(std::uint32_t edge, double at);

  // Enclosures at the double stage and at the current BallPrecision.
  DiscPoint target_disc(std::uint32_t t, const Target& x) const;
  BallVec2 target_ball(std::uint32_t t, const Target& x) const;
  Interval time_interval(std::uint32_t w, const Target& x) const;
  Ball time_ball(std::uint32_t w, const Target& x);
  // The chain re-evaluated in Arb; the offset only when asked (it recurses through the
  // offsets of the vertex sources the chain descends from).
  // `source_vertex` (not kNoIndex): the chain applied to that vertex of the first window's
  // triangle instead of the pseudo-source (edge_ray_origin).
  WindowBall evaluate(std::uint32_t w, bool with_offset, std::uint32_t source_vertex = kNoIndex);
  // The window's geometry in exact local coordinates of its frame (sums of square roots),
  // when its pseudo-source's position is exact and its chain's unfoldings keep the
  // coordinates small (see 3.); its offset is exact_sigma(pseudo), when that exists.
  using ExactVector = std::array<ExactSum, 2>;
  struct ExactWindow {
    std::uint32_t frame = 0;
    bool line = false;
    ExactVector s;     // point source
    ExactVector p, d;  // line source: a point, its direction; inner side sign
    int inner = 1;
    std::array<ExactVector, 2> image;
  };
  const ExactWindow* exact_window(std::uint32_t w);
  // The exact time of w at x, when exact_window(w) exists and the squared distance (or
  // the line's length) is rational or denests.
  std::optional<ExactSum> exact_time(std::uint32_t w, const Target& x);
  const ExactSum* exact_sigma(std::uint32_t pseudo);
  // |d|^2 in the frame's metric of a line window's exact direction d, when rational (or
  // proved equal to its border edge's squared length).
  std::optional<mpq_class> line_length2(std::uint32_t w);
  // Time expressions (windows.h): Arb and exact values, and the staged comparison
  // (kUndecided when no stage decides).
  Ball expr_ball(std::uint32_t expr);
  const ExactSum* exact_expr(std::uint32_t expr);
  // prune_only: the caller keeps everything when undecided (escalates to prune_bits only).
  int compare_time_exprs(std::uint32_t a, std::uint32_t b, bool prune_only = false);
  mpq_class edge_length2(std::uint32_t e) const;
  // An edge point's parameter in rationals [lo, hi] (exact, its bracket, or its enclosure).
  bool edge_point_bounds(const EdgePoint& ep, mpq_class* lo, mpq_class* hi) const;

  CertificationCounts counts;

 private:
  Ball sigma_ball(std::uint32_t pseudo);
  WindowBall evaluate_chain(std::uint32_t w, bool with_offset, std::uint32_t source_vertex);
  void trim_memos();  // only between decisions: pointers into the memo stay valid within one
  bool same_expression(std::uint32_t w1, std::uint32_t w2, const Target& x);
  std::uint32_t root_front(std::uint32_t w);
  // The front id of the point source `where` (a vertex, an edge point, a caller's point) at
  // its own place in `frame`, with offset expression id sigma - 1 (0: no offset).
  std::uint32_t point_front(std::uint64_t where, std::uint32_t frame, std::uint64_t sigma);
  bool point_on_edge(std::uint64_t p, std::uint32_t edge) const;
  bool same_point_source(std::uint32_t pa, std::uint32_t pb) const;
  bool relayed_along_edge(std::uint32_t relay, std::uint32_t w, const Target& x) const;
  bool bound_fixed(std::uint32_t w, int j, std::uint32_t v) const;
  std::optional<ExactVector> target_uv(std::uint32_t f, const Target& x) const;
  int exact_side(const ExactWindow& e, int j, const Target& x) const;
  int exact_direction_cross(const ExactWindow& a, const ExactWindow& b, std::uint32_t v) const;
  std::unique_ptr<ExactWindow> build_exact_window(std::uint32_t w, std::uint32_t source_vertex = kNoIndex);
  std::uint32_t edge_ray_origin(std::uint32_t w, int j) const;
  template <class F>
  int escalate(long cap, F&& sign_at_precision);

  struct MemoKey {
    std::uint64_t a, b, c;
    bool operator==(const MemoKey& o) const { return a == o.a && b == o.b && c == o.c; }
  };
  struct MemoHash {
    std::size_t operator()(const MemoKey& k) const {
      return std::hash<std::uint64_t>()(k.a * 0x9E3779B97F4A7C15ull ^ (k.b + 0x632BE59BD9B4E019ull) * 31 ^ k.c);
    }
  };
  std::uint32_t intern(const MemoKey& k);
  std::optional<int> recall(const MemoKey& k);
  int remember(const MemoKey& k, int outcome);

  const Unfolding& u_;
  const WindowStore& s_;
  long max_bits_, prune_bits_;
  std::unordered_map<MemoKey, std::uint32_t, MemoHash> ids_;  // front, expression and point ids
  std::vector<std::uint32_t> front_ids_, expr_ids_;           // per window / TimeExpr (+1; 0: none yet)
  std::unordered_map<std::uint32_t, std::array<std::uint64_t, 2>> point_fronts_;  // front id -> (where, sigma)
  std::unordered_map<MemoKey, int, MemoHash> decided_;
  mutable std::unordered_map<MemoKey, DiscPoint, MemoHash> disc_cache_;  // (frame, point key)
  mutable std::unordered_map<MemoKey, BallVec2, MemoHash> ball_cache_;   // (frame, point key, bits)
  std::unordered_map<long, std::unordered_map<std::uint32_t, Ball>> time_memo_;  // bits -> TimeExpr -> ball
  std::unordered_map<MemoKey, WindowBall, MemoHash> chain_memo_;  // (window, source vertex, bits and offset)
  std::unordered_map<MemoKey, std::array<BallVec2, 2>, MemoHash> edge_memo_;  // (frame, edge, bits): A, D
  std::unordered_map<std::uint32_t, std::unique_ptr<ExactWindow>> exact_memo_;
  std::unordered_map<std::uint32_t, std::unique_ptr<ExactSum>> exact_time_memo_;
};

}  // namespace grassfire
