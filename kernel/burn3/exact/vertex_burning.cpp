// vertex_burning.cpp -- the link rule at vertices with segments, and fire along segments
// (part of WindowPropagation; window_propagation.h).
//
// A vertex whose link has segment directions (a 1-dimensional part of the complex meets it)
// burns by the operational form of Definition 9 (docs/design.md 5, MedialComplex::link_burns):
// at the first time T at which its link, with every element arrived by T removed, has no
// cycle and at most one segment direction (the 2D rule of 3.3.1 along segments), or at its
// ignition f(v). Arrivals come from windows reaching it through a sector and from fire
// running along a segment from the segment's other end (time + length). When it burns it
// emits into every sector not arrived by T (a vertex source with offset T) and along every
// segment not arrived by T. Ties are decided by Certifier::compare_time_exprs; an arrival
// that no stage orders before T is not counted as arrived (the burn time found is then
// that of a real burning path, possibly later than an unprovable tie would allow;
// counted as kept_undecided).
// Timing: a burn event is keyed by the upper end of T's enclosure; all window and arrival
// events are keyed by lower ends of their times, so when the burn pops every arrival
// before T has been seen (Dijkstra finality), and T is recomputed then.
#include <algorithm>

#include "burn3/exact/window_propagation.h"

namespace grassfire {

namespace {

std::vector<std::uint32_t> sectors_of(const MedialComplex& mc, std::uint32_t v) {
  std::vector<std::uint32_t> r;
  for (const LinkElement& el : mc.link_elements(v))
    if (!el.is_pole) r.push_back(el.id);
  return r;
}

}  // namespace

// The link rule runs where segments or singular curves meet the vertex; the poles along a
// singular curve receive their arrivals from the edge's junction rule (edge_junction.cpp).
void WindowPropagation::init_links() {
  link_of_.assign(mc_.vertex_count(), kNoIndex);
  for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) {
    bool segment = false, singular = false;
    for (const LinkElement& el : mc_.link_elements(v)) {
      if (!el.is_pole) continue;
      (mc_.edge(el.id).stratum == EdgeStratum::Dangling ? segment : singular) = true;
    }
    if (mc_.vertex(v).kind == VertexKind::Isolated) segment = true;  // burns at f alone
    if (mc_.is_singular_point(v)) singular = true;  // sheets meeting at a point: Prop 6's link rule
    if (o_.singular_walls && singular) continue;  // part 1: the curve is a wall, no link rule
    if (!segment && !singular) continue;
    link_of_[v] = static_cast<std::uint32_t>(links_.size());
    LinkState l;
    l.arrival.assign(mc_.link_elements(v).size(), kNoIndex);
    links_.push_back(std::move(l));
  }
}

std::uint32_t WindowPropagation::min_time(std::uint32_t a, std::uint32_t b) {
  if (a == kNoIndex) return b;
  if (b == kNoIndex) return a;
  const int c = cert_.compare_time_exprs(a, b);
  if (c == 0 || c == -1) return a;
  if (c == 1) return b;
  TimeExpr m;
  m.kind = TimeExpr::Kind::Min;
  m.a = a, m.b = b;
  m.value = Interval(std::min(s_.times[a].value.lo, s_.times[b].value.lo), std::min(s_.times[a].value.hi, s_.times[b].value.hi));
  return new_time(m);
}

void WindowPropagation::burn_vertex_at(std::uint32_t v, std::uint32_t time) {
  if (is_link_vertex(v)) {
    LinkState& l = links_[link_of_[v]];
    l.fixed = min_time(l.fixed, time);
    schedule_burn(v);
    return;
  }
  for (std::uint32_t sec : sectors_of(mc_, v)) claim_sector(sec, time);
}

// The sector's apex burns at `time` (given, or by the link rule): it becomes the sector's
// best arrival, and its vertex source is made when that is final.
void WindowPropagation::claim_sector(std::uint32_t sector, std::uint32_t time) {
  best_hi_[sector] = std::min(best_hi_[sector], s_.times[time].value.hi);
  std::uint32_t& best = best_time_[sector];
  if (sector_source_[sector] != kNoIndex) return;  // already burning from its own front
  best = min_time(best, time);
  queue_.push({s_.times[best].value.hi, sector, EventKind::VertexSource});
}

