// bt_bracket_upper.cpp -- the upper bound by chords of convex sheets (bt_bracket_upper.h).
#include "burn3/bt_bracket_upper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>

#include "burn3/bracket_support.h"
#include "geometry3/exact_predicates3.h"

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Feet of border ignitions stay inside their edge (any point gives a valid path; an end
// could lie on the supporting line of the point it feeds).
constexpr double kInside = 0x1p-20;

double dist(const Vec3d& a, const Vec3d& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
Vec3d lerp(const Vec3d& a, const Vec3d& b, double s) {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

using Uv = std::array<mpq_class, 2>;
mpq_class cross2(const Uv& o, const Uv& a, const Uv& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Twice the area of the convex hull of the points (Andrew's monotone chain, exact).
mpq_class hull_area2(std::vector<Uv> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return 0;
  std::vector<Uv> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && sgn(cross2(h[k - 2], h[k - 1], p[i])) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && sgn(cross2(h[k - 2], h[k - 1], p[i])) <= 0) --k;
    h[k++] = p[i];
  }
  mpq_class a = 0;
  for (std::size_t i = 1; i + 1 < k; ++i) a += cross2(h[0], h[i], h[i + 1]);
  return abs(a);
}

double kth(std::vector<double> v, std::size_t k) {
  if (k == 0 || v.size() < k) return kInf;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k - 1), v.end());
  return v[k - 1];
}

}  // namespace

ChordUpperBound::ChordUpperBound(const MedialComplex& mc, double spacing, const std::vector<PointSource>& sources)
    : mc_(mc), spacing_(spacing), sources_(sources) {
  const auto start = std::chrono::steady_clock::now();
  classify_sheets();
  place_samples();
  solve();
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::size_t ChordUpperBound::convex_sheets() const {
  return static_cast<std::size_t>(std::count(convex_.begin(), convex_.end(), 1));
}

void ChordUpperBound::classify_sheets() {
  const std::size_t ns = mc_.sheets().size();
  convex_.assign(ns, 0);
  line_.assign(ns, {});
  for (std::uint32_t s = 0; s < ns; ++s) {
    const Sheet& sh = mc_.sheets()[s];
    if (!sh.planar || sh.triangles.empty()) continue;
    std::map<std::uint32_t, int> uses;
    for (std::uint32_t t : sh.triangles)
      for (std::uint32_t e : mc_.triangle(t).e) ++uses[e];
    std::vector<std::uint32_t> boundary;
    bool ok = true;
    for (const auto& [e, n] : uses) {
      if (n == 1) boundary.push_back(e);
      if (n > 1 && mc_.edge(e).stratum == EdgeStratum::Singular) ok = false;  // Sigma inside S
    }
    std::vector<char> on_boundary(mc_.vertex_count(), 0);
    for (std::uint32_t e : boundary) on_boundary[mc_.edge(e).v[0]] = on_boundary[mc_.edge(e).v[1]] = 1;
    const PlanarFrame& frame = mc_.triangle_frame(sh.triangles.front());
    std::vector<Uv> uv;
    mpq_class area = 0;
    for (std::uint32_t t : sh.triangles) {
      const auto& v = mc_.triangle(t).v;
      std::array<Uv, 3> c;
      for (int i = 0; i < 3; ++i) {
        c[i] = frame.local(mc_.vertex(v[i]).exact);
        uv.push_back(c[i]);
        if (!on_boundary[v[i]] && on_sigma_vertex(mc_, v[i])) ok = false;  // a pinch inside S
      }
      area += abs(cross2(c[0], c[1], c[2]));
    }
    if (!ok || area != hull_area2(uv)) continue;
    convex_[s] = 1;
    // line ids: boundary edges on one supporting line share one (exact collinearity)
    std::vector<std::uint32_t> id(boundary.size());
    std::iota(id.begin(), id.end(), 0u);
    for (std::size_t i = 0; i < boundary.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) {
        const ComplexEdge &a = mc_.edge(boundary[i]), &b = mc_.edge(boundary[j]);
        const ExactPoint3 &p = mc_.vertex(a.v[0]).exact, &q = mc_.vertex(a.v[1]).exact;
        if (collinear(p, q, mc_.vertex(b.v[0]).exact) && collinear(p, q, mc_.vertex(b.v[1]).exact)) {
          id[i] = id[j];
          break;
        }
      }
    for (std::size_t i = 0; i < boundary.size(); ++i) line_[s].push_back({boundary[i], id[i]});
  }
}

void ChordUpperBound::place_samples() {
  const std::size_t nv = mc_.vertex_count();
  vertex_sample_.assign(nv, kNoIndex);
  edge_samples_.assign(mc_.edge_count(), {});
  sheet_samples_.assign(mc_.sheets().size(), {});
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (!on_sigma_vertex(mc_, v)) continue;
    vertex_sample_[v] = static_cast<std::uint32_t>(samples_.size());
    samples_.push_back({mc_.vertex(v).approx, kNoIndex, v});
    floor_.push_back(mc_.is_border_point(v) ? mc_.ignition_at_vertex(v) : kInf);
  }
  for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
    if (!on_sigma_edge(mc_, e)) continue;
    const ComplexEdge& ed = mc_.edge(e);
    const auto n = static_cast<std::uint32_t>(std::max(1.0, std::ceil(ed.length / spacing_)));
    for (std::uint32_t i = 1; i < n; ++i) {
      edge_samples_[e].push_back(static_cast<std::uint32_t>(samples_.size()));
      samples_.push_back({lerp(mc_.vertex(ed.v[0]).approx, mc_.vertex(ed.v[1]).approx, double(i) / n), e, kNoIndex});
      floor_.push_back(kInf);
    }
  }
  for (const PointSource& s : sources_) {
    const ComplexPoint& x = s.location;
    if (x.kind == ComplexPoint::Kind::Vertex && vertex_sample_[x.id] != kNoIndex)
      floor_[vertex_sample_[x.id]] = std::min(floor_[vertex_sample_[x.id]], s.t0.get_d());
    if (x.kind == ComplexPoint::Kind::Edge && on_sigma_edge(mc_, x.id)) {  // a sample of its own
      edge_samples_[x.id].push_back(static_cast<std::uint32_t>(samples_.size()));
      samples_.push_back({x.approx(), x.id, kNoIndex});
      floor_.push_back(s.t0.get_d());
    }
  }
  for (std::uint32_t s = 0; s < mc_.sheets().size(); ++s) {
    if (!convex_[s]) continue;
    std::vector<char> seen(samples_.size(), 0);
    for (std::uint32_t t : mc_.sheets()[s].triangles) {
      for (std::uint32_t v : mc_.triangle(t).v)
        if (vertex_sample_[v] != kNoIndex && !seen[vertex_sample_[v]]) {
          seen[vertex_sample_[v]] = 1;
          sheet_samples_[s].push_back(vertex_sample_[v]);
        }
      for (std::uint32_t e : mc_.triangle(t).e)
        for (std::uint32_t i : edge_samples_[e])
          if (!seen[i]) seen[i] = 1, sheet_samples_[s].push_back(i);
    }
  }
}

