// bt_bracket.cpp -- the lower bound of BT by the junction rule over cells of the singular set
// (bt_bracket.h: the derivation and its contract).
#include "burn3/bt_bracket.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>

#include "burn3/bracket_support.h"
#include "burn3/discrete/discrete_query.h"

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }
Vec3d lerp(const Vec3d& a, const Vec3d& b, double s) {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

double point_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = sub(b, a);
  const double l2 = dot(d, d);
  const double s = l2 > 0 ? std::clamp(dot(sub(p, a), d) / l2, 0.0, 1.0) : 0.0;
  return norm(sub(p, lerp(a, b, s)));
}

// The distance between segments ab and cd (Ericson, Real-Time Collision Detection 5.1.9),
// with the four end-to-segment distances as a guard against the degenerate branches.
double segment_segment(const Vec3d& p1, const Vec3d& q1, const Vec3d& p2, const Vec3d& q2) {
  const Vec3d d1 = sub(q1, p1), d2 = sub(q2, p2), r = sub(p1, p2);
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double best = std::min({point_segment(p1, p2, q2), point_segment(q1, p2, q2), point_segment(p2, p1, q1),
                          point_segment(q2, p1, q1)});
  if (a <= 0 || e <= 0) return best;
  const double c = dot(d1, r), b = dot(d1, d2), den = a * e - b * b;
  if (den <= 1e-300) return best;
  const double s = std::clamp((b * f - c * e) / den, 0.0, 1.0);
  const double t = (b * s + f) / e;
  if (t < 0 || t > 1) return best;
  return std::min(best, norm(sub(lerp(p1, q1, s), lerp(p2, q2, t))));
}

double cell_distance(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  return segment_segment(a, b, c, d);
}

// The first time at which vertex v's link rule holds when link element i arrives at t[i]
// (MedialComplex::link_burns; a border point, whose rule holds with nothing arrived, at its
// first arrival).
double link_time(const MedialComplex& mc, std::uint32_t v, const std::vector<double>& t) {
  std::vector<std::size_t> order(t.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t[a] < t[b]; });
  std::vector<bool> arrived(t.size(), false);
  const bool border = mc.link_burns(v, arrived);
  for (std::size_t i : order) {
    if (!std::isfinite(t[i])) break;
    arrived[i] = true;
    if (border || mc.link_burns(v, arrived)) return t[i];
  }
  return kInf;
}

double kth(std::vector<double> v, std::uint32_t k) {
  if (v.size() < k || k == 0) return kInf;
  std::nth_element(v.begin(), v.begin() + (k - 1), v.end());
  return v[k - 1];
}

}  // namespace

BtLowerBound::BtLowerBound(const MedialComplex& mc, const BtLowerBoundOptions& options) : mc_(mc), o_(options) {
  if (!(o_.spacing > 0)) throw std::invalid_argument(mc.source() + ": bracket spacing must be > 0");
  const auto start = std::chrono::steady_clock::now();
  build_cells();
  add_sources();
  solve();
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BtLowerBound::build_cells() {
  const std::size_t nv = mc_.vertex_count(), ns = mc_.sheets().size();
  vertex_cell_.assign(nv, kNoIndex);
  edge_first_cell_.assign(mc_.edge_count() + 1, kNoIndex);
  sheet_cells_.assign(ns, {});
  sheet_border_.assign(ns, {});
  sheet_sources_.assign(ns, {});
  // Vertex cells: on an edge of Sigma, or on triangles of two or more sheets, or isolated.
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (!on_sigma_vertex(mc_, v)) continue;
    Cell c;
    c.a = c.b = mc_.vertex(v).approx;
    c.vertex = v;
    c.floor = mc_.is_border_point(v) ? mc_.ignition_at_vertex(v) : kInf;
    // one side per link element: a sector (its sheet) or a pole (never a non-local arrival:
    // fire along an edge of Sigma is the envelope's)
    for (const LinkElement& el : mc_.link_elements(v))
      c.side_sheet.push_back(el.is_pole ? kNoIndex : mc_.sectors()[el.id].sheet);
    c.need = 0;  // the link rule
    vertex_cell_[v] = static_cast<std::uint32_t>(cells_.size());
    cells_.push_back(c);
  }
  for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
    if (!on_sigma_edge(mc_, e)) continue;
    const ComplexEdge& ed = mc_.edge(e);
    const auto n = static_cast<std::uint32_t>(std::max(1.0, std::ceil(ed.length / o_.spacing)));
    if (cells_.size() + n > o_.max_cells)
      throw std::invalid_argument(mc_.source() + ": bracket spacing too small (more than max_cells cells)");
    edge_first_cell_[e] = static_cast<std::uint32_t>(cells_.size());
    const Vec3d &p = mc_.vertex(ed.v[0]).approx, &q = mc_.vertex(ed.v[1]).approx;
    for (std::uint32_t i = 0; i < n; ++i) {
      Cell c;
      c.a = lerp(p, q, double(i) / n);
      c.b = lerp(p, q, double(i + 1) / n);
      c.edge = e;
      c.floor = kInf;
      for (std::uint32_t t : mc_.edge_triangles(e)) c.side_sheet.push_back(mc_.triangle(t).sheet);
      c.need = c.side_sheet.empty() ? 1 : static_cast<std::uint32_t>(c.side_sheet.size()) - 1;
      cells_.push_back(c);
    }
  }
  // Closures: the cells on each sheet's edges and vertices; each sheet's border edges.
  std::vector<std::uint32_t> mark(cells_.size(), kNoIndex);
  for (std::uint32_t s = 0; s < ns; ++s)
    for (std::uint32_t t : mc_.sheets()[s].triangles) {
      for (std::uint32_t v : mc_.triangle(t).v)
        if (vertex_cell_[v] != kNoIndex && mark[vertex_cell_[v]] != s) {
          mark[vertex_cell_[v]] = s;
          sheet_cells_[s].push_back(vertex_cell_[v]);
        }
      for (std::uint32_t e : mc_.triangle(t).e) {
        if (mc_.edge(e).stratum == EdgeStratum::Border) sheet_border_[s].push_back(e);
        if (edge_first_cell_[e] == kNoIndex) continue;
        const auto n = static_cast<std::uint32_t>(std::max(1.0, std::ceil(mc_.edge(e).length / o_.spacing)));
        for (std::uint32_t i = 0; i < n; ++i)
          if (mark[edge_first_cell_[e] + i] != s) {
            mark[edge_first_cell_[e] + i] = s;
            sheet_cells_[s].push_back(edge_first_cell_[e] + i);
          }
      }
    }
}

