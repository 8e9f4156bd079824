// exact_burning_field.cpp -- see exact_burning_field.h.
#include "burn3/exact/exact_burning_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "burn3/exact/window_values.h"
#include "geometry3/exact_predicates3.h"
#include "geometry3/vec3.h"

namespace grassfire {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A path crosses each window of a chain once and each vertex source once; the budget
// bounds the walk on a corrupted store rather than any real path.
constexpr int kPathBudget = 10'000'000;

// Points closer than rounding noise of the frame round trips (relative 1e-12) are one.
bool same_point(const Vec3d& a, const Vec3d& b) {
  const double scale = 1 + std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])});
  return v3::dist(a, b) <= 1e-12 * scale;
}

double value_of(const Interval& i) { return i.is_infinite() ? kInf : i.mid(); }

// Barycentric coordinates of p with respect to the triangle (a, b, c) in the triangle's
// plane (p projected onto it), by the normal equations of p - a = u (b - a) + v (c - a).
std::array<double, 3> barycentric3(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& p) {
  const Vec3d e1 = v3::sub(b, a), e2 = v3::sub(c, a), d = v3::sub(p, a);
  const double g11 = v3::dot(e1, e1), g12 = v3::dot(e1, e2), g22 = v3::dot(e2, e2);
  const double r1 = v3::dot(d, e1), r2 = v3::dot(d, e2);
  const double det = g11 * g22 - g12 * g12;
  if (!(det > 0)) return {1.0, 0.0, 0.0};
  const double u = (r1 * g22 - r2 * g12) / det, v = (r2 * g11 - r1 * g12) / det;
  return {1 - u - v, u, v};
}

std::array<double, 3> barycentric2(const DiscPoint& a, const DiscPoint& b, const DiscPoint& c, double x, double y) {
  const double e1x = b.x - a.x, e1y = b.y - a.y, e2x = c.x - a.x, e2y = c.y - a.y;
  const double dx = x - a.x, dy = y - a.y;
  const double det = e1x * e2y - e1y * e2x;
  if (det == 0) return {1.0, 0.0, 0.0};
  const double u = (dx * e2y - dy * e2x) / det, v = (e1x * dy - e1y * dx) / det;
  return {1 - u - v, u, v};
}

// Origins where the fire itself starts (the path ends there): a caller's point source and
// the border rules. Vertices and any other burned point emit fire that came from elsewhere.
bool starts_fire(SourceOrigin o) {
  return o == SourceOrigin::GivenPoint || o == SourceOrigin::BorderPoint || o == SourceOrigin::BorderPlane;
}

}  // namespace

ExactBurningField::ExactBurningField(ExactBurning& eb, double edge_spacing)
    : eb_(eb), mc_(eb.complex()), h_(edge_spacing), definition9_(!exact_engine_unsupported(eb.complex()) && !eb.propagation().walls()) {
  if (!(h_ > 0) || !std::isfinite(h_)) throw std::invalid_argument("ExactBurningField: the edge spacing must be positive");
  method_ = definition9_ ? "exact (window propagation, Definition 9)"
                         : "exact (window propagation, singular edges as walls: an upper bound of BT, not Definition 9)";
}

double ExactBurningField::vertex_burn_time(std::uint32_t v) const { return value_of(eb_.vertex_burn_time(v)); }

std::uint32_t ExactBurningField::edge_points(std::uint32_t e) const {
  const double n = std::ceil(mc_.edge(e).length / h_) - 1;
  return n > 0 ? static_cast<std::uint32_t>(n) : 0;
}

ComplexPoint ExactBurningField::edge_complex_point(std::uint32_t e, std::uint32_t i) const {
  ComplexPoint x;
  x.kind = ComplexPoint::Kind::Edge;
  x.id = e;
  x.parameter = mpq_class(i, edge_points(e) + 1);
  x.parameter.canonicalize();
  const ExactPoint3& a = mc_.vertex(mc_.edge(e).v[0]).exact;
  const ExactPoint3& b = mc_.vertex(mc_.edge(e).v[1]).exact;
  x.point = a + x.parameter * (b - a);
  return x;
}

double ExactBurningField::edge_point_burn_time(std::uint32_t e, std::uint32_t i) const {
  return value_of(eb_.burn_time(edge_complex_point(e, i)));
}

