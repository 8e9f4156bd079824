// edge_junction.cpp -- the junction rule of Definition 9 on singular edges (4.2.1, 4.2.3;
// docs/design.md 5; part of WindowPropagation, window_propagation.h).
//
// A singular edge E with k sheet sides (triangles) keeps every arrival of fire through
// each side: a window of that side's triangle whose wedge meets E (a record). With a_i(x)
// the earliest arrival through side i at the point x of E, x burns at A(x), the (k-1)-th
// smallest a_i(x), or earlier if fire runs along the curve to it (MedialComplex::
// edge_link_burns). A is 1-Lipschitz along E (order statistics of 1-Lipschitz functions
// are), so fire along the curve matters only next to stretches where fewer than k - 1
// sides ever arrive; the point sources below supply it.
// From the burned curve fire enters every sheet side (entering a side that arrived earlier
// is harmless: those times never realise the minimum there):
//  - piece: a maximal interval of E on which one record w realises A. w's front, unfolded
//    across E into each other side (the same source, rotated about E), with its wedge cut
//    to the rays through the piece's ends, is a child window there (a front continues
//    across the curve: a merge);
//  - kink: where the realising record changes, the two pieces' wedges leave a gap where A
//    has a convex corner (Fig. 4.4: the board-and-fin kink at s = 2 + sqrt2); the point
//    itself burns at A there and emits as a point source into every side (an EdgePoint
//    pseudo-source), which fills the gap with A(k) + |x - k|; where the pieces overlap
//    instead, the source is dominated and harmless;
//  - stretch end: the end of a burned stretch next to one with fewer than k - 1 arrivals
//    emits the same way; its own arrivals on E (every side) are A(k) + |x - k|, so the
//    unburned stretch then burns by fire along the curve;
//  - poles: a piece ending at a vertex of E is an arrival along the curve at that vertex
//    (its link rule, vertex_burning.cpp), which decides the singular points.
// Finality (Dijkstra): a record's times are at least its key, so when the queue reaches T
// every arrival below T is known; a piece is emitted as soon as T reaches the lower bound
// of its times (so that no window is made after the sweep passed its key: the link rule's
// decisions at singular points rely on it), kinks and stretch ends once T passes their
// time, and pieces are recomputed (junction_passes) while records still arrive. Every emission is
// fire of a real burning path (an upper bound of BT); every decision is certified: the
// crossings of every pair of records are isolated in certified brackets (edge_crossings.h:
// exact candidate roots, else certified subdivision; no sample decides), so between the
// breakpoints no two records change order and the order of arrivals at one rational point
// of an elementary interval (Certifier::compare_times, deciding: up to max_bits) holds on
// all of it; a record covers that point by its double range outside the certified margins
// of its ends and by certified side tests inside them (record_covers); proved ties take the
// older record (equal times), so sources made on the edge never re-realise their own
// pieces; the pieces' ends are edge points whose parameter is exact where a closed form is
// found (junction_kinks.h) and a certified enclosure otherwise. What no stage settles is
// counted `uncertified` (uncertified_crossings, uncertified_orders, uncertified_breaks:
// also the order of two breakpoints whose enclosures overlap, break_order), never decided
// by a default.
// Complexity: per pass O(B R) certified comparisons for R records and B breakpoints
// (B = O(R^2) crossings at worst; R is small: the windows of one triangle per side).
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "burn3/exact/edge_crossings.h"
#include "burn3/exact/junction_kinks.h"
#include "burn3/exact/window_propagation.h"
#include "geometry3/exact_predicates3.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint64_t kEdgeEnd = 0, kRecordEnd = 1ull << 60, kCrossing = 2ull << 60;

std::uint64_t crossing_id(std::uint32_t a, std::uint32_t b, int root) {
  return kCrossing | (std::uint64_t(std::min(a, b)) << 30) | (std::uint64_t(std::max(a, b)) << 1) | std::uint64_t(root);
}

}  // namespace

ExactPoint3 WindowPropagation::edge_point3(std::uint32_t edge, double at) const {
  const ExactPoint3& a = mc_.vertex(mc_.edge(edge).v[0]).exact;
  const ExactPoint3& b = mc_.vertex(mc_.edge(edge).v[1]).exact;
  const mpq_class l(at);  // exact value of the double
  return a + l * (b - a);
}

bool WindowPropagation::source_on_edge(std::uint32_t w, std::uint32_t edge) const {
  const Window& W = s_.windows[w];
  if (!W.root()) return false;
  const PseudoSource& ps = s_.pseudo[W.pseudo];
  const auto& ev = mc_.edge(edge).v;
  switch (ps.origin) {
    case SourceOrigin::Vertex: return ps.vertex == ev[0] || ps.vertex == ev[1];
    case SourceOrigin::EdgePoint: return s_.edge_points[ps.data].edge == edge;
    case SourceOrigin::GivenPoint: {
      const ExactPoint3& p = s_.given[ps.data].point;
      const ExactPoint3& a = mc_.vertex(ev[0]).exact;
      return cross(mc_.vertex(ev[1]).exact - a, p - a) == ExactPoint3{};
    }
    default: return false;
  }
}