std::vector<std::uint32_t> ChordUpperBound::lines_at(std::uint32_t sheet, const ComplexPoint& x) const {
  std::vector<std::uint32_t> r;
  for (const auto& [e, id] : line_[sheet]) {
    const ComplexEdge& ed = mc_.edge(e);
    if ((x.kind == ComplexPoint::Kind::Edge && x.id == e) ||
        (x.kind == ComplexPoint::Kind::Vertex && (ed.v[0] == x.id || ed.v[1] == x.id)))
      r.push_back(id);
  }
  return r;
}

std::vector<std::uint32_t> ChordUpperBound::sample_lines(std::uint32_t sheet, std::uint32_t i) const {
  ComplexPoint x;
  x.kind = samples_[i].edge != kNoIndex ? ComplexPoint::Kind::Edge : ComplexPoint::Kind::Vertex;
  x.id = samples_[i].edge != kNoIndex ? samples_[i].edge : samples_[i].vertex;
  return lines_at(sheet, x);
}

bool ChordUpperBound::chord(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) const {
  for (std::uint32_t x : a)
    if (std::find(b.begin(), b.end(), x) != b.end()) return false;
  return true;
}

// min over the ignitions of convex sheet s reachable by a chord from p (p's boundary lines)
double ChordUpperBound::ignition(std::uint32_t s, const Vec3d& p, const std::vector<std::uint32_t>& lines) const {
  double best = kInf;
  for (const auto& [e, id] : line_[s]) {
    const ComplexEdge& ed = mc_.edge(e);
    if (ed.stratum != EdgeStratum::Border || ed.rule == IgnitionRule::Never) continue;
    if (std::find(lines.begin(), lines.end(), id) != lines.end()) continue;
    const Vec3d &a = mc_.vertex(ed.v[0]).approx, &b = mc_.vertex(ed.v[1]).approx;
    if (ed.rule == IgnitionRule::Linear) {
      const double ra = mc_.vertex(ed.v[0]).radius, rb = mc_.vertex(ed.v[1]).radius;
      auto time = [&](double t) { return (1 - t) * ra + t * rb + dist(p, lerp(a, b, t)); };
      best = std::min(best, golden_section_minimum(time, kInside, 1 - kInside));
    } else {
      best = std::min(best, golden_section_minimum(
                                [&](double t) {
                                  const Vec3d y = lerp(a, b, t);
                                  return dist(y, ed.rule_point_approx) + dist(p, y);
                                },
                                kInside, 1 - kInside));
    }
  }
  for (const PointSource& src : sources_) {
    const ComplexPoint& x = src.location;
    bool in = false;
    if (x.kind == ComplexPoint::Kind::Triangle) in = mc_.triangle(x.id).sheet == s;
    if (x.kind == ComplexPoint::Kind::Edge)
      for (std::uint32_t t : mc_.edge_triangles(x.id)) in = in || mc_.triangle(t).sheet == s;
    if (x.kind == ComplexPoint::Kind::Vertex)
      for (std::uint32_t t : mc_.vertex_triangles(x.id)) in = in || mc_.triangle(t).sheet == s;
    if (in && chord(lines, lines_at(s, x))) best = std::min(best, src.t0.get_d() + dist(p, x.approx()));
  }
  return best;
}

