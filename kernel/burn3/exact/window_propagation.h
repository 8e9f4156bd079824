// window_propagation.h -- the event loop of the exact burning engine: fronts (windows)
// propagated across the sheets of a medial complex (4.2.3, 5.2; docs/design.md 5).
//
// Computes: every window that can realise the burning time BT inside the sheets, from the
// caller's point sources and the border ignition rules, with Definition 9 at singular
// edges (the junction rule, edge_junction.cpp: arrivals recorded per sheet side, including
// fronts that only graze the edge; the edge burns at the (k-1)-th arrival; its pieces
// continue into the other sides as child windows across the edge, kinks and stretch ends
// as EdgePoint point sources) and at vertices with segments or singular poles (the link
// rule, vertex_burning.cpp); ExactBurningOptions::singular_walls keeps the walls of docs/exact-engine.md ("--singular-walls").
// The method is Chen and Han's window propagation with the improvements of Xin and Wang
// 2009 (ICH, as in CGAL's Surface_mesh_shortest_path): a priority queue ordered by a
// certified lower bound of each window's times (so that, as in Dijkstra's algorithm, every
// time below the current key is final), pseudo-sources at vertices where paths bend
// (sector_geometry.h), and two pruning rules, each applied only on a certified decision:
//  - vertex filter. A child window C on an exit edge with ends a, b is dropped when
//    time(X1) > d(a) + |a X1| (X1 the end of C farther from a), or the same for b, or, for
//    the entry edge's vertex c not on the exit edge, time(Y) > d(c) + |c Y| at the end Y of
//    the parent's entry interval farther from c; d(v) is the time of a real path to v in
//    the same sector. Proof: along a line through v, time_w(X) - |v X| is non-increasing as
//    X moves away from v (|grad time| <= 1), so the inequality at the far end holds on the
//    whole interval, and for c every ray of C passes the entry interval (time(X) = time(Y)
//    + |Y X| >= ... ); beyond the edge the path through v and then straight is a real path
//    that is strictly shorter, so C carries no burning path.
//  - one angle, one split (Xin and Wang): of the windows entering a triangle through one
//    edge and reaching the opposite vertex o, only the earliest at o (the occupier)
//    continues on both sides of o; a later one continues only on the side of o from which
//    its ray comes (and an occupier that loses its place loses the other side's subtree).
// An undecided comparison prunes nothing (Certifier: kept_undecided). Visibility is never
// extended: a wedge side is decided by Certifier::side, and an undecided side is counted
// `uncertified`. Exact ties (symmetric inputs) are proved by exact arithmetic on planar
// sheets, or by identical expressions, so that tied vertex sources are created once.
// Contract: a validated MedialComplex and its Unfolding; point sources located in closed
// triangles (coordinates exact, in the triangle's plane: std::invalid_argument otherwise).
// Complexity: O(W log W) for W windows (W is O(n^2) in the worst case, about O(n^1.5) on
// meshes in practice) plus the certified fallbacks; memory O(W).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <vector>

#include "burn3/exact/edge_fronts.h"
#include "burn3/exact/engine_mutant.h"
#include "burn3/exact/sector_geometry.h"
#include "burn3/exact/window_certify.h"
#include "burn3/exact/window_values.h"