void WindowPropagation::junction_arrival(std::uint32_t w, std::uint32_t edge, const Bound& b0, const Bound& b1,
                                         const DiscPoint& x0, const DiscPoint& x1, bool grazing) {
  const Window& W = s_.windows[w];
  const auto& ev = mc_.edge(edge).v;
  const DiscPoint A = u_.vertex_image(W.triangle, ev[0]), B = u_.vertex_image(W.triangle, ev[1]);
  auto param = [&](const DiscPoint& x, const Bound& b) {
    if (b.vertex == ev[0]) return 0.0;
    if (b.vertex == ev[1]) return 1.0;
    const double dx = B.x - A.x, dy = B.y - A.y;
    return std::clamp(((x.x - A.x) * dx + (x.y - A.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  };
  // |t~ - t| for t = (x - A).(B - A) / |B - A|^2 with x, A, B within their radii (and the
  // roundings): a margin for the coverage filter (record_covers), which decides by certified
  // side tests inside it.
  auto param_err = [&](const DiscPoint& x, const Bound& b) {
    if (b.vertex == ev[0] || b.vertex == ev[1]) return 0.0;
    const double dx = B.x - A.x, dy = B.y - A.y, len = std::sqrt(dx * dx + dy * dy);
    const double moved = A.r + B.r, t = std::fabs(((x.x - A.x) * dx + (x.y - A.y) * dy) / (dx * dx + dy * dy));
    if (!(len > 4 * moved) || !std::isfinite(t)) return kInf;
    return 2 * ((x.r + A.r + (1 + t) * moved) / (len - moved) + 1e-15 * (1 + t));
  };
  JunctionRecord r{w, W.triangle, {b0, b1}, {param(x0, b0), param(x1, b1)}, {param_err(x0, b0), param_err(x1, b1)},
                   source_on_edge(w, edge), grazing};
  r.line = {A.ix(), A.iy(), B.ix() - A.ix(), B.iy() - A.iy()};
  JunctionState& st = junctions_[junction_of_[edge]];
  st.records.push_back(static_cast<std::uint32_t>(records_.size()));
  records_.push_back(r);
  ++stats_.junction_records;
  st.dirty = true;
  schedule_junction(edge, std::max(W.key, approx_lower_bound(W, x0, x1)));
}

void WindowPropagation::schedule_junction(std::uint32_t edge, double key) {
  JunctionState& st = junctions_[junction_of_[edge]];
  if (key >= st.pending) return;
  st.pending = key;
  queue_.push({key, edge, EventKind::Junction});
}

// ---- the (k-1)-th arrival along the edge ---------------------------------------------------

// The crossings of every new record with every earlier one (a pair's crossings never
// change, so each pair is computed once: the passes only filter out dead records).
void WindowPropagation::pair_new_records(std::uint32_t edge) {
  JunctionState& st = junctions_[junction_of_[edge]];
  for (std::size_t i = st.paired; i < st.records.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const std::uint32_t ra = st.records[j], rb = st.records[i];
      const JunctionRecord &a = records_[ra], &b = records_[rb];
      if (s_.windows[a.window].dead() || s_.windows[b.window].dead()) continue;  // dead stays dead
      const double lo = std::max(std::min(a.at[0], a.at[1]), std::min(b.at[0], b.at[1]));
      const double hi = std::min(std::max(a.at[0], a.at[1]), std::max(b.at[0], b.at[1]));
      if (!(lo < hi)) continue;
      if (o_.mutant == EngineMutant::sampled_crossings) {
        const std::vector<double> roots = approx_crossings(u_, s_, edge, a.window, b.window, lo, hi);
        for (std::size_t k = 0; k < roots.size(); ++k)
          st.crossings.push_back({{roots[k], crossing_id(ra, rb, static_cast<int>(k))}, ra, rb, false, 0, 0});
        continue;
      }
      // Over the union of the two ranges' margins (a crossing just outside the double range
      // is harmless; one inside must not be missed).
      const double mlo = std::max(0.0, lo - std::max(a.at_err[0], a.at_err[1]) - std::max(b.at_err[0], b.at_err[1]));
      const double mhi = std::min(1.0, hi + std::max(a.at_err[0], a.at_err[1]) + std::max(b.at_err[0], b.at_err[1]));
      const EdgeCrossings c = isolate_crossings(u_, s_, cert_, edge_fronts_, edge, a.window, b.window, mpq_class(mlo), mpq_class(mhi));
      stats_.crossing_boxes += c.boxes;
      cert_.counts.negligible_ties += c.negligible;
      if (c.undecided) ++stats_.uncertified_crossings, ++cert_.counts.uncertified;
      if (c.roots.size() > 2) ++stats_.uncertified_crossings, ++cert_.counts.uncertified;  // ids hold two
      for (std::size_t k = 0; k < std::min<std::size_t>(2, c.roots.size()); ++k) {
        Crossing x{{c.roots[k].at, crossing_id(ra, rb, static_cast<int>(k))}, ra, rb, true, c.roots[k].lo, c.roots[k].hi};
        st.crossings.push_back(std::move(x));
      }
    }
  st.paired = st.records.size();
}

std::vector<WindowPropagation::Break> WindowPropagation::junction_breaks(std::uint32_t edge,
                                                                          const std::vector<std::uint32_t>& recs) {
  // Record ends at their double parameters (record_covers decides coverage near them by
  // certified side tests); crossings at their certified brackets' midpoints. Each with its
  // certified enclosure from the double stage: an edge end exactly, a record's end within
  // its margin, a crossing inside its bracket.
  std::vector<std::pair<Break, Interval>> en{{{0.0, kEdgeEnd | 0}, Interval(0.0)}, {{1.0, kEdgeEnd | 1}, Interval(1.0)}};
  for (std::uint32_t r : recs)
    for (int j = 0; j < 2; ++j) {
      const double at = records_[r].at[j], e = records_[r].at_err[j];
      if (at > 0.0 && at < 1.0)
        en.push_back({{at, kRecordEnd | (std::uint64_t(r) << 1) | std::uint64_t(j)}, {round_down(at - e), round_up(at + e)}});
    }
  pair_new_records(edge);
  for (const Crossing& c : junctions_[junction_of_[edge]].crossings)
    if (!s_.windows[records_[c.a].window].dead() && !s_.windows[records_[c.b].window].dead())
      en.push_back({c.at, c.bracketed ? Interval{std::nextafter(c.lo.get_d(), -kInf), std::nextafter(c.hi.get_d(), kInf)}
                                      : Interval{-kInf, kInf}});
  std::sort(en.begin(), en.end(), [](const auto& x, const auto& y) {
    return x.first.at < y.first.at || (x.first.at == y.first.at && x.first.id < y.first.id);
  });
  // The double order is the true one where neighbours' certified enclosures are disjoint;
  // elsewhere it is proved from the points themselves (break_order), or counted.
  std::vector<Break> br;
  for (std::size_t i = 0; i < en.size(); ++i) {
    if (i + 1 < en.size() && !(en[i].second.hi < en[i + 1].second.lo))
      break_order(edge, en[i].first, en[i + 1].first);
    br.push_back(en[i].first);
  }
  // Equal parameters name one point: keep the smallest name (stable as records arrive).
  br.erase(std::unique(br.begin(), br.end(), [](const Break& x, const Break& y) { return x.at == y.at; }), br.end());
  return br;
}

// Whether the breakpoints a <= b (by their doubles, their double-stage enclosures
// overlapping) are in that order, or one point: their edge points' certified
// parameters (exact, a bracket, an enclosure: break_point) disjoint, or both exact and
// compared exactly, or within 2^-65 of arc length of each other (a negligible tie). What
// none proves is counted in `uncertified_breaks`, once per pair.
void WindowPropagation::break_order(std::uint32_t edge, const Break& a, const Break& b) {
  if ((a.id >> 60) == 0 && (b.id >> 60) == 0) return;  // the edge's two ends
  JunctionState& st = junctions_[junction_of_[edge]];
  if (!st.ordered.insert({std::min(a.id, b.id), std::max(a.id, b.id)}).second) return;
  const EdgePoint pa = s_.edge_points[break_point(edge, a)], pb = s_.edge_points[break_point(edge, b)];
  mpq_class alo, ahi, blo, bhi;
  if (cert_.edge_point_bounds(pa, &alo, &ahi) && cert_.edge_point_bounds(pb, &blo, &bhi) && (ahi < blo || bhi < alo)) {
    if (bhi < alo) ++stats_.uncertified_breaks, ++cert_.counts.uncertified;  // proved the other way round
    return;
  }
  if (pa.exact >= 0 && pb.exact >= 0 && exact_sign(s_.exact_times[pb.exact] - s_.exact_times[pa.exact]) >= 0) return;
  // Both within a stretch of arc length d with 2 d <= 2^-64: whichever order is taken, the
  // record given to the sliver between them realises A at a point of it (certified at the
  // elementary interval's midpoint) and A is 1-Lipschitz, so A and the fire emitted there
  // move by at most 2 d: a negligible tie (2^-64 added to every error, burn_outputs.h).
  if (cert_.edge_point_bounds(pa, &alo, &ahi) && cert_.edge_point_bounds(pb, &blo, &bhi)) {
    const mpq_class d = std::max(ahi, bhi) - std::min(alo, blo);
    if (4 * d * d * cert_.edge_length2(edge) <= mpq_class(1, 1) / (mpq_class(1) << 128)) {
      ++cert_.counts.negligible_ties;
      return;
    }
  }
  ++stats_.uncertified_breaks, ++cert_.counts.uncertified;
}

// Whether record r covers the point x of parameter `at` (1, 0; kUndecided): the double range
// decides outside the margins of its ends, the certified side test of the window's ray
// through the end's bound vertex inside them (an end at a vertex of the edge is exact).
int WindowPropagation::record_covers(std::uint32_t edge, std::uint32_t r, double at,
                                     const std::function<const Target&()>& x) {
  const JunctionRecord& rec = records_[r];
  const int lo_end = rec.at[0] <= rec.at[1] ? 0 : 1, hi_end = 1 - lo_end;
  const double lo = rec.at[lo_end], hi = rec.at[hi_end];
  if (lo + rec.at_err[lo_end] < at && at < hi - rec.at_err[hi_end]) return 1;
  if (at < lo - rec.at_err[lo_end] || at > hi + rec.at_err[hi_end]) return 0;
  const Window& W = s_.windows[rec.window];
  const auto& ev = mc_.edge(edge).v;
  for (int j = 0; j < 2; ++j) {
    const Bound& b = rec.end[j];
    if (b.vertex == ev[0] || b.vertex == ev[1]) continue;  // the range reaches that end of the edge
    const double margin = rec.at_err[j];
    if (std::fabs(at - rec.at[j]) > margin) {  // outside this end's margin: the range decides it
      if ((j == lo_end && at < lo) || (j == hi_end && at > hi)) return 0;
      continue;
    }
    if (W.root() || b.vertex != W.bound[j] || b.depth != W.bound_depth[j]) return kUndecided;
    const int sg = cert_.side_if_certified(rec.window, j, x());
    if (sg == kUndecided) return kUndecided;
    if (sg == (j == 0 ? -1 : 1)) return 0;  // inside the closed wedge: side(B0) >= 0 >= side(B1)
  }
  return 1;
}

// The record realising the (k-1)-th arrival at the parameter `at` (strictly inside an
// elementary interval), or kNoIndex when fewer than k - 1 sides have arrived there. Every
// order and coverage is certified (deciding comparisons escalate to max_bits); a proved
// tie takes the older record (equal times: either realises the same value); what no stage
// settles is counted uncertified (uncertified_orders) and the older record is taken.
std::uint32_t WindowPropagation::realising_record(std::uint32_t edge, const std::vector<std::uint32_t>& recs,
                                                  double at) {
  // The double filter first (enclosures of each record's time there); the staged
  // comparison at the exact rational point only where those overlap.
  std::optional<ExactPoint3> p;
  mpq_class lambda;  // p's parameter (its Arb images: Unfolding::edge_param_ball)
  std::optional<Target> xt;
  const std::function<const Target&()> x = [&]() -> const Target& {
    if (!xt) p = edge_point3(edge, at), lambda = mpq_class(at), xt = Target{kNoIndex, &*p, cert_.point_key(edge, at), edge, &lambda};
    return *xt;
  };
  std::vector<Interval> value(recs.size());
  for (std::size_t i = 0; i < recs.size(); ++i) value[i] = record_time(edge, recs[i], at);
  bool undecided = false;
  std::vector<std::array<std::size_t, 3>> staged;  // (ri, qi, outcome): each pair decided once
  auto earlier = [&](std::size_t ri, std::size_t qi) {  // record ri before qi (ties: older first)
    int c = certified_sign(value[ri] - value[qi]);
    if (c == kUndecided) {
      const auto [a, b] = std::minmax(ri, qi);
      const auto it = std::find_if(staged.begin(), staged.end(), [&](const auto& s) { return s[0] == a && s[1] == b; });
      if (it != staged.end()) {
        c = static_cast<int>((*it)[2]) - 2;
      } else {
        c = cert_.compare_times(records_[recs[a]].window, x(), records_[recs[b]].window, x(), false, true);
        staged.push_back({a, b, static_cast<std::size_t>(c + 2)});
        if (c == kUndecided) undecided = true;
      }
      if (ri != a && c != kUndecided) c = -c;
    } else {
      ++cert_.counts.filter;
    }
    return c == -1 || ((c == 0 || c == kUndecided) && recs[ri] < recs[qi]);
  };
  const auto& sides = mc_.edge_triangles(edge);
  std::vector<std::size_t> best(sides.size(), kNoIndex);  // per side: its earliest record
  for (std::size_t ri = 0; ri < recs.size(); ++ri) {
    const std::uint32_t r = recs[ri];
    const int covers = record_covers(edge, r, at, x);
    if (covers == 0) continue;
    if (covers == kUndecided) undecided = true;  // taken as covering
    const std::size_t i = std::find(sides.begin(), sides.end(), records_[r].side) - sides.begin();
    if (best[i] == kNoIndex || earlier(ri, best[i])) best[i] = ri;
  }
  std::vector<std::size_t> arrived;
  for (std::size_t ri : best)
    if (ri != kNoIndex) arrived.push_back(ri);
  // Definition 9: the (k-1)-th arrival of k sides (the mutants: the k-th, the first).
  std::size_t rank = sides.size() - 2;
  if (o_.mutant == EngineMutant::kth_arrival) rank = sides.size() - 1;
  if (o_.mutant == EngineMutant::first_arrival) rank = 0;
  std::uint32_t r = kNoIndex;
  if (arrived.size() > rank) {
    std::sort(arrived.begin(), arrived.end(), earlier);
    r = recs[arrived[rank]];
  }
  if (undecided) ++stats_.uncertified_orders, ++cert_.counts.uncertified;
  return r;
}

// A record's time at the point of parameter `at` of the edge, as a double enclosure.
Interval WindowPropagation::record_time(std::uint32_t, std::uint32_t r, double at) const {
  const JunctionRecord& rec = records_[r];
  const Interval l(at);
  const Approx t = approx_time(s_.windows[rec.window],
                               DiscPoint::from_intervals(rec.line[0] + l * rec.line[2], rec.line[1] + l * rec.line[3]));
  return {round_down(t.v - t.e), round_up(t.v + t.e)};
}

// The (k-1)-th arrival at a point depends only on the records whose range covers it, so a
// pass recomputes it only inside the ranges of the records added (or dead) since the last
// pass, and elsewhere takes the realising record of the last pass's piece there (no
// breakpoint appears outside those ranges, so each elementary interval there lies inside
// one old piece).
std::vector<WindowPropagation::Piece> WindowPropagation::junction_pieces(std::uint32_t edge) {
  JunctionState& st = junctions_[junction_of_[edge]];
  std::vector<std::uint32_t> recs;
  for (std::uint32_t r : st.records)
    if (!s_.windows[records_[r].window].dead()) recs.push_back(r);
  std::vector<std::array<double, 2>> changed;
  auto range_of = [&](std::uint32_t r) {  // with the margins of its ends (record_covers)
    const auto& at = records_[r].at;
    const double err = std::max(records_[r].at_err[0], records_[r].at_err[1]);
    changed.push_back({std::min(at[0], at[1]) - err, std::max(at[0], at[1]) + err});
  };
  for (std::size_t i = st.counted; i < st.records.size(); ++i) range_of(st.records[i]);
  for (std::uint32_t r : st.alive)
    if (s_.windows[records_[r].window].dead()) range_of(r);
  const std::vector<Piece> old = std::move(st.pieces);
  constexpr std::uint32_t kRecompute = kNoIndex - 1;
  auto previous = [&](double m) {
    for (const auto& c : changed)
      if (c[0] <= m && m <= c[1]) return kRecompute;
    const auto it = std::lower_bound(old.begin(), old.end(), m, [](const Piece& p, double x) { return p.hi.at < x; });
    return it != old.end() && it->lo.at < m && m < it->hi.at ? it->record : kRecompute;
  };
  const std::vector<Break> br = junction_breaks(edge, recs);
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i + 1 < br.size(); ++i) {
    if (!(br[i].at < br[i + 1].at)) continue;
    const double m = 0.5 * (br[i].at + br[i + 1].at);
    std::uint32_t r = previous(m);
    if (r == kRecompute) r = realising_record(edge, recs, m);
    if (!pieces.empty() && pieces.back().record == r) {
      pieces.back().hi = br[i + 1];
      continue;
    }
    pieces.push_back({r, br[i], br[i + 1]});
  }
  st.counted = st.records.size();
  st.alive = std::move(recs);
  return pieces;
}

// A certified lower bound of a piece's times (its record's time along the piece).
double WindowPropagation::piece_time_lo(std::uint32_t edge, const Piece& p) const {
  const Window& W = s_.windows[records_[p.record].window];
  const auto& ev = mc_.edge(edge).v;
  const DiscPoint A = u_.vertex_image(W.triangle, ev[0]), B = u_.vertex_image(W.triangle, ev[1]);
  auto at = [&](double l) {
    const Interval L(l);
    return DiscPoint::from_intervals(A.ix() + L * (B.ix() - A.ix()), A.iy() + L * (B.iy() - A.iy()));
  };
  return approx_lower_bound(W, at(p.lo.at), at(p.hi.at));
}

// Timing (Dijkstra finality, as for windows): every window must be made before the sweep
// passes its key. So a piece is continued across the edge as soon as the sweep reaches the
// lower bound of its times, with the records known then: its fire is real (the (k-1)-th
// arrival of the known records is never below the true one) and its children's keys are
// not below the sweep. A record arriving later can lower the (k-1)-th arrival only where it
// is above the sweep (every arrival below the sweep is known), so a later pass emits the
// new pieces there, and the fire emitted before is dominated, never wrong. Parts of a piece
// already continued for the same record are not emitted twice (unemitted_parts). A kink or
// stretch end is a burned point: it emits once the sweep passes the upper end of its time
// there, when that time is final.
void WindowPropagation::process_junction(std::uint32_t edge, double key) {
  JunctionState& st = junctions_[junction_of_[edge]];
  st.pending = kInf;
  ++stats_.junction_passes;
  if (st.dirty) st.pieces = junction_pieces(edge), st.dirty = false;
  const std::vector<Piece> pieces = st.pieces;
  double next = kInf;
  auto due = [&](double t) {
    if (t <= key) return true;
    next = std::min(next, t);
    return false;
  };
  auto burned_at = [&](const Piece& p, const Break& b) { return due(record_time(edge, p.record, b.at).hi); };
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    if (p.record == kNoIndex) continue;
    if (due(piece_time_lo(edge, p))) emit_piece(edge, p);
    const bool left_gap = i > 0 && pieces[i - 1].record == kNoIndex;
    const bool right_gap = i + 1 < pieces.size() && pieces[i + 1].record == kNoIndex;
    if (left_gap && burned_at(p, p.lo)) edge_point_source(edge, p.lo, p.record, SweepEvent::Kind::StretchEnd);
    if (right_gap && burned_at(p, p.hi)) edge_point_source(edge, p.hi, p.record, SweepEvent::Kind::StretchEnd);
    if (i + 1 < pieces.size() && pieces[i + 1].record != kNoIndex && (p.hi.id >> 60) != 0 &&
        o_.mutant != EngineMutant::no_kink_emission && burned_at(p, p.hi))
      edge_point_source(edge, p.hi, p.record, SweepEvent::Kind::Kink);
    // A piece ending at an end vertex of the edge: the edge's points next to the vertex burn
    // at the piece's time there, which the vertex's own link rule may exceed (joint.ma: the
    // edge (3, 188) next to vertex 3 at 0.3159, vertex 3 at 0.3404), and they are sources into
    // every side: a point source at the vertex's position with that time (their limit),
    // unless the vertex burned by then (its own emission dominates; equal keys: burns first).
    for (const Break& b : {p.lo, p.hi}) {
      if ((b.id >> 60) != 0) continue;
      const std::uint32_t v = mc_.edge(edge).v[b.id & 1];
      if (is_link_vertex(v) && link_burn_time(v) != kNoIndex) continue;
      if (burned_at(p, b)) edge_point_source(edge, b, p.record, SweepEvent::Kind::StretchEnd);
    }
  }
  if (next < kInf) schedule_junction(edge, next);
}

// ---- emission -------------------------------------------------------------------------------

std::uint32_t WindowPropagation::break_point(std::uint32_t edge, const Break& b) {
  JunctionState& st = junctions_[junction_of_[edge]];
  for (const auto& [id, ep] : st.points)
    if (id == b.id) return ep;
  EdgePoint ep;
  ep.edge = edge;
  if ((b.id >> 60) == 0) {  // an end vertex of the edge: lambda 0 or 1
    const int j = static_cast<int>(b.id & 1);
    ep.lambda = Interval(j);
    s_.exact_times.push_back(ExactSum::rational(mpq_class(j)));
    ep.exact = static_cast<std::int32_t>(s_.exact_times.size() - 1);
  } else if ((b.id >> 60) == (kCrossing >> 60)) {
    const std::uint32_t ra = static_cast<std::uint32_t>((b.id >> 30) & 0x3fffffff);
    const std::uint32_t rb = static_cast<std::uint32_t>((b.id >> 1) & 0x1fffffff);
    const Crossing* c = nullptr;
    for (const Crossing& x : st.crossings)
      if (x.at.id == b.id) c = &x;
    const KinkParameter k =
        c && c->bracketed ? kink_parameter(u_, s_, cert_, edge, records_[ra].window, records_[rb].window, c->lo, c->hi)
                          : kink_parameter(u_, s_, cert_, edge, records_[ra].window, records_[rb].window, b.at);
    ep.lambda = k.lambda;
    if (k.bracket) ep.bracketed = true, ep.lo = (*k.bracket)[0], ep.hi = (*k.bracket)[1];
    if (k.exact) {
      s_.exact_times.push_back(*k.exact);
      ep.exact = static_cast<std::int32_t>(s_.exact_times.size() - 1);
    }
    if (!k.certified) ++stats_.uncertified_breaks, ++cert_.counts.uncertified;
    else ep.equal_windows = {records_[ra].window, records_[rb].window};
  } else {  // a record's ray through its bound vertex meets the edge there
    const std::uint32_t r = static_cast<std::uint32_t>((b.id >> 1) & 0x7fffffff);
    const int j = static_cast<int>(b.id & 1);
    const KinkParameter k = ray_parameter(u_, s_, cert_, edge, records_[r].window, records_[r].end[j].vertex, b.at);
    ep.lambda = k.lambda;
    if (k.bracket) ep.bracketed = true, ep.lo = (*k.bracket)[0], ep.hi = (*k.bracket)[1];
    if (k.exact) {
      s_.exact_times.push_back(*k.exact);
      ep.exact = static_cast<std::int32_t>(s_.exact_times.size() - 1);
    }
    if (!k.certified) ++stats_.uncertified_breaks, ++cert_.counts.uncertified;
  }
  s_.edge_points.push_back(ep);
  const auto id = static_cast<std::uint32_t>(s_.edge_points.size() - 1);
  st.points.emplace_back(b.id, id);
  return id;
}

// The bound of a piece end in the realising record's frame: an end vertex of the edge, the
// record's own wedge bound, or an edge point.
WindowPropagation::Bound WindowPropagation::piece_bound(std::uint32_t edge, const JunctionRecord& r, const Break& b) {
  const Window& W = s_.windows[r.window];
  if ((b.id >> 60) == 0) {
    const std::uint32_t v = mc_.edge(edge).v[b.id & 1];
    return {v, u_.vertex_image(W.triangle, v), W.depth};
  }
  for (int j = 0; j < 2; ++j)
    if (b.id == (kRecordEnd | (std::uint64_t(&r - records_.data()) << 1) | std::uint64_t(j))) return r.end[j];
  const std::uint32_t ep = break_point(edge, b);
  return {ep | kEdgePointBound, edge_point_image(u_, s_, W.triangle, ep), W.depth};
}

// The parts of piece p (between its ends and the ends of earlier emissions of the same
// record, ordered by parameter) that no earlier emission of its record covers.
std::vector<WindowPropagation::Piece> WindowPropagation::unemitted_parts(const JunctionState& st, const Piece& p) const {
  std::vector<const Piece*> done;
  for (const Piece& e : st.emitted)
    if (e.record == p.record && e.hi.at > p.lo.at && e.lo.at < p.hi.at) done.push_back(&e);
  std::sort(done.begin(), done.end(), [](const Piece* a, const Piece* b) { return a->lo.at < b->lo.at; });
  std::vector<Piece> parts;
  Break from = p.lo;
  for (const Piece* e : done) {
    if (e->lo.at > from.at) parts.push_back({p.record, from, e->lo});
    if (e->hi.at > from.at) from = e->hi;
  }
  if (from.at < p.hi.at) parts.push_back({p.record, from, p.hi});
  return parts;
}

void WindowPropagation::emit_piece(std::uint32_t edge, const Piece& p) {
  JunctionState& st = junctions_[junction_of_[edge]];
  const std::vector<Piece> parts = unemitted_parts(st, p);
  if (parts.empty()) return;
  st.emitted.push_back(p);
  const JunctionRecord r = records_[p.record];
  const std::uint32_t w = r.window;
  const Window W = s_.windows[w];  // a copy: enter_child grows the store
  const bool increasing = r.at[0] < r.at[1];  // the record's clockwise end has parameter at[0]
  for (const Piece& part : parts) {
    // Arrivals along the curve at the edge's end vertices (their link rule).
    for (const Break& b : {part.lo, part.hi})
      if ((b.id >> 60) == 0) {
        const std::uint32_t v = mc_.edge(edge).v[b.id & 1];
        if (is_link_vertex(v)) link_arrival(v, mc_.edge_end_element(edge, static_cast<int>(b.id & 1)), window_time_at(w, v));
      }
    if (r.on_edge || r.grazing) continue;  // its source emits into every side itself; a grazing
                                           // front's rays run along the edge (its ends' sources emit)
    const Bound lo = piece_bound(edge, r, part.lo), hi = piece_bound(edge, r, part.hi);
    const Bound& b0 = increasing ? lo : hi;
    const Bound& b1 = increasing ? hi : lo;
    const double key = std::max(W.key, approx_lower_bound(W, lo.image, hi.image));
    for (std::uint32_t t2 : mc_.edge_triangles(edge)) {
      if (t2 == r.side) continue;
      enter_child(w, edge, t2, b0, b1, key);
      ++stats_.merges;
    }
  }
}

// Whether an edge-point source already burns at edge point ep (proved equal parameters).
bool WindowPropagation::same_point_as_source(std::uint32_t edge, std::uint32_t ep) {
  const JunctionState& st = junctions_[junction_of_[edge]];
  const EdgePoint& p = s_.edge_points[ep];
  for (std::uint64_t id : st.sources)
    for (const auto& [name, other] : st.points) {
      if (name != id || other == ep) continue;
      const EdgePoint& q = s_.edge_points[other];
      if (p.lambda.hi < q.lambda.lo || q.lambda.hi < p.lambda.lo) continue;
      if (p.exact >= 0 && q.exact >= 0 && exact_sign(s_.exact_times[p.exact] - s_.exact_times[q.exact]) == 0) return true;
    }
  return false;
}

// A point of the edge burning at the realising record's time there: a point source into
// every sheet side (roots in every triangle of the edge), made once per breakpoint.
void WindowPropagation::edge_point_source(std::uint32_t edge, const Break& b, std::uint32_t record,
                                          SweepEvent::Kind kind) {
  JunctionState& st = junctions_[junction_of_[edge]];
  if (std::find(st.sources.begin(), st.sources.end(), b.id) != st.sources.end()) return;
  st.sources.push_back(b.id);
  const std::uint32_t ep = break_point(edge, b);
  if (same_point_as_source(edge, ep)) return;
  const std::uint32_t time = window_time_at(records_[record].window, ep | kEdgePointBound);
  PseudoSource ps;
  ps.origin = SourceOrigin::EdgePoint;
  ps.data = ep;
  ps.time = time;
  ps.sigma = s_.times[time].value;
  ps.exact = -1;
  const auto p = static_cast<std::uint32_t>(s_.pseudo.size());
  ps.first_root = static_cast<std::uint32_t>(s_.windows.size());
  s_.pseudo.push_back(ps);
  for (std::uint32_t t : mc_.edge_triangles(edge)) {
    const ComplexTriangle& tr = mc_.triangle(t);
    int k = 0;
    while (tr.e[k] != edge) ++k;
    add_root(p, t, static_cast<std::uint8_t>(7 & ~(1u << k)), ps.sigma.lo);
  }
  s_.pseudo[p].root_count = static_cast<std::uint32_t>(s_.windows.size()) - ps.first_root;
  ++stats_.pseudo_sources;
  ++(kind == SweepEvent::Kind::Kink ? stats_.kinks : stats_.stretch_ends);
  events_.push_back({kind, ep, time});
}

std::vector<WindowPropagation::JunctionSwitch> WindowPropagation::junction_switches() {
  std::vector<JunctionSwitch> out;
  for (std::uint32_t edge = 0; edge < junction_of_.size(); ++edge) {
    if (junction_of_[edge] == kNoIndex) continue;
    if (junctions_[junction_of_[edge]].dirty) {
      std::vector<Piece> p = junction_pieces(edge);
      junctions_[junction_of_[edge]].pieces = std::move(p);
      junctions_[junction_of_[edge]].dirty = false;
    }
    const std::vector<Piece> pieces = junctions_[junction_of_[edge]].pieces;  // a copy: break_point grows the state
    for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
      const Piece &a = pieces[i], &b = pieces[i + 1];
      if (a.record == kNoIndex || b.record == kNoIndex || a.record == b.record || (a.hi.id >> 60) == 0) continue;
      const std::uint32_t ep = break_point(edge, a.hi);
      const std::uint32_t wa = records_[a.record].window, wb = records_[b.record].window;
      out.push_back({edge, ep, wa, wb, window_time_at(wa, ep | kEdgePointBound)});
    }
  }
  // Switches at vertices where a curve runs on from one singular edge into another (exactly
  // two singular edges at v, no link rule there): the records realising A at v on each side.
  for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) {
    if (is_link_vertex(v)) continue;
    std::vector<std::uint32_t> es;
    for (std::uint32_t e : mc_.vertex_edges(v))
      if (junction_of_[e] != kNoIndex) es.push_back(e);
    if (es.size() != 2) continue;
    std::array<const Piece*, 2> at_v{nullptr, nullptr};
    std::array<std::uint32_t, 2> end{0, 0};
    for (int i = 0; i < 2; ++i) {
      const std::vector<Piece>& pieces = junctions_[junction_of_[es[i]]].pieces;
      if (pieces.empty()) continue;
      end[i] = mc_.edge(es[i]).v[0] == v ? 0 : 1;
      at_v[i] = end[i] == 0 ? &pieces.front() : &pieces.back();
    }
    if (!at_v[0] || !at_v[1] || at_v[0]->record == kNoIndex || at_v[1]->record == kNoIndex) continue;
    const std::uint32_t wa = records_[at_v[0]->record].window, wb = records_[at_v[1]->record].window;
    if (wa == wb) continue;
    const Break b0 = end[0] == 0 ? at_v[0]->lo : at_v[0]->hi, b1 = end[1] == 0 ? at_v[1]->lo : at_v[1]->hi;
    const std::uint32_t p0 = break_point(es[0], b0), p1 = break_point(es[1], b1);
    JunctionSwitch sw{es[0], p0, wa, wb, window_time_at(wa, p0 | kEdgePointBound)};
    sw.edge2 = es[1], sw.point2 = p1;
    out.push_back(sw);
  }
  return out;
}

// Arrivals that realise no emitted piece: fronts that end at the curve (they meet the other
// sheets' fronts there, or arrive after the curve burned).
void WindowPropagation::count_quenched() {
  for (const JunctionState& st : junctions_)
    for (std::uint32_t r : st.records) {
      bool used = false;
      for (const Piece& e : st.emitted) used = used || e.record == r;
      stats_.quenched += !used;
    }
}

}  // namespace grassfire