ExactPoint3 ExactBurningField::exact_point_in(std::uint32_t t, const Vec3d& p) const {
  const auto& tv = mc_.triangle(t).v;
  std::array<double, 3> b =
      barycentric3(mc_.vertex(tv[0]).approx, mc_.vertex(tv[1]).approx, mc_.vertex(tv[2]).approx, p);
  double sum = 0;
  for (double& x : b) sum += (x = std::isfinite(x) ? std::max(0.0, x) : 0.0);
  if (!(sum > 0)) b = {1.0, 0.0, 0.0}, sum = 1.0;
  mpq_class b0(b[0] / sum), b1(b[1] / sum);
  if (b0 + b1 > 1) b1 = 1 - b0;
  const mpq_class b2 = 1 - b0 - b1;
  return b0 * mc_.vertex(tv[0]).exact + b1 * mc_.vertex(tv[1]).exact + b2 * mc_.vertex(tv[2]).exact;
}

std::uint32_t ExactBurningField::best_window(std::uint32_t t, const Target& x) const {
  Certifier& cert = eb_.certifier();
  const auto& ws = eb_.propagation().store().windows;
  std::uint32_t best = kNoIndex;
  double best_time = kInf;
  const IPoint at = ipoint(cert.target_disc(t, x));
  for (std::uint32_t w : eb_.triangle_windows(t)) {
    const Window& win = ws[w];
    if (!win.root()) {
      const Interval s0 = window_side(win, ipoint(win.image[0]), at);
      const Interval s1 = window_side(win, ipoint(win.image[1]), at);
      if (s0.hi < 0 || s1.lo > 0) continue;  // certainly outside the wedge
    }
    const double v = cert.time_interval(w, x).mid();
    if (v < best_time) best = w, best_time = v;
  }
  return best;
}

ExactBurningField::Frame2 ExactBurningField::to_frame(std::uint32_t t, const Vec3d& p) const {
  const auto& tv = mc_.triangle(t).v;
  const std::array<double, 3> b =
      barycentric3(mc_.vertex(tv[0]).approx, mc_.vertex(tv[1]).approx, mc_.vertex(tv[2]).approx, p);
  const Unfolding& u = eb_.unfolding();
  Frame2 q;
  for (int i = 0; i < 3; ++i) q.x += b[i] * u.corner(t, i).x, q.y += b[i] * u.corner(t, i).y;
  return q;
}

Vec3d ExactBurningField::from_frame(std::uint32_t t, const Frame2& q) const {
  const Unfolding& u = eb_.unfolding();
  const std::array<double, 3> b = barycentric2(u.corner(t, 0), u.corner(t, 1), u.corner(t, 2), q.x, q.y);
  const auto& tv = mc_.triangle(t).v;
  Vec3d r{0, 0, 0};
  for (int i = 0; i < 3; ++i) r = v3::add(r, v3::scale(mc_.vertex(tv[i]).approx, b[i]));
  return r;
}

// Backwards from p: towards S (at most to S itself), or along -u for a plane wave, while
// every barycentric coordinate stays >= 0 (a coordinate already negative by rounding is
// taken as 0, so the step is never negative).
Vec3d ExactBurningField::back_step(std::uint32_t w, const Vec3d& p) const {
  const Window& win = eb_.propagation().store().windows[w];
  const std::uint32_t t = win.triangle;
  const Frame2 P = to_frame(t, p);
  const double dx = win.plane() ? -win.source.x : win.source.x - P.x;
  const double dy = win.plane() ? -win.source.y : win.source.y - P.y;
  const Unfolding& u = eb_.unfolding();
  const std::array<double, 3> b0 = barycentric2(u.corner(t, 0), u.corner(t, 1), u.corner(t, 2), P.x, P.y);
  const std::array<double, 3> b1 = barycentric2(u.corner(t, 0), u.corner(t, 1), u.corner(t, 2), P.x + dx, P.y + dy);
  // A coordinate whose rate is below rounding level is constant: the path runs along
  // that side of t (a front sliding along an edge), which it does not leave.
  const double rate = std::fabs(b1[0] - b0[0]) + std::fabs(b1[1] - b0[1]) + std::fabs(b1[2] - b0[2]);
  double s = win.plane() ? kInf : 1.0;
  for (int i = 0; i < 3; ++i) {
    const double db = b1[i] - b0[i];
    if (db < -1e-12 * rate) s = std::min(s, std::max(0.0, b0[i]) / -db);
  }
  if (!std::isfinite(s) || !(s > 0)) return p;
  return from_frame(t, {P.x + s * dx, P.y + s * dy});
}

// Whether fire started at p in window w: p is w's pseudo-source (a caller's point source,
// or the border point where a border window's path meets the border edge).
bool ExactBurningField::window_starts_at(std::uint32_t w, const Vec3d& p, const Vec3d& back) const {
  const Window& win = eb_.propagation().store().windows[w];
  if (win.parent != kNoIndex || !same_point(p, back)) return false;
  return starts_fire(eb_.propagation().store().pseudo[win.pseudo].origin);
}