namespace grassfire {

struct ExactBurningOptions {
  bool vertex_filter = true;          // the vertex filter (tests switch it off to compare)
  bool one_angle_one_split = true;
  // Singular edges as walls (docs/exact-engine.md; `burn3d --singular-walls`): fronts stop there and
  // no junction rule runs. Not Definition 9: an upper bound of BT (fire from the curves is left out).
  bool singular_walls = false;
  long max_bits = 512;                // Arb precision cap of the certified stages
  EngineMutant mutant = EngineMutant::none;  // checks only: a deliberate breakage (engine_mutant.h)
  std::uint64_t max_windows = 400'000'000;  // iteration bound (std::runtime_error beyond)
  // Progress reports only: after every event of the sweep, its key (a lower bound of its
  // time), the events so far and the windows created (support/progress.h via the pipeline).
  std::function<void(double key, std::uint64_t events, std::uint64_t windows)> on_event{};
};

struct PropagationStats {
  std::uint64_t windows = 0;          // created (incl. roots and arrival records)
  std::uint64_t processed = 0;        // popped and propagated
  std::uint64_t filtered = 0;         // children dropped by the vertex filter
  std::uint64_t split_pruned = 0;     // children not created by one angle, one split
  std::uint64_t evicted = 0;          // windows killed as dominated (subtrees, old sources)
  std::uint64_t pseudo_sources = 0;
  std::uint64_t ties_absorbed = 0;    // unprovable ties folded into an existing vertex source
  std::uint64_t vertex_events = 0;    // a window reaching a vertex
  std::uint64_t wall_arrivals = 0;    // children reaching a singular edge (walls: stopped there)
  std::uint64_t vertex_burns = 0;     // vertices burned by the link rule
  std::uint64_t segment_arrivals = 0; // fire reaching a vertex along a segment
  std::uint64_t border_arrivals = 0;  // children that reached a border edge
  std::uint64_t undecided_angles = 0; // sectors taken to bend without a certified angle
  // Junction rule on singular edges (4.2.1; edge_junction.cpp):
  std::uint64_t junction_records = 0; // arrivals of a window at a singular edge (per sheet side)
  std::uint64_t junction_passes = 0;  // recomputations of an edge's (k-1)-th arrival
  std::uint64_t merges = 0;           // pieces emitted: a front continued across a burned curve
  std::uint64_t quenched = 0;         // arrivals that realise no piece (the front ends at the curve)
  std::uint64_t kinks = 0;            // kink points: point sources where the (k-1)-th arrival switches
  std::uint64_t stretch_ends = 0;     // ends of burned stretches next to unburned ones
  // Piece ends located only by an enclosure no stage certified, and neighbouring
  // breakpoints whose order no stage proved (edge_junction.cpp, break_order).
  std::uint64_t uncertified_breaks = 0;
  // Junction decisions no stage certified at max_bits (each also counted in the certifier's
  // `uncertified`): pairs of records whose crossings were not all isolated, orders of
  // arrivals and coverages at a point of an elementary interval.
  std::uint64_t uncertified_crossings = 0;
  std::uint64_t uncertified_orders = 0;
  std::uint64_t crossing_boxes = 0;   // boxes examined by the crossings' isolation (cost)
  double seconds = 0.0;
};

class WindowPropagation {
 public:
  WindowPropagation(const Unfolding& u, const ExactBurningOptions& o);

  // A point source igniting at `start`; the point must lie in the closed triangle.
  void add_point_source(std::uint32_t triangle, const ExactPoint3& point, const mpq_class& start);
  // A point source at vertex v (any vertex): v burns at `start`.
  void add_vertex_source(std::uint32_t v, const mpq_class& start);
  // Every border rule of the complex (Linear, DistanceToPoint, Never) and f at border vertices.
  void add_border_ignition();
  void run();

  const WindowStore& store() const { return s_; }
  Certifier& certifier() { return cert_; }
  const PropagationStats& stats() const { return stats_; }
  const std::vector<SweepEvent>& events() const { return events_; }
  const SectorGeometry& sectors() const { return sectors_; }
  // The burn time (TimeExpr) of a vertex decided by the link rule (vertices with
  // segments), kNoIndex otherwise or if it never burns.
  std::uint32_t link_burn_time(std::uint32_t v) const {
    return link_of_[v] == kNoIndex ? kNoIndex : links_[link_of_[v]].burned;
  }
  bool is_link_rule_vertex(std::uint32_t v) const { return link_of_[v] != kNoIndex; }
  bool walls() const { return o_.singular_walls; }
  // After run(): the switch points of the singular edges' (k-1)-th arrival, from each edge's
  // final pieces: a point of the edge (inside it, or a vertex where the curve runs on into
  // another singular edge) where the realising record changes between two burned pieces (edge_junction.cpp; classified by junction_points.h). `point` is an
  // edge point (exact parameter where a closed form exists), `left` and `right` the windows
  // realising the arrival just below and just above its parameter, `time` BT there.
  // At a vertex v of a singular curve (two singular edges at v, no link rule there): `edge`
  // and `point` are the edge arriving at v and its end point at v (`left` realises A on it),
  // `edge2` and `point2` the edge leaving v and its end point (`right` realises A there);
  // kNoIndex for a switch inside one edge.
  struct JunctionSwitch {
    std::uint32_t edge, point, left, right, time;
    std::uint32_t edge2 = kNoIndex, point2 = kNoIndex;
  };
  std::vector<JunctionSwitch> junction_switches();