void BtLowerBound::add_sources() {
  for (std::size_t i = 0; i < o_.sources.size(); ++i) {
    const ComplexPoint& x = o_.sources[i].location;
    const double t0 = o_.sources[i].t0.get_d();
    source_point_.push_back(x.approx());
    std::vector<std::uint32_t> tris;
    if (x.kind == ComplexPoint::Kind::Triangle) tris = {x.id};
    if (x.kind == ComplexPoint::Kind::Edge) tris = mc_.edge_triangles(x.id);
    if (x.kind == ComplexPoint::Kind::Vertex) tris = mc_.vertex_triangles(x.id);
    for (std::uint32_t t : tris) {
      auto& list = sheet_sources_[mc_.triangle(t).sheet];
      if (list.empty() || list.back() != i) list.push_back(static_cast<std::uint32_t>(i));
    }
    // A source on Sigma ignites that point: a cell of length 0 with floor t0.
    if (on_sigma(x)) {
      if (x.kind == ComplexPoint::Kind::Vertex) {
        cells_[vertex_cell_[x.id]].floor = std::min(cells_[vertex_cell_[x.id]].floor, t0);
        continue;
      }
      Cell c;
      c.a = c.b = x.approx();
      c.edge = x.id;
      c.floor = t0;
      const auto id = static_cast<std::uint32_t>(cells_.size());
      cells_.push_back(c);
      for (std::uint32_t t : tris) sheet_cells_[mc_.triangle(t).sheet].push_back(id);
    }
  }
}

bool BtLowerBound::on_sigma(const ComplexPoint& x) const {
  if (x.kind == ComplexPoint::Kind::Vertex) return vertex_cell_[x.id] != kNoIndex;
  if (x.kind == ComplexPoint::Kind::Edge) return edge_first_cell_[x.id] != kNoIndex;
  return false;
}

// A lower bound, over the segment ab, of the ignitions of sheet s: min over border points y
// of f(y) + |x - y| and over sources of t0 + |x - source|, for every x in ab.
double BtLowerBound::ignition_bound(std::uint32_t s, const Vec3d& a, const Vec3d& b) const {
  double best = kInf;
  const Vec3d mid = lerp(a, b, 0.5);
  const double half = 0.5 * norm(sub(b, a));
  for (std::uint32_t e : sheet_border_[s]) {
    const ComplexEdge& ed = mc_.edge(e);
    if (ed.rule == IgnitionRule::Never) continue;
    const Vec3d &p = mc_.vertex(ed.v[0]).approx, &q = mc_.vertex(ed.v[1]).approx;
    if (ed.rule == IgnitionRule::Linear) {
      const ComplexVertex &va = mc_.vertex(ed.v[0]), &vb = mc_.vertex(ed.v[1]);
      if (va.radius_squared == vb.radius_squared) {
        best = std::min(best, va.radius + cell_distance(a, b, p, q));
        continue;
      }
      const double ra = va.radius, rb = vb.radius;
      best = std::min(best, golden_section_minimum([&](double t) {
                        return (1 - t) * ra + t * rb + norm(sub(mid, lerp(p, q, t)));
                      }, 0.0, 1.0) - half);
    } else {
      const Vec3d& o = ed.rule_point_approx;
      best = std::min(best, golden_section_minimum([&](double t) {
                        const Vec3d y = lerp(p, q, t);
                        return norm(sub(y, o)) + norm(sub(mid, y));
                      }, 0.0, 1.0) - half);
    }
  }
  for (std::uint32_t i : sheet_sources_[s])
    best = std::min(best, o_.sources[i].t0.get_d() + point_segment(source_point_[i], a, b));
  return best;
}

