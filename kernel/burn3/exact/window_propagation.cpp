// window_propagation.cpp -- see window_propagation.h.
#include "burn3/exact/window_propagation.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "burn3/exact/sources.h"
#include "burn3/exact/window_values.h"
#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

WindowPropagation::WindowPropagation(const Unfolding& u, const ExactBurningOptions& o)
    : u_(u), mc_(u.complex()), o_(o), cert_(u, s_, o.max_bits), sectors_(sector_geometry(u, o.mutant)) {
  occupier_.assign(3 * mc_.triangle_count(), kNoIndex);
  const std::size_t S = mc_.sectors().size();
  best_time_.assign(S, kNoIndex);
  best_hi_.assign(S, kInf);
  sector_source_.assign(S, kNoIndex);
  stats_.undecided_angles = sectors_.undecided_angles;
  init_links();
  junction_of_.assign(mc_.edge_count(), kNoIndex);
  for (std::uint32_t e = 0; e < mc_.edge_count(); ++e)
    if (mc_.edge(e).stratum == EdgeStratum::Singular) {
      junction_of_[e] = static_cast<std::uint32_t>(junctions_.size());
      junctions_.emplace_back();
    }
  s_.windows.reserve(16 * mc_.triangle_count() + 64);
}

std::uint32_t WindowPropagation::new_window(Window w) {
  if (s_.windows.size() >= o_.max_windows)
    throw std::runtime_error(mc_.source() + ": the exact engine exceeded its bound of " + std::to_string(o_.max_windows) +
                             " windows");
  s_.windows.push_back(w);
  ++stats_.windows;
  return static_cast<std::uint32_t>(s_.windows.size() - 1);
}

// ---- sources ------------------------------------------------------------------------------

void WindowPropagation::add_root(std::uint32_t pseudo, std::uint32_t t, std::uint8_t exits, double key) {
  const RootDisc r = root_disc(u_, s_, pseudo, t);
  Window w;
  w.pseudo = pseudo;
  w.triangle = t;
  w.source = r.source;
  w.offset = r.offset;
  w.flags = r.plane ? Window::kPlane : 0;
  w.exits = exits;
  w.key = key;
  const std::uint32_t id = new_window(w);
  s_.windows[id].anchor = id;
  queue_.push({key, id});
}

void WindowPropagation::add_border_window(std::uint32_t pseudo, std::uint32_t e) {
  const std::uint32_t t = border_triangle(mc_, e);
  const RootDisc r = root_disc(u_, s_, pseudo, t);
  const auto& ev = mc_.edge(e).v;
  // The clockwise end as seen from the source is p with (p, q, third) clockwise.
  const std::uint32_t p = u_.edge_side(e, t) > 0 ? ev[1] : ev[0], q = p == ev[0] ? ev[1] : ev[0];
  Window w;
  w.pseudo = pseudo;
  w.triangle = t;
  w.edge = e;
  w.bound = {p, q};
  w.image = {u_.vertex_image(t, p), u_.vertex_image(t, q)};
  w.source = r.source;
  w.offset = r.offset;
  w.flags = r.plane ? Window::kPlane : 0;
  w.key = approx_lower_bound(w, w.image[0], w.image[1]);
  const std::uint32_t id = new_window(w);
  s_.windows[id].anchor = id;
  queue_.push({w.key, id});
}

std::uint32_t WindowPropagation::new_time(TimeExpr e) {
  s_.times.push_back(e);
  return static_cast<std::uint32_t>(s_.times.size() - 1);
}

std::uint32_t WindowPropagation::exact_time(const ExactSum& x) {
  s_.exact_times.push_back(x);
  TimeExpr e;
  e.a = static_cast<std::uint32_t>(s_.exact_times.size() - 1);
  e.value = x.approx();
  return new_time(e);
}

std::uint32_t WindowPropagation::window_time_at(std::uint32_t w, std::uint32_t v) {
  TimeExpr e;
  e.kind = TimeExpr::Kind::WindowAt;
  e.a = w, e.b = v;
  e.value = cert_.time_interval(w, Target{v, nullptr});
  // A chain through an ill-conditioned unfolding (a tiny edge, a crossing of a singular
  // curve at a small angle) widens the double enclosure; this value becomes a vertex's BT,
  // a source's offset, an arrival on a curve: re-evaluate it in Arb then.
  if (e.value.hi - e.value.lo > 0x1p-32 * std::max(1.0, std::fabs(e.value.lo))) {
    BallPrecision bits(128);
    const Interval tight = intersect(e.value, cert_.time_ball(w, Target{v, nullptr}).to_interval());
    if (tight.lo <= tight.hi) e.value = tight;
  }
  return new_time(e);
}