std::vector<std::uint32_t> ChordUpperBound::side_sheets(std::uint32_t i) const {
  std::vector<std::uint32_t> r;
  if (samples_[i].edge != kNoIndex) {
    for (std::uint32_t t : mc_.edge_triangles(samples_[i].edge)) r.push_back(mc_.triangle(t).sheet);
  } else {
    for (const LinkElement& el : mc_.link_elements(samples_[i].vertex))
      r.push_back(el.is_pole ? kNoIndex : mc_.sectors()[el.id].sheet);
  }
  return r;
}

double ChordUpperBound::burn_time(std::uint32_t i, const std::vector<double>& side, double along) const {
  double t = std::min(floor_[i], along);
  if (samples_[i].edge != kNoIndex) return side.empty() ? t : std::min(t, kth(side, side.size() - 1));
  const std::uint32_t v = samples_[i].vertex;
  std::vector<std::size_t> order(side.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return side[a] < side[b]; });
  std::vector<bool> arrived(side.size(), false);
  const bool border = mc_.link_burns(v, arrived);
  for (std::size_t k : order) {
    if (!(side[k] < t)) break;
    arrived[k] = true;
    if (border || mc_.link_burns(v, arrived)) return side[k];
  }
  return t;
}

void ChordUpperBound::solve() {
  const std::size_t n = samples_.size();
  std::vector<std::vector<std::uint32_t>> sheets(n);  // the sides' sheets
  std::vector<std::vector<double>> side(n);
  std::vector<double> along(n, kInf);
  value_.assign(n, kInf);
  std::vector<char> done(n, 0);
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  auto settle = [&](std::uint32_t i) {
    const double t = burn_time(i, side[i], along[i]);
    if (t < value_[i]) value_[i] = t, queue.push({t, i});
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    sheets[i] = side_sheets(i);
    for (std::uint32_t s : sheets[i])
      side[i].push_back(s != kNoIndex && convex_[s] ? ignition(s, samples_[i].p, sample_lines(s, i)) : kInf);
    settle(i);
  }
  // The edges of Sigma through a sample, and the samples on them (ends included).
  auto edges_of = [&](std::uint32_t i) {
    if (samples_[i].edge != kNoIndex) return std::vector<std::uint32_t>{samples_[i].edge};
    std::vector<std::uint32_t> r;
    for (std::uint32_t e : mc_.vertex_edges(samples_[i].vertex))
      if (!edge_samples_[e].empty() || mc_.edge(e).stratum == EdgeStratum::Singular ||
          mc_.edge(e).stratum == EdgeStratum::Dangling)
        r.push_back(e);
    return r;
  };
  while (!queue.empty()) {
    const auto [t, u] = queue.top();
    queue.pop();
    if (done[u] || t > value_[u]) continue;
    done[u] = 1;
    // along the edges of Sigma through u
    for (std::uint32_t e : edges_of(u)) {
      std::vector<std::uint32_t> on = edge_samples_[e];
      on.push_back(vertex_sample_[mc_.edge(e).v[0]]);
      on.push_back(vertex_sample_[mc_.edge(e).v[1]]);
      for (std::uint32_t w : on) {
        if (w == u || done[w]) continue;
        const double a = t + dist(samples_[u].p, samples_[w].p);
        if (samples_[w].edge != kNoIndex) {
          along[w] = std::min(along[w], a);
        } else {
          const std::uint32_t el = mc_.edge_end_element(e, mc_.edge(e).v[0] == samples_[w].vertex ? 0 : 1);
          side[w][el] = std::min(side[w][el], a);
        }
        settle(w);
      }
    }
    // chords of the convex sheets through u
    for (std::uint32_t s : sheets[u]) {
      if (s == kNoIndex || !convex_[s]) continue;
      const std::vector<std::uint32_t> lu = sample_lines(s, u);
      for (std::uint32_t w : sheet_samples_[s]) {
        if (w == u || done[w] || !chord(lu, sample_lines(s, w))) continue;
        const double a = t + dist(samples_[u].p, samples_[w].p);
        for (std::size_t j = 0; j < sheets[w].size(); ++j)
          if (sheets[w][j] == s) side[w][j] = std::min(side[w][j], a);
        settle(w);
      }
    }
  }
}