void WindowPropagation::link_arrival(std::uint32_t v, std::uint32_t element, std::uint32_t time) {
  LinkState& l = links_[link_of_[v]];
  if (l.burned != kNoIndex) return;
  std::uint32_t& a = l.arrival[element];
  if (a != kNoIndex && cert_.compare_time_exprs(time, a) != -1) return;
  a = time;
  schedule_burn(v);
}

// The earliest time the link rule (or the ignition) burns v with the arrivals known now.
std::uint32_t WindowPropagation::link_candidate(std::uint32_t v) {
  const LinkState& l = links_[link_of_[v]];
  std::uint32_t best = l.fixed;
  const std::size_t m = l.arrival.size();
  for (std::size_t j = 0; j < m; ++j) {
    if (l.arrival[j] == kNoIndex) continue;
    std::vector<bool> arrived(m, false);
    for (std::size_t i = 0; i < m; ++i) {
      if (l.arrival[i] == kNoIndex) continue;
      const int c = i == j ? 0 : cert_.compare_time_exprs(l.arrival[i], l.arrival[j]);
      arrived[i] = c == 0 || c == -1;
    }
    if (mc_.link_burns(v, arrived)) best = min_time(best, l.arrival[j]);
  }
  return best;
}

void WindowPropagation::schedule_burn(std::uint32_t v) {
  if (links_[link_of_[v]].burned != kNoIndex) return;
  const std::uint32_t t = link_candidate(v);
  if (t != kNoIndex) queue_.push({s_.times[t].value.hi, v, EventKind::VertexBurn});
}

void WindowPropagation::process_burn(std::uint32_t v, double key) {
  if (links_[link_of_[v]].burned != kNoIndex) return;
  const std::uint32_t t = link_candidate(v);
  if (t == kNoIndex) return;
  if (s_.times[t].value.hi > key) {  // a wider enclosure than the one scheduled: wait for it
    queue_.push({s_.times[t].value.hi, v, EventKind::VertexBurn});
    return;
  }
  links_[link_of_[v]].burned = t;
  ++stats_.vertex_burns;
  events_.push_back({SweepEvent::Kind::VertexBurn, v, t});
  emit_from_vertex(v, t);
}

void WindowPropagation::emit_from_vertex(std::uint32_t v, std::uint32_t time) {
  const auto& elements = mc_.link_elements(v);
  for (std::size_t j = 0; j < elements.size(); ++j) {
    const std::uint32_t a = links_[link_of_[v]].arrival[j];
    if (a != kNoIndex && cert_.compare_time_exprs(a, time) != 1) continue;  // it burned from there already
    const LinkElement& el = elements[j];
    if (!el.is_pole) {
      claim_sector(el.id, time);
      continue;
    }
    if (mc_.edge(el.id).stratum != EdgeStratum::Dangling) continue;
    const auto& ev = mc_.edge(el.id).v;
    const std::uint32_t u = ev[0] == v ? ev[1] : ev[0];
    TimeExpr plus;
    plus.kind = TimeExpr::Kind::Plus;
    plus.a = time, plus.b = el.id;
    plus.value = s_.times[time].value + sqrt(enclose(cert_.edge_length2(el.id)));
    const std::uint32_t arrival = new_time(plus);
    segment_arrivals_.push_back({u, mc_.edge_end_element(el.id, ev[0] == u ? 0 : 1), arrival});
    queue_.push({plus.value.lo, static_cast<std::uint32_t>(segment_arrivals_.size() - 1), EventKind::SegmentArrival});
  }
}

void WindowPropagation::process_segment_arrival(std::uint32_t a) {
  const SegmentArrival sa = segment_arrivals_[a];
  ++stats_.segment_arrivals;
  if (is_link_vertex(sa.vertex)) link_arrival(sa.vertex, sa.element, sa.time);
}

}  // namespace grassfire