std::uint32_t WindowPropagation::spawn_vertex_source(std::uint32_t v, std::uint32_t sector, std::uint32_t time) {
  PseudoSource ps;
  ps.origin = SourceOrigin::Vertex;
  ps.vertex = v;
  ps.sector = sector;
  ps.time = time;
  ps.sigma = s_.times[time].value;
  ExactSource es;
  es.vertex = v;
  ps.exact = static_cast<std::int32_t>(s_.exact.size());
  s_.exact.push_back(std::move(es));
  const auto p = static_cast<std::uint32_t>(s_.pseudo.size());
  ps.first_root = static_cast<std::uint32_t>(s_.windows.size());
  s_.pseudo.push_back(ps);
  for (std::uint32_t t : mc_.sectors()[sector].triangles)
    add_root(p, t, static_cast<std::uint8_t>(1u << corner_of(mc_.triangle(t), v)), ps.sigma.lo);
  s_.pseudo[p].root_count = static_cast<std::uint32_t>(s_.windows.size()) - ps.first_root;
  sector_source_[sector] = p;
  ++stats_.pseudo_sources;
  events_.push_back({SweepEvent::Kind::VertexSource, sector, time});
  return p;
}

void WindowPropagation::add_vertex_source(std::uint32_t v, const mpq_class& start) {
  if (v >= mc_.vertex_count()) throw std::invalid_argument("point source: no vertex " + std::to_string(v));
  burn_vertex_at(v, exact_time(ExactSum::rational(start)));
}

void WindowPropagation::add_point_source(std::uint32_t t, const ExactPoint3& point, const mpq_class& start) {
  if (t >= mc_.triangle_count()) throw std::invalid_argument("point source: no triangle " + std::to_string(t));
  const ComplexTriangle& tr = mc_.triangle(t);
  const ExactPoint3 &a = mc_.vertex(tr.v[0]).exact, &b = mc_.vertex(tr.v[1]).exact, &c = mc_.vertex(tr.v[2]).exact;
  if (orientation(a, b, c, point) != 0) throw std::invalid_argument("point source: not in the plane of its triangle");
  const ExactPoint3 n = cross(b - a, c - a);
  std::array<int, 3> side{};  // side[i]: of the edge opposite corner i
  for (int i = 0; i < 3; ++i) {
    const ExactPoint3& p = mc_.vertex(tr.v[(i + 1) % 3]).exact;
    const ExactPoint3& q = mc_.vertex(tr.v[(i + 2) % 3]).exact;
    side[i] = sgn(dot(cross(q - p, point - p), n));
    if (side[i] < 0) throw std::invalid_argument("point source: outside its triangle");
  }
  const int zeros = (side[0] == 0) + (side[1] == 0) + (side[2] == 0);
  const std::uint32_t time = exact_time(ExactSum::rational(start));
  if (zeros == 2) {  // on a vertex
    const int i = side[0] != 0 ? 0 : side[1] != 0 ? 1 : 2;
    burn_vertex_at(tr.v[i], time);
    return;
  }
  s_.given.push_back({t, point, start});
  PseudoSource ps;
  ps.origin = SourceOrigin::GivenPoint;
  ps.data = static_cast<std::uint32_t>(s_.given.size() - 1);
  ps.time = time;
  ps.sigma = s_.times[time].value;
  ExactSource es;
  es.point = point;
  ps.exact = static_cast<std::int32_t>(s_.exact.size());
  s_.exact.push_back(std::move(es));
  const auto p = static_cast<std::uint32_t>(s_.pseudo.size());
  ps.first_root = static_cast<std::uint32_t>(s_.windows.size());
  s_.pseudo.push_back(ps);
  ++stats_.pseudo_sources;
  if (zeros == 0) {
    add_root(p, t, 7, ps.sigma.lo);
  } else {  // inside the edge opposite corner i: every triangle on that edge
    const int i = side[0] == 0 ? 0 : side[1] == 0 ? 1 : 2;
    const std::uint32_t e = tr.e[i];
    for (std::uint32_t t2 : mc_.edge_triangles(e)) {
      int k = 0;
      while (mc_.triangle(t2).e[k] != e) ++k;
      add_root(p, t2, static_cast<std::uint8_t>(7 & ~(1u << k)), ps.sigma.lo);
    }
  }
  s_.pseudo[p].root_count = static_cast<std::uint32_t>(s_.windows.size()) - ps.first_root;
}