double ChordUpperBound::at(const ComplexPoint& x) const {
  if (x.kind == ComplexPoint::Kind::Vertex && vertex_sample_[x.id] != kNoIndex) return value_[vertex_sample_[x.id]];
  const Vec3d p = x.approx();
  // the time of fire reaching p through convex sheet s (by chords), p's lines in s given
  auto through = [&](std::uint32_t s, const std::vector<std::uint32_t>& lines) {
    if (!convex_[s]) return kInf;
    double best = ignition(s, p, lines);
    for (std::uint32_t w : sheet_samples_[s])
      if (chord(lines, sample_lines(s, w))) best = std::min(best, value_[w] + dist(p, samples_[w].p));
    return best;
  };
  if (x.kind == ComplexPoint::Kind::Edge &&
      (mc_.edge(x.id).stratum == EdgeStratum::Singular || mc_.edge(x.id).stratum == EdgeStratum::Dangling)) {
    const std::uint32_t e = x.id;
    double along = kInf;
    std::vector<std::uint32_t> on = edge_samples_[e];
    on.push_back(vertex_sample_[mc_.edge(e).v[0]]);
    on.push_back(vertex_sample_[mc_.edge(e).v[1]]);
    for (std::uint32_t w : on) along = std::min(along, value_[w] + dist(p, samples_[w].p));
    std::vector<double> side;
    for (std::uint32_t t : mc_.edge_triangles(e)) {
      const std::uint32_t s = mc_.triangle(t).sheet;
      side.push_back(through(s, lines_at(s, x)));
    }
    return side.empty() ? along : std::min(along, kth(side, side.size() - 1));
  }
  std::uint32_t t = x.id;
  if (x.kind == ComplexPoint::Kind::Edge) t = mc_.edge_triangles(x.id).front();
  if (x.kind == ComplexPoint::Kind::Vertex) t = mc_.vertex_triangles(x.id).front();
  const std::uint32_t s = mc_.triangle(t).sheet;
  double own = kInf;  // the point's own ignition on the border
  if (x.kind == ComplexPoint::Kind::Edge && mc_.edge(x.id).stratum == EdgeStratum::Border)
    own = mc_.ignition_on_edge(x.id, x.parameter.get_d());
  if (x.kind == ComplexPoint::Kind::Vertex && mc_.is_border_point(x.id)) own = mc_.ignition_at_vertex(x.id);
  for (const PointSource& src : sources_)
    if (src.location.kind == x.kind && src.location.id == x.id && src.location.point == x.point)
      own = std::min(own, src.t0.get_d());
  return std::min(own, through(s, lines_at(s, x)));
}

}  // namespace grassfire