 private:
  // Events: a window to propagate, fire arriving at a vertex along a segment, a vertex
  // burning by the link rule. At equal keys arrivals come before burns (a burn's key is an
  // upper bound of its time: every arrival below it must have been seen).
  enum class EventKind : std::uint8_t { Window = 0, SegmentArrival = 1, VertexSource = 2, VertexBurn = 3, Junction = 4 };
  struct QueueEntry {
    double key;
    std::uint32_t id;
    EventKind kind = EventKind::Window;
    bool operator>(const QueueEntry& o) const {
      if (key != o.key) return key > o.key;
      if (kind != o.kind) return kind > o.kind;
      return id > o.id;
    }
  };
  // The link rule's state at a vertex with segments (part 1) or poles (part 2): the first
  // arrival per link element (TimeExpr, kNoIndex: none yet), the ignition (fixed), and the
  // burn time once decided.
  struct LinkState {
    std::vector<std::uint32_t> arrival;
    std::uint32_t fixed = kNoIndex;
    std::uint32_t burned = kNoIndex;
  };
  struct SegmentArrival {
    std::uint32_t vertex, element, time;
  };
  // A wedge bound while building a child: a vertex, its image in the parent's frame, and
  // the depth at which that image is exact.
  struct Bound {
    std::uint32_t vertex;
    DiscPoint image;
    std::uint32_t depth;
  };
  // An arrival of fire at a singular edge through one of its sheet sides (4.2.1): a window
  // of that side's triangle, its wedge bounds (clockwise, counter-clockwise) in its frame,
  // and where its rays through them meet the edge (parameter along v[0] -> v[1], doubles:
  // only to order the breakpoints; every decision is certified at rational points).
  struct JunctionRecord {
    std::uint32_t window;
    std::uint32_t side;     // the window's triangle (one sheet side of the edge)
    std::array<Bound, 2> end;
    std::array<double, 2> at;
    std::array<double, 2> at_err{0.0, 0.0};  // |true parameter - at| <= at_err (the discs' radii)
    bool on_edge = false;   // its source lies on the edge (emits into every side already)
    bool grazing = false;   // a wedge ray runs along the edge: nothing to emit beyond the edge
    std::array<Interval, 4> line{};  // A.x, A.y, B.x - A.x, B.y - A.y: the edge in the window's frame
  };
  // A breakpoint of an edge's (k-1)-th arrival: an end of the edge, a record's end, or a
  // crossing of two records' times; `id` names it (edge-point sources and emitted pieces
  // are made once per name).
  struct Break {
    double at;
    std::uint64_t id;
  };
  struct Piece {
    std::uint32_t record;  // kNoIndex: fewer than k - 1 sides arrived
    Break lo, hi;
  };
  // Where two records' times cross along the edge (computed once per pair of records).
  struct Crossing {
    Break at;
    std::uint32_t a, b;  // the records
    bool bracketed = false;  // [lo, hi] holds the crossing (edge_crossings.h); else sampled
    mpq_class lo, hi;
  };
  struct JunctionState {
    std::vector<std::uint32_t> records;
    std::vector<Piece> emitted;          // (record, interval) already continued across the edge
    std::vector<std::uint64_t> sources;  // break ids with an edge-point source
    std::vector<std::pair<std::uint64_t, std::uint32_t>> points;  // break id -> edge point
    std::vector<Crossing> crossings;     // of every pair among records[0, paired)
    std::set<std::pair<std::uint64_t, std::uint64_t>> ordered;  // breakpoint pairs whose order was examined
    std::size_t paired = 0;
    std::vector<Piece> pieces;  // of the last pass (recomputed when records arrived)
    std::size_t counted = 0;            // records[0, counted) were known to that pass
    std::vector<std::uint32_t> alive;   // the records alive then
    bool dirty = false;
    double pending = std::numeric_limits<double>::infinity();
  };

  void process(std::uint32_t w);
  void process_root(std::uint32_t w);
  void process_entered(std::uint32_t w);
  std::pair<bool, bool> reach_opposite(std::uint32_t w, int corner);
  void vertex_arrival(std::uint32_t w, std::uint32_t v, std::uint32_t sector);
  void process_vertex_source(std::uint32_t sector, double key);
  void make_child(std::uint32_t w, int exit_slot, int icw, int iccw, const Bound& b0, const Bound& b1,
                  const DiscPoint* third, std::uint32_t third_vertex);
  bool filtered(std::uint32_t w, std::uint32_t a, std::uint32_t b, const DiscPoint& x0, const DiscPoint& x1,
                const DiscPoint* third, std::uint32_t third_vertex);
  std::uint32_t spawn_vertex_source(std::uint32_t v, std::uint32_t sector, std::uint32_t time);
  std::uint32_t new_time(TimeExpr e);
  std::uint32_t exact_time(const ExactSum& x);
  std::uint32_t window_time_at(std::uint32_t w, std::uint32_t v);
  // Vertex v burns at the given time (ignition, a point source on it, the link rule):
  // every sector (and segment) receives fire from it.
  void burn_vertex_at(std::uint32_t v, std::uint32_t time);
  std::uint32_t new_window(Window w);
  void add_root(std::uint32_t pseudo, std::uint32_t t, std::uint8_t exits, double key);
  void add_border_window(std::uint32_t pseudo, std::uint32_t e);
  void kill_subtree(std::uint32_t w);
  void kill_child_through(std::uint32_t w, std::uint32_t edge);
  double vertex_bound(std::uint32_t t, std::uint32_t v) const;