void WindowPropagation::add_border_ignition() {
  for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
    const ComplexEdge& ed = mc_.edge(e);
    if (ed.stratum != EdgeStratum::Border || ed.rule == IgnitionRule::Never) continue;
    PseudoSource ps;
    ps.data = e;
    if (ed.rule == IgnitionRule::Linear) {
      if (!linear_plane_wave(mc_, e)) continue;  // slope >= 1: the endpoints' sources suffice
      ps.origin = SourceOrigin::BorderPlane;
      const mpq_class& r2 = mc_.vertex(ed.v[0]).radius_squared;
      if (r2 == mc_.vertex(ed.v[1]).radius_squared) {
        ExactSource es;
        es.line = true;
        es.edge = e;
        ExactSum r = ExactSum::sqrt_of(r2);
        r.simplify();
        ps.time = exact_time(r);
        ps.exact = static_cast<std::int32_t>(s_.exact.size());
        s_.exact.push_back(std::move(es));
      }
    } else {
      const RotatedPoint rp = rotated_point(mc_, e);
      if (sgn(rp.h2) == 0) {  // p on the edge's line: a point source if inside the edge
        if (sgn(rp.alpha) > 0 && rp.alpha < 1) add_point_source(border_triangle(mc_, e), ed.rule_point, 0);
        continue;
      }
      ps.origin = SourceOrigin::BorderPoint;
      ps.sigma = Interval(0.0);
    }
    s_.pseudo.push_back(ps);
    ++stats_.pseudo_sources;
    add_border_window(static_cast<std::uint32_t>(s_.pseudo.size() - 1), e);
  }
  for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v)
    if (const std::optional<ExactSum> f = exact_vertex_ignition(mc_, v)) burn_vertex_at(v, exact_time(*f));
}

// ---- the event loop -------------------------------------------------------------------------