void ExactBurningField::walk_window(std::uint32_t w, Vec3d at, std::vector<Vec3d>& path, int budget) const {
  const WindowStore& s = eb_.propagation().store();
  for (; w != kNoIndex && budget > 0; --budget) {
    const Window& win = s.windows[w];
    const Vec3d q = back_step(w, at);
    if (!same_point(q, path.back())) path.push_back(q);
    at = q;
    if (win.parent != kNoIndex) {
      w = win.parent;
      continue;
    }
    const PseudoSource& ps = s.pseudo[win.pseudo];
    if (ps.origin == SourceOrigin::Vertex) {
      const Vec3d& v = mc_.vertex(ps.vertex).approx;
      if (!same_point(v, path.back())) path.push_back(v);
      walk_time(ps.time, ps.vertex, path, budget - 1);
    } else if (!starts_fire(ps.origin)) {
      walk_time(ps.time, kNoIndex, path, budget - 1);  // a point that burned before emitting
    }
    return;  // a point source, or the border edge where a border window started
  }
}

void ExactBurningField::walk_time(std::uint32_t time, std::uint32_t vertex, std::vector<Vec3d>& path, int budget) const {
  const WindowStore& s = eb_.propagation().store();
  while (time != kNoIndex && budget-- > 0) {
    const TimeExpr& e = s.times[time];
    switch (e.kind) {
      case TimeExpr::Kind::Exact:
        return;  // the vertex's ignition, or a point source on it
      case TimeExpr::Kind::WindowAt:
        if (is_edge_point(e.b)) {  // a kink or stretch end: back along the front that burned it
          const EdgePoint& ep = s.edge_points[e.b & ~kEdgePointBound];
          const auto& ev = mc_.edge(ep.edge).v;
          const Vec3d& a = mc_.vertex(ev[0]).approx;
          const Vec3d& b = mc_.vertex(ev[1]).approx;
          const double l = ep.lambda.mid();
          const Vec3d q{a[0] + l * (b[0] - a[0]), a[1] + l * (b[1] - a[1]), a[2] + l * (b[2] - a[2])};
          if (!same_point(q, path.back())) path.push_back(q);
          walk_window(e.a, q, path, budget);
          return;
        }
        if (e.b >= mc_.vertex_count()) return;
        walk_window(e.a, mc_.vertex(e.b).approx, path, budget);
        return;
      case TimeExpr::Kind::Plus: {
        if (vertex == kNoIndex || e.b >= mc_.edge_count()) return;
        const auto& ev = mc_.edge(e.b).v;
        vertex = ev[0] == vertex ? ev[1] : ev[0];
        path.push_back(mc_.vertex(vertex).approx);
        time = e.a;
        break;
      }
      case TimeExpr::Kind::Min:
        time = s.times[e.a].value.mid() <= s.times[e.b].value.mid() ? e.a : e.b;
        break;
      default:
        return;  // a time known only by its value: the path ends here
    }
  }
}

void ExactBurningField::walk_vertex(std::uint32_t v, std::vector<Vec3d>& path, int budget) const {
  const WindowPropagation& prop = eb_.propagation();
  if (prop.is_link_rule_vertex(v)) {
    walk_time(prop.link_burn_time(v), v, path, budget);
    return;
  }
  std::uint32_t best = kNoIndex;
  double best_time = kInf;
  for (std::uint32_t t : mc_.vertex_triangles(v)) {
    const std::uint32_t w = best_window(t, Target{v, nullptr});
    if (w == kNoIndex) continue;
    const double x = eb_.certifier().time_interval(w, Target{v, nullptr}).mid();
    if (x < best_time) best = w, best_time = x;
  }
  if (best == kNoIndex) return;
  const Window& win = prop.store().windows[best];
  const PseudoSource& ps = prop.store().pseudo[win.pseudo];
  if (win.parent == kNoIndex && ps.origin == SourceOrigin::Vertex && ps.vertex == v)
    walk_time(ps.time, v, path, budget);  // v burned first, then emitted this window
  else
    walk_window(best, mc_.vertex(v).approx, path, budget);
}