void BtLowerBound::solve() {
  const std::size_t n = cells_.size();
  const double r = o_.reach > 0 ? o_.reach : 32 * o_.spacing;
  // side values n_t(c), initialised with the ignitions of each side's sheet
  std::vector<std::vector<double>> side(n);
  for (std::size_t c = 0; c < n; ++c)
    for (std::uint32_t s : cells_[c].side_sheet)
      side[c].push_back(s == kNoIndex ? kInf : ignition_bound(s, cells_[c].a, cells_[c].b));
  n_value_.assign(n, kInf);
  l_value_.assign(n, kInf);
  std::vector<char> n_done(n, 0), l_done(n, 0);
  using Item = std::pair<double, std::uint64_t>;  // value, 2 * cell + (0: N, 1: L)
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  auto settle_n = [&](std::size_t c) {
    const double v = std::min(cells_[c].floor, cells_[c].need == 0 ? link_time(mc_, cells_[c].vertex, side[c])
                                                                   : kth(side[c], cells_[c].need));
    if (v < n_value_[c]) {
      n_value_[c] = v;
      queue.push({v, 2 * c});
    }
  };
  for (std::size_t c = 0; c < n; ++c) settle_n(c);
  // every cell's sheets, for the L -> n_t relaxation
  std::vector<std::vector<std::uint32_t>> cell_sheets(n);
  for (std::uint32_t s = 0; s < sheet_cells_.size(); ++s)
    for (std::uint32_t c : sheet_cells_[s]) cell_sheets[c].push_back(s);
  std::uint64_t pops = 0;
  while (!queue.empty()) {
    const auto [v, item] = queue.top();
    queue.pop();
    const std::size_t c = item / 2;
    if (++pops > 8 * n * n + 64) throw std::logic_error("bt_bracket: lower-bound sweep did not terminate");
    if (item % 2 == 0) {
      if (n_done[c] || v > n_value_[c]) continue;
      n_done[c] = 1;
      // the envelope: L(c') <= N(c) + dist(c', c) for every cell c'
      for (std::size_t d = 0; d < n; ++d) {
        if (l_done[d]) continue;
        const double w = v + cell_distance(cells_[d].a, cells_[d].b, cells_[c].a, cells_[c].b);
        if (w < l_value_[d]) {
          l_value_[d] = w;
          queue.push({w, 2 * d + 1});
        }
      }
    } else {
      if (l_done[c] || v > l_value_[c]) continue;
      l_done[c] = 1;
      // non-local arrivals through each sheet of c's closure, at least r later
      for (std::uint32_t s : cell_sheets[c])
        for (std::uint32_t d : sheet_cells_[s]) {
          if (n_done[d]) continue;
          const double w = v + std::max(r, cell_distance(cells_[d].a, cells_[d].b, cells_[c].a, cells_[c].b));
          bool changed = false;
          for (std::size_t j = 0; j < cells_[d].side_sheet.size(); ++j)
            if (cells_[d].side_sheet[j] == s && w < side[d][j]) side[d][j] = w, changed = true;
          if (changed) settle_n(d);
        }
    }
  }
}

double BtLowerBound::at(const ComplexPoint& x) const {
  const Vec3d p = x.approx();
  double best = kInf;
  if (on_sigma(x)) {
    for (std::size_t c = 0; c < cells_.size(); ++c)
      best = std::min(best, n_value_[c] + point_segment(p, cells_[c].a, cells_[c].b));
    return best;
  }
  std::uint32_t t = x.id;
  if (x.kind == ComplexPoint::Kind::Edge) t = mc_.edge_triangles(x.id).front();
  if (x.kind == ComplexPoint::Kind::Vertex) t = mc_.vertex_triangles(x.id).front();
  const std::uint32_t s = mc_.triangle(t).sheet;
  best = ignition_bound(s, p, p);
  for (std::uint32_t c : sheet_cells_[s]) best = std::min(best, l_value_[c] + point_segment(p, cells_[c].a, cells_[c].b));
  return best;
}

namespace {
BtLowerBoundOptions lower_options(double h, const std::vector<PointSource>& sources) {
  BtLowerBoundOptions o;
  o.spacing = h;
  o.sources = sources;
  return o;
}
DiscreteBurningOptions upper_options(double h, const std::vector<PointSource>& sources) {
  DiscreteBurningOptions o;
  o.spacing = h;
  o.sources = sources;
  return o;
}
}  // namespace

BtBracket::BtBracket(const MedialComplex& mc, double spacing, const std::vector<PointSource>& sources)
    : mc_(mc),
      sources_(sources),
      lower_(mc, lower_options(spacing, sources)),
      upper_(burn_discrete(mc, upper_options(spacing, sources))),
      chords_(mc, spacing, sources) {}

Interval BtBracket::at(const ComplexPoint& x) const {
  Interval r;
  r.lo = lower_.at(x);
  r.hi = std::min(discrete_burning_time_at(mc_, upper_, sources_, x), chords_.at(x));
  return r;
}

}  // namespace grassfire