void WindowPropagation::run() {
  const auto start = std::chrono::steady_clock::now();
  for (std::uint64_t events = 1; !queue_.empty(); ++events) {
    const QueueEntry top = queue_.top();
    queue_.pop();
    switch (top.kind) {
      case EventKind::Window: process(top.id); break;
      case EventKind::SegmentArrival: process_segment_arrival(top.id); break;
      case EventKind::VertexSource: process_vertex_source(top.id, top.key); break;
      case EventKind::VertexBurn: process_burn(top.id, top.key); break;
      case EventKind::Junction: process_junction(top.id, top.key); break;
    }
    if (o_.on_event) o_.on_event(top.key, events, stats_.windows);
  }
  count_quenched();
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void WindowPropagation::process(std::uint32_t w) {
  Window& win = s_.windows[w];
  if (win.dead() || (win.flags & Window::kProcessed)) return;
  win.flags |= Window::kProcessed;
  ++stats_.processed;
  if (win.root())
    process_root(w);
  else
    process_entered(w);
}

void WindowPropagation::process_root(std::uint32_t w) {
  const Window W = s_.windows[w];
  const ComplexTriangle& tr = mc_.triangle(W.triangle);
  const PseudoSource& ps = s_.pseudo[W.pseudo];
  std::uint32_t at = ps.origin == SourceOrigin::Vertex ? ps.vertex : kNoIndex;
  if (ps.origin == SourceOrigin::EdgePoint) {  // a source at an end vertex of its edge: that vertex is not reached
    const EdgePoint& ep = s_.edge_points[ps.data];
    if (ep.lambda.is_point() && (ep.lambda.lo == 0.0 || ep.lambda.lo == 1.0))
      at = mc_.edge(ep.edge).v[ep.lambda.lo == 0.0 ? 0 : 1];
  }
  for (int i = 0; i < 3; ++i)
    if (tr.v[i] != at) vertex_arrival(w, tr.v[i], sectors_.corner_sector[3 * W.triangle + i]);
  for (int k = 0; k < 3; ++k) {
    // A root covers its whole triangle: every singular edge of it receives an arrival.
    const bool junction = !o_.singular_walls && mc_.edge(tr.e[k]).stratum == EdgeStratum::Singular;
    if (!((W.exits >> k) & 1) && !junction) continue;
    const int ia = (k + 1) % 3, ib = (k + 2) % 3;
    // Seen from S (on the side of corner k), corner ia is clockwise of ib iff
    // cross(a - S, b - S) > 0, iff the triangle turns counter-clockwise.
    const int cw = u_.orientation(W.triangle) > 0 ? ia : ib, ccw = cw == ia ? ib : ia;
    const Bound b0{tr.v[cw], u_.corner(W.triangle, cw), W.depth}, b1{tr.v[ccw], u_.corner(W.triangle, ccw), W.depth};
    make_child(w, k, cw, ccw, b0, b1, nullptr, kNoIndex);
  }
}

void WindowPropagation::process_entered(std::uint32_t w) {
  const Window W = s_.windows[w];
  const std::uint32_t t = W.triangle;
  const ComplexTriangle& tr = mc_.triangle(t);
  int k = 0;
  while (tr.e[k] != W.edge) ++k;
  const std::uint32_t o = tr.v[k];
  // p: the entry edge's end on the clockwise side seen from S, (p, q, o) clockwise.
  const int ip = u_.orientation(t) > 0 ? (k + 2) % 3 : (k + 1) % 3, iq = ip == (k + 1) % 3 ? (k + 2) % 3 : (k + 1) % 3;
  const DiscPoint &P = u_.corner(t, ip), &Q = u_.corner(t, iq);
  // The ends of the entry interval, for the vertex filter's third-vertex test, only where
  // that vertex has a time (else the test cannot prune).
  auto entry_end = [&](int j, std::uint32_t far_from) {
    if (!o_.vertex_filter || vertex_bound(t, far_from) == kInf) return RayHit{};
    if (W.bound[j] == tr.v[j == 0 ? ip : iq]) return RayHit{true, j == 0 ? P : Q};
    return approx_ray_hit(W, W.image[j], P, Q);
  };
  const RayHit y0 = entry_end(0, tr.v[iq]), y1 = entry_end(1, tr.v[ip]);
  const Bound B0{W.bound[0], W.image[0], W.bound_depth[0]}, B1{W.bound[1], W.image[1], W.bound_depth[1]};
  const Bound O{o, u_.corner(t, k), W.depth};
  const DiscPoint* third_q = y0.ok ? &y0.point : nullptr;  // end of the entry interval farthest from q
  const DiscPoint* third_p = y1.ok ? &y1.point : nullptr;
  const int s0 = cert_.side(w, 0, Target{o, nullptr});
  if (s0 < 0) {  // o clockwise of the wedge: everything leaves through (o, q)
    make_child(w, ip, k, iq, B0, B1, third_p, tr.v[ip]);
    graze_singular_edges(w, k, ip);
    return;
  }
  const int s1 = cert_.side(w, 1, Target{o, nullptr});
  if (s1 > 0) {  // o counter-clockwise of the wedge: everything leaves through (p, o)
    make_child(w, iq, ip, k, B0, B1, third_q, tr.v[iq]);
    graze_singular_edges(w, k, iq);
    return;
  }
  const auto [left, right] = reach_opposite(w, k);
  if (s0 > 0 && left) make_child(w, iq, ip, k, B0, O, third_q, tr.v[iq]);
  if (s1 < 0 && right) make_child(w, ip, k, iq, O, B1, third_p, tr.v[ip]);
  stats_.split_pruned += (s0 > 0 && !left) + (s1 < 0 && !right);
  if (s0 == 0) graze_singular_edges(w, k, ip);  // the ray through o may run along (p, o)
  if (s1 == 0) graze_singular_edges(w, k, iq);  // ... or along (o, q)
}

// A front that grazes a singular edge of its triangle (a wedge ray runs along it: the plane
// wave from the fin's border along N) arrives there without crossing it: record it when
// both ends of the edge lie in the closed wedge (certified), for the edge slots other than
// the entry slot and the slot exited through.
void WindowPropagation::graze_singular_edges(std::uint32_t w, int entry_slot, int exit_slot) {
  if (o_.singular_walls) return;
  const Window W = s_.windows[w];
  const ComplexTriangle& tr = mc_.triangle(W.triangle);
  for (int m = 0; m < 3; ++m) {
    if (m == entry_slot || m == exit_slot || mc_.edge(tr.e[m]).stratum != EdgeStratum::Singular) continue;
    const auto& ev = mc_.edge(tr.e[m]).v;
    bool inside = true;
    for (std::uint32_t v : ev)
      inside = inside && cert_.side(w, 0, Target{v, nullptr}) >= 0 && cert_.side(w, 1, Target{v, nullptr}) <= 0;
    if (!inside) continue;
    const Bound a{ev[0], u_.vertex_image(W.triangle, ev[0]), W.depth}, b{ev[1], u_.vertex_image(W.triangle, ev[1]), W.depth};
    junction_arrival(w, tr.e[m], a, b, a.image, b.image, true);
  }
}

// Window w reaches the vertex o opposite its entry edge (corner k): the occupier rule of
// one angle, one split, then the vertex's arrival. Returns whether w continues on the side
// of (p, o) and on the side of (o, q).
std::pair<bool, bool> WindowPropagation::reach_opposite(std::uint32_t w, int k) {
  const std::uint32_t t = s_.windows[w].triangle;
  const ComplexTriangle& tr = mc_.triangle(t);
  const std::uint32_t o = tr.v[k];
  vertex_arrival(w, o, sectors_.corner_sector[3 * t + k]);
  if (!o_.one_angle_one_split) return {true, true};
  const std::uint32_t slot = 3 * t + k;
  const std::uint32_t occ = occupier_[slot];
  if (occ == kNoIndex || s_.windows[occ].dead()) {
    occupier_[slot] = w;
    return {true, true};
  }
  const Target at{o, nullptr};
  const int c = cert_.compare_times(w, at, occ, at);
  if (c == kUndecided) return {true, true};
  const int d = cert_.compare_directions(w, occ, o);  // < 0: w's ray comes from the p side
  const int ip = u_.orientation(t) > 0 ? (k + 2) % 3 : (k + 1) % 3, iq = ip == (k + 1) % 3 ? (k + 2) % 3 : (k + 1) % 3;
  if (c < 0) {
    // w is the new occupier; the old one is dominated on w's side.
    if (d == -1) kill_child_through(occ, tr.e[iq]);
    if (d == 1) kill_child_through(occ, tr.e[ip]);
    occupier_[slot] = w;
    return {true, true};
  }
  if (d == -1) return {true, false};
  if (d == 1) return {false, true};
  return {true, true};
}

// Window w reaches vertex v through `sector`. The sector's earliest arrival is kept as a
// time expression (a Min of arrivals no stage orders); where paths bend at v its vertex
// source is created when that time is final (an event keyed by its upper end: Dijkstra
// finality), so each sector gets one source, not one per improvement.
void WindowPropagation::vertex_arrival(std::uint32_t w, std::uint32_t v, std::uint32_t sector) {
  ++stats_.vertex_events;
  const Interval tv = cert_.time_interval(w, Target{v, nullptr});
  best_hi_[sector] = std::min(best_hi_[sector], tv.hi);
  std::uint32_t& best = best_time_[sector];
  if (best != kNoIndex && tv.lo > s_.times[best].value.hi) return;  // certainly later: the filter alone
  const std::uint32_t e = window_time_at(w, v);
  int c = -1;
  if (best != kNoIndex) c = cert_.compare_time_exprs(e, best, !is_link_vertex(v));
  if (c == 1) return;
  // A proved tie adds nothing to the sector but is still an arrival through its own link
  // element (the link rule counts the elements arrived).
  if (is_link_vertex(v)) {
    const ComplexTriangle& tr = mc_.triangle(s_.windows[w].triangle);
    link_arrival(v, mc_.corner_element(s_.windows[w].triangle, corner_of(tr, v)), e);
  }
  if (c == 0) return;
  if (sector_source_[sector] != kNoIndex) {
    // After the sector's source was made (its time was final): only an unprovable tie can
    // arrive; when the source's offset enclosure holds the new time's lower end its windows
    // stay enclosures of the minimum, so the source absorbs it.
    PseudoSource& ps = s_.pseudo[sector_source_[sector]];
    if (c == kUndecided && ps.sigma.lo <= tv.lo) {
      ps.time = min_time(ps.time, e);
      cert_.source_time_changed();
      ++stats_.ties_absorbed;
      return;
    }
    for (std::uint32_t r = ps.first_root; r < ps.first_root + ps.root_count; ++r) kill_subtree(r);
    sector_source_[sector] = kNoIndex;
  }
  best = c == kUndecided ? min_time(best, e) : e;
  if (sectors_.bends[sector]) queue_.push({s_.times[best].value.hi, sector, EventKind::VertexSource});
}

void WindowPropagation::process_vertex_source(std::uint32_t sector, double key) {
  if (sector_source_[sector] != kNoIndex) return;
  const std::uint32_t t = best_time_[sector];
  if (s_.times[t].value.hi > key) {
    queue_.push({s_.times[t].value.hi, sector, EventKind::VertexSource});
    return;
  }
  spawn_vertex_source(mc_.sectors()[sector].apex, sector, t);
}

// ---- children -------------------------------------------------------------------------------

double WindowPropagation::vertex_bound(std::uint32_t t, std::uint32_t v) const {
  return best_hi_[sectors_.corner_sector[3 * t + corner_of(mc_.triangle(t), v)]];
}

bool WindowPropagation::filtered(std::uint32_t w, std::uint32_t a, std::uint32_t b, const DiscPoint& x0,
                                 const DiscPoint& x1, const DiscPoint* third, std::uint32_t third_vertex) {
  const Window& W = s_.windows[w];
  const std::uint32_t t = W.triangle;
  auto beaten = [&](std::uint32_t v, const DiscPoint& p) {
    const double d = vertex_bound(t, v);
    if (d == kInf) return false;
    const DiscPoint q = u_.vertex_image(t, v);
    const double dx = p.x - q.x, dy = p.y - q.y, len = std::sqrt(dx * dx + dy * dy);
    const double via = d + len + (p.r + q.r + 4 * kUnit * len + kUnit * (d + len)) * (1 + 8 * kUnit) + 0x1p-1000;
    const Approx tw = approx_time(W, p);
    return tw.v - tw.e > via;
  };
  return beaten(a, x1) || beaten(b, x0) || (third && beaten(third_vertex, *third));
}

void WindowPropagation::make_child(std::uint32_t w, int exit_slot, int icw, int iccw, const Bound& b0,
                                   const Bound& b1, const DiscPoint* third, std::uint32_t third_vertex) {
  const Window W = s_.windows[w];
  const std::uint32_t t = W.triangle;
  const ComplexTriangle& tr = mc_.triangle(t);
  const std::uint32_t E = tr.e[exit_slot];
  // The child's interval [x0, x1] on the exit edge, from its clockwise end A to B; where a
  // ray may be parallel to the edge the edge's end stands in (a superset: still sound for
  // the filter, whose test weakens away from its vertex, and for the key).
  const DiscPoint &A = u_.corner(t, icw), &B = u_.corner(t, iccw);
  const RayHit h0 = b0.vertex == tr.v[icw] ? RayHit{true, A} : approx_ray_hit(W, b0.image, A, B);
  const RayHit h1 = b1.vertex == tr.v[iccw] ? RayHit{true, B} : approx_ray_hit(W, b1.image, A, B);
  const DiscPoint x0 = h0.ok ? h0.point : A, x1 = h1.ok ? h1.point : B;
  if (o_.vertex_filter && filtered(w, tr.v[icw], tr.v[iccw], x0, x1, third, third_vertex)) {
    ++stats_.filtered;
    return;
  }
  const ComplexEdge& ed = mc_.edge(E);
  if (ed.stratum == EdgeStratum::Border) {
    ++stats_.border_arrivals;
    return;
  }
  if (ed.stratum == EdgeStratum::Singular) {  // an arrival at a junction (edge_junction.cpp)
    ++stats_.wall_arrivals;
    if (!o_.singular_walls) junction_arrival(w, E, b0, b1, x0, x1, false);
    return;
  }
  const auto& ts = mc_.edge_triangles(E);
  enter_child(w, E, ts[0] == t ? ts[1] : ts[0], b0, b1, std::max(W.key, approx_lower_bound(W, x0, x1)));
}

// The child of w entering t2 across edge E, its wedge bounded by b0 (clockwise) and b1 in
// w's frame: unfolded into t2's frame (a reflection swaps the bounds).
void WindowPropagation::enter_child(std::uint32_t w, std::uint32_t E, std::uint32_t t2, const Bound& b0,
                                    const Bound& b1, double key) {
  const Window W = s_.windows[w];
  const std::uint32_t t = W.triangle;
  Window c;
  c.pseudo = W.pseudo;
  c.parent = w;
  c.depth = W.depth + 1;
  c.edge = E;
  c.bound = {b0.vertex, b1.vertex};
  c.bound_depth = {b0.depth, b1.depth};
  c.key = key;
  c.flags = static_cast<std::uint8_t>(W.flags & Window::kPlane);
  c.anchor = W.anchor;
  c.triangle = t2;
  if (u_.same_frame(t, t2)) {
    c.source = W.source;
    c.offset = W.offset;
    c.image = {b0.image, b1.image};
  } else {
    const RigidMotion2& m = u_.crossing(E, t, t2);
    c.anchor = kNoIndex;  // this window itself
    if (W.plane()) {
      c.source = m.apply_vector(W.source);
      const Interval t0(round_down(m.t0 - m.trans_error), round_up(m.t0 + m.trans_error));
      const Interval t1(round_down(m.t1 - m.trans_error), round_up(m.t1 + m.trans_error));
      c.offset = W.offset - (c.source.ix() * t0 + c.source.iy() * t1);
    } else {
      c.source = m.apply(W.source);
      c.offset = W.offset;
    }
    c.image = {m.apply(b0.image), m.apply(b1.image)};
    if (o_.mutant == EngineMutant::mirrored_rotation && mc_.edge(E).stratum == EdgeStratum::Singular) {
      // engine-mirrored-rotation: the source reflected through the edge's line in t2's frame
      // (the front enters from t2's own side; checks only, the certified stages disagree).
      const auto& ev = mc_.edge(E).v;
      const DiscPoint A = u_.vertex_image(t2, ev[0]), B = u_.vertex_image(t2, ev[1]);
      const double dx = B.x - A.x, dy = B.y - A.y, n = std::sqrt(dx * dx + dy * dy);
      auto mirror = [&](double x, double y, bool vec) {
        const double rx = vec ? x : x - A.x, ry = vec ? y : y - A.y, k = 2 * (rx * dx + ry * dy) / (n * n);
        return std::array<double, 2>{(vec ? 0 : A.x) + k * dx - rx, (vec ? 0 : A.y) + k * dy - ry};
      };
      const auto q = mirror(c.source.x, c.source.y, W.plane());
      c.source = DiscPoint{q[0], q[1], c.source.r * 2 + 1e-12};
    }
    if (m.reflect) {
      std::swap(c.bound[0], c.bound[1]);
      std::swap(c.bound_depth[0], c.bound_depth[1]);
      std::swap(c.image[0], c.image[1]);
    }
  }
  const std::uint32_t id = new_window(c);
  if (c.anchor == kNoIndex) s_.windows[id].anchor = id;
  s_.windows[id].next_sibling = s_.windows[w].first_child;
  s_.windows[w].first_child = id;
  queue_.push({c.key, id});
}

void WindowPropagation::kill_subtree(std::uint32_t w) {
  std::vector<std::uint32_t> stack{w};
  while (!stack.empty()) {
    const std::uint32_t x = stack.back();
    stack.pop_back();
    Window& win = s_.windows[x];
    if (win.dead()) continue;
    win.flags |= Window::kDead;
    ++stats_.evicted;
    for (std::uint32_t c = win.first_child; c != kNoIndex; c = s_.windows[c].next_sibling) stack.push_back(c);
  }
}

void WindowPropagation::kill_child_through(std::uint32_t w, std::uint32_t edge) {
  for (std::uint32_t c = s_.windows[w].first_child; c != kNoIndex; c = s_.windows[c].next_sibling)
    if (s_.windows[c].edge == edge) kill_subtree(c);
}

}  // namespace grassfire