FieldSample ExactBurningField::sample_in_triangle(std::uint32_t t, const Vec3d& p) const {
  const ExactPoint3 x = exact_point_in(t, p);
  const Target at{kNoIndex, &x};
  FieldSample r;
  r.bt = value_of(eb_.burn_time(t, at));
  const std::uint32_t w = best_window(t, at);
  if (w == kNoIndex || !std::isfinite(r.bt)) return {};
  const Vec3d q = to_double(x);
  r.from = back_step(w, q);
  if (window_starts_at(w, q, r.from)) {
    r.started = true;
    return r;
  }
  if (!same_point(q, r.from)) {
    r.direction = v3::unit(v3::sub(q, r.from));
    return r;
  }
  // p is a vertex source's apex: the direction of the vertex's own path.
  const std::vector<Vec3d> path = path_in_triangle(t, q);
  if (path.size() < 2) {
    r.started = true;
  } else {
    r.direction = v3::unit(v3::sub(q, path[1]));
  }
  return r;
}

std::vector<Vec3d> ExactBurningField::path_in_triangle(std::uint32_t t, const Vec3d& p) const {
  const ExactPoint3 x = exact_point_in(t, p);
  std::vector<Vec3d> path{to_double(x)};
  const std::uint32_t w = best_window(t, Target{kNoIndex, &x});
  if (w == kNoIndex) return path;
  const Window& win = eb_.propagation().store().windows[w];
  const PseudoSource& ps = eb_.propagation().store().pseudo[win.pseudo];
  if (win.parent == kNoIndex && ps.origin == SourceOrigin::Vertex && same_point(path[0], mc_.vertex(ps.vertex).approx))
    walk_time(ps.time, ps.vertex, path, kPathBudget);
  else
    walk_window(w, path[0], path, kPathBudget);
  return path;
}

FieldSample ExactBurningField::sample_on_segment(std::uint32_t e, double s) const {
  s = std::clamp(std::isfinite(s) ? s : 0.0, 0.0, 1.0);
  const mpq_class sq(s);
  FieldSample r;
  r.bt = value_of(eb_.segment_burn_time(e, sq));
  if (!std::isfinite(r.bt)) return {};
  const auto& ev = mc_.edge(e).v;
  const double len = mc_.edge(e).length;
  const double t0 = vertex_burn_time(ev[0]) + s * len, t1 = vertex_burn_time(ev[1]) + (1 - s) * len;
  const std::uint32_t end = t0 <= t1 ? ev[0] : ev[1];
  const Vec3d p = edge_point(mc_, e, s);
  r.from = mc_.vertex(end).approx;
  if (!same_point(p, r.from)) {
    r.direction = v3::unit(v3::sub(p, r.from));
    return r;
  }
  const std::vector<Vec3d> path = path_from_vertex(end);
  if (path.size() < 2)
    r.started = true;
  else
    r.direction = v3::unit(v3::sub(p, path[1]));
  return r;
}

std::vector<Vec3d> ExactBurningField::path_on_segment(std::uint32_t e, double s) const {
  s = std::clamp(std::isfinite(s) ? s : 0.0, 0.0, 1.0);
  const FieldSample x = sample_on_segment(e, s);
  std::vector<Vec3d> path{edge_point(mc_, e, s)};
  if (!std::isfinite(x.bt)) return path;
  const auto& ev = mc_.edge(e).v;
  const std::uint32_t end = same_point(x.from, mc_.vertex(ev[0]).approx) ? ev[0] : ev[1];
  if (!same_point(path.back(), x.from)) path.push_back(x.from);
  walk_vertex(end, path, kPathBudget);
  return path;
}

std::vector<Vec3d> ExactBurningField::path_from_vertex(std::uint32_t v) const {
  std::vector<Vec3d> path{mc_.vertex(v).approx};
  walk_vertex(v, path, kPathBudget);
  return path;
}

// The side whose time equals the point's BT (the minimum with walls; the side of the
// (k-1)-th arrival under the junction rule): the one nearest to BT.
std::vector<Vec3d> ExactBurningField::path_from_edge_point(std::uint32_t e, std::uint32_t i) const {
  if (mc_.edge(e).stratum == EdgeStratum::Dangling)
    return path_on_segment(e, static_cast<double>(i) / (edge_points(e) + 1));
  const ComplexPoint x = edge_complex_point(e, i);
  const double bt = value_of(eb_.burn_time(x));
  std::uint32_t best = kNoIndex;
  double gap = kInf;
  for (std::uint32_t t : mc_.edge_triangles(e)) {
    const double side = value_of(eb_.burn_time(t, x.point));
    if (!std::isfinite(side)) continue;
    if (std::fabs(side - bt) < gap || best == kNoIndex) best = t, gap = std::fabs(side - bt);
  }
  if (best == kNoIndex || !std::isfinite(bt)) return {x.approx()};
  return path_in_triangle(best, x.approx());
}

}  // namespace grassfire