  // The junction rule on singular edges (edge_junction.cpp).
  void junction_arrival(std::uint32_t w, std::uint32_t edge, const Bound& b0, const Bound& b1, const DiscPoint& x0,
                        const DiscPoint& x1, bool grazing);
  void graze_singular_edges(std::uint32_t w, int entry_slot, int exit_slot);
  void schedule_junction(std::uint32_t edge, double key);
  void process_junction(std::uint32_t edge, double key);
  std::vector<Break> junction_breaks(std::uint32_t edge, const std::vector<std::uint32_t>& recs);
  void break_order(std::uint32_t edge, const Break& a, const Break& b);
  std::uint32_t realising_record(std::uint32_t edge, const std::vector<std::uint32_t>& recs, double at);
  int record_covers(std::uint32_t edge, std::uint32_t r, double at, const std::function<const Target&()>& x);
  std::vector<Piece> junction_pieces(std::uint32_t edge);
  double piece_time_lo(std::uint32_t edge, const Piece& p) const;
  std::vector<Piece> unemitted_parts(const JunctionState& st, const Piece& p) const;
  void pair_new_records(std::uint32_t edge);
  Interval record_time(std::uint32_t edge, std::uint32_t r, double at) const;
  Bound piece_bound(std::uint32_t edge, const JunctionRecord& r, const Break& b);
  std::uint32_t break_point(std::uint32_t edge, const Break& b);
  void emit_piece(std::uint32_t edge, const Piece& p);
  void edge_point_source(std::uint32_t edge, const Break& b, std::uint32_t record, SweepEvent::Kind kind);
  void enter_child(std::uint32_t w, std::uint32_t edge, std::uint32_t t2, const Bound& b0, const Bound& b1, double key);
  bool source_on_edge(std::uint32_t w, std::uint32_t edge) const;
  bool same_point_as_source(std::uint32_t edge, std::uint32_t ep);
  void count_quenched();
  ExactPoint3 edge_point3(std::uint32_t edge, double at) const;

  void init_links();
  bool is_link_vertex(std::uint32_t v) const { return link_of_[v] != kNoIndex; }
  void link_arrival(std::uint32_t v, std::uint32_t element, std::uint32_t time);
  std::uint32_t link_candidate(std::uint32_t v);
  void schedule_burn(std::uint32_t v);
  void process_burn(std::uint32_t v, double key);
  void process_segment_arrival(std::uint32_t a);
  void emit_from_vertex(std::uint32_t v, std::uint32_t time);
  void claim_sector(std::uint32_t sector, std::uint32_t time);
  std::uint32_t min_time(std::uint32_t a, std::uint32_t b);

  const Unfolding& u_;
  const MedialComplex& mc_;
  ExactBurningOptions o_;
  WindowStore s_;
  Certifier cert_;
  SectorGeometry sectors_;
  PropagationStats stats_;
  std::priority_queue<QueueEntry, std::vector<QueueEntry>, std::greater<QueueEntry>> queue_;
  std::vector<std::uint32_t> occupier_;      // 3 t + corner
  std::vector<std::uint32_t> best_time_;     // per sector: the earliest known arrival at its apex (TimeExpr)
  std::vector<double> best_hi_;              // per sector: upper bound of a real path's time to the apex
  std::vector<std::uint32_t> sector_source_; // per sector: its current vertex pseudo-source
  std::vector<std::uint32_t> link_of_;       // vertex -> index into links_, or kNoIndex
  std::vector<LinkState> links_;
  std::vector<SegmentArrival> segment_arrivals_;
  std::vector<SweepEvent> events_;
  std::vector<std::uint32_t> junction_of_;   // edge -> index into junctions_, or kNoIndex
  std::vector<JunctionState> junctions_;
  std::vector<JunctionRecord> records_;
  EdgeFronts edge_fronts_;                   // the records' closed forms along their edges (edge_crossings.h)
};

}  // namespace grassfire
