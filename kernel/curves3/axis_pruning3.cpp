// axis_pruning3.cpp -- the subdivision K of axis_pruning3.h: the threshold lines cut every
// cell of M exactly; the collapse is in axis_pruning3_collapse.cpp.
#include "curves3/axis_pruning3.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "curves3/axis_pruning3_detail.h"
#include "curves3/medial_curves.h"

namespace grassfire {
namespace pruning3 {

namespace {

using Weights = std::array<mpq_class, 3>;
using Polygon = std::vector<Weights>;

// A threshold function's value at a point: +infinity (a corner that never burns has weight
// there) or an exact rational.
struct Value {
  bool infinite = false;
  mpq_class v;
  // ST at a point where BT = 0 (a border igniting at R = 0): G = 0 there, but ST = 1 - R/BT
  // is undefined; such points fail a positive ST threshold, so that the collapse can start
  // from that border (keeping them would block every collapse of a failing sheet).
  bool undefined_st = false;
  bool fails() const { return !infinite && (sgn(v) < 0 || (sgn(v) == 0 && undefined_st)); }
};

}  // namespace

// The two threshold functions at the corners of a cell (E = BT - R - T, G = (1 - S) BT - R).
struct CornerValues {
  std::array<Value, 3> e, g;
};

class Subdivision {
 public:
  Subdivision(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& t)
      : mc_(mc), values_(values), t_(t) {}

  Refined build() {
    edge_params_.resize(mc_.edge_count());
    pieces_.resize(mc_.triangle_count());
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) add_edge_crossings(e);
    for (std::uint32_t t = 0; t < mc_.triangle_count(); ++t) clip_triangle(t);
    number_vertices();
    for (std::uint32_t t = 0; t < mc_.triangle_count(); ++t) {
      interior_.clear();
      for (const Polygon& p : pieces_[t]) add_piece(t, p);
    }
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e)
      if (mc_.edge(e).stratum == EdgeStratum::Dangling) add_segment(e);
    return std::move(k_);
  }

 private:
  Value value_of(double bt, double r, bool erosion) const {
    if (!std::isfinite(bt)) return {true, 0};
    const mpq_class b(bt), rr(r);
    if (erosion) return {false, b - rr - *t_.erosion};
    return {false, (1 - *t_.tubularity) * b - rr, bt == 0 && sgn(*t_.tubularity) > 0};
  }
  std::array<double, 2> edge_bt(std::uint32_t e) const {
    const ComplexEdge& ed = mc_.edge(e);
    return {values_.vertex_bt[ed.v[0]], values_.vertex_bt[ed.v[1]]};
  }
  // Values of the function `erosion` (else tubularity) at the cell's corners.
  std::array<Value, 3> triangle_values(std::uint32_t t, bool erosion) const {
    std::array<Value, 3> out;
    for (int i = 0; i < 3; ++i)
      out[i] = value_of(values_.corner_bt[t][i], mc_.vertex(mc_.triangle(t).v[i]).radius, erosion);
    return out;
  }
  std::array<Value, 2> edge_values(std::uint32_t e, bool erosion) const {
    const ComplexEdge& ed = mc_.edge(e);
    const std::array<double, 2> bt = edge_bt(e);
    return {value_of(bt[0], mc_.vertex(ed.v[0]).radius, erosion), value_of(bt[1], mc_.vertex(ed.v[1]).radius, erosion)};
  }
  static Value combine(const Value* at, const mpq_class* w, int n) {
    Value out;
    out.undefined_st = true;
    for (int i = 0; i < n; ++i) {
      if (sgn(w[i]) == 0) continue;
      if (at[i].infinite) return {true, 0};
      out.v += w[i] * at[i].v;
      out.undefined_st &= at[i].undefined_st;  // BT >= 0: BT = 0 at a point iff at its corners
    }
    return out;
  }
  bool fails_on_edge(std::uint32_t e, const mpq_class& s) const {
    const mpq_class w[2] = {1 - s, s};
    for (bool erosion : {true, false}) {
      if (!(erosion ? t_.erosion.has_value() : t_.tubularity.has_value())) continue;
      if (combine(edge_values(e, erosion).data(), w, 2).fails()) return true;
    }
    return false;
  }
  bool fails_in_triangle(std::uint32_t t, const Weights& w) const {
    for (bool erosion : {true, false}) {
      if (!(erosion ? t_.erosion.has_value() : t_.tubularity.has_value())) continue;
      if (combine(triangle_values(t, erosion).data(), w.data(), 3).fails()) return true;
    }
    return false;
  }

  // The edges' own crossings: where E or G changes sign strictly between finite ends.
  void add_edge_crossings(std::uint32_t e) {
    for (bool erosion : {true, false}) {
      if (!(erosion ? t_.erosion.has_value() : t_.tubularity.has_value())) continue;
      const std::array<Value, 2> v = edge_values(e, erosion);
      if (v[0].infinite || v[1].infinite || sgn(v[0].v) * sgn(v[1].v) >= 0) continue;
      edge_params_[e].push_back(v[0].v / (v[0].v - v[1].v));
    }
  }

  // Sutherland-Hodgman by one linear function: the pieces where it is >= 0 and <= 0,
  // each dropped when degenerate (fewer than 3 corners, or no corner strictly on its side;
  // a polygon on which the function is 0 everywhere is the >= 0 piece).
  static void split(const Polygon& poly, const std::array<Value, 3>& at, std::vector<Polygon>& out) {
    std::vector<mpq_class> f;
    for (const Weights& w : poly) f.push_back(combine(at.data(), w.data(), 3).v);
    Polygon pos, neg;
    bool strict_pos = false, strict_neg = false;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const std::size_t j = (i + 1) % poly.size();
      const int si = sgn(f[i]), sj = sgn(f[j]);
      if (si >= 0) pos.push_back(poly[i]);
      if (si <= 0) neg.push_back(poly[i]);
      strict_pos |= si > 0;
      strict_neg |= si < 0;
      if (si * sj < 0) {
        const mpq_class s = f[i] / (f[i] - f[j]);
        Weights x;
        for (int k = 0; k < 3; ++k) x[k] = poly[i][k] + s * (poly[j][k] - poly[i][k]);
        pos.push_back(x);
        neg.push_back(x);
      }
    }
    if (pos.size() >= 3 && (strict_pos || !strict_neg)) out.push_back(std::move(pos));  // f = 0 throughout: kept
    if (neg.size() >= 3 && strict_neg) out.push_back(std::move(neg));
  }

  void clip_triangle(std::uint32_t t) {
    std::vector<Polygon> pieces = {Polygon{Weights{1, 0, 0}, Weights{0, 1, 0}, Weights{0, 0, 1}}};
    for (bool erosion : {true, false}) {
      if (!(erosion ? t_.erosion.has_value() : t_.tubularity.has_value())) continue;
      const std::array<Value, 3> at = triangle_values(t, erosion);
      if (at[0].infinite || at[1].infinite || at[2].infinite) continue;  // the open triangle passes
      std::vector<Polygon> next;
      for (const Polygon& p : pieces) split(p, at, next);
      pieces = std::move(next);
    }
    for (const Polygon& p : pieces)
      for (const Weights& w : p) {
        std::uint32_t e;
        mpq_class s;
        if (on_edge(t, w, e, s)) edge_params_[e].push_back(s);
      }
    pieces_[t] = std::move(pieces);
  }

  // Whether w lies inside an edge of t (exactly one zero weight); its edge and parameter.
  bool on_edge(std::uint32_t t, const Weights& w, std::uint32_t& e, mpq_class& s) const {
    int zeros = 0, k = 0;
    for (int i = 0; i < 3; ++i)
      if (sgn(w[i]) == 0) ++zeros, k = i;
    if (zeros != 1) return false;
    const ComplexTriangle& tr = mc_.triangle(t);
    e = tr.e[k];
    const int j = tr.v[(k + 1) % 3] == mc_.edge(e).v[1] ? (k + 1) % 3 : (k + 2) % 3;
    s = w[j];
    return true;
  }

  void number_vertices() {
    for (std::uint32_t v = 0; v < mc_.vertex_count(); ++v) {
      const ComplexVertex& cv = mc_.vertex(v);
      RefinedVertex3 x;
      x.point = cv.exact;
      x.radius_squared = cv.radius_squared;
      x.info = {PrunedVertex3::On::Vertex, v, cv.radius, values_.vertex_bt[v], false};
      const mpq_class w[1] = {1};
      for (bool erosion : {true, false})
        if (erosion ? t_.erosion.has_value() : t_.tubularity.has_value()) {
          const Value at = value_of(values_.vertex_bt[v], cv.radius, erosion);
          x.info.fails |= combine(&at, w, 1).fails();
        }
      k_.vertices.push_back(std::move(x));
    }
    edge_first_.resize(mc_.edge_count());
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      std::vector<mpq_class>& p = edge_params_[e];
      std::sort(p.begin(), p.end());
      p.erase(std::unique(p.begin(), p.end()), p.end());
      edge_first_[e] = static_cast<std::uint32_t>(k_.vertices.size());
      const ComplexEdge& ed = mc_.edge(e);
      const ComplexVertex &a = mc_.vertex(ed.v[0]), &b = mc_.vertex(ed.v[1]);
      const std::array<double, 2> bt = edge_bt(e);
      for (const mpq_class& s : p) {
        RefinedVertex3 x;
        x.point = {a.exact.x + s * (b.exact.x - a.exact.x), a.exact.y + s * (b.exact.y - a.exact.y),
                   a.exact.z + s * (b.exact.z - a.exact.z)};
        const mpq_class r = (1 - s) * mpq_class(a.radius) + s * mpq_class(b.radius);
        x.radius_squared = r * r;
        const double sd = s.get_d();
        x.info = {PrunedVertex3::On::Edge, e, r.get_d(), interpolate(bt[0], bt[1], sd), fails_on_edge(e, s)};
        k_.vertices.push_back(std::move(x));
        ++k_.cut_points;
      }
    }
  }
  static double interpolate(double a, double b, double s) {
    if (s == 0) return a;
    if (s == 1) return b;
    if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
    return (1 - s) * a + s * b;
  }

  std::uint32_t edge_point_id(std::uint32_t e, const mpq_class& s) const {
    const std::vector<mpq_class>& p = edge_params_[e];
    const auto it = std::lower_bound(p.begin(), p.end(), s);
    if (it == p.end() || *it != s) throw std::logic_error("prune3d: a cut point is missing on its edge");
    return edge_first_[e] + static_cast<std::uint32_t>(it - p.begin());
  }

  // The vertex of K at w in t, made when it lies inside t.
  std::uint32_t vertex_id(std::uint32_t t, const Weights& w) {
    const ComplexTriangle& tr = mc_.triangle(t);
    for (int i = 0; i < 3; ++i)
      if (w[i] == 1) return tr.v[i];
    std::uint32_t e;
    mpq_class s;
    if (on_edge(t, w, e, s)) return edge_point_id(e, s);
    for (const auto& [iw, id] : interior_)
      if (iw == w) return id;
    RefinedVertex3 x;
    mpq_class r = 0;
    double bt = 0;
    bool burns = true;
    for (int i = 0; i < 3; ++i) {
      const ComplexVertex& c = mc_.vertex(tr.v[i]);
      x.point.x += w[i] * c.exact.x, x.point.y += w[i] * c.exact.y, x.point.z += w[i] * c.exact.z;
      r += w[i] * mpq_class(c.radius);
      if (!std::isfinite(values_.corner_bt[t][i])) burns = false;
      bt += w[i].get_d() * values_.corner_bt[t][i];
    }
    x.radius_squared = r * r;
    x.info = {PrunedVertex3::On::Triangle, t, r.get_d(), burns ? bt : std::numeric_limits<double>::infinity(),
              fails_in_triangle(t, w)};
    k_.vertices.push_back(std::move(x));
    ++k_.cut_points;
    const auto id = static_cast<std::uint32_t>(k_.vertices.size() - 1);
    interior_.push_back({w, id});
    return id;
  }

  // Whether the point w of t fails: a vertex's, an edge's or the triangle's own values.
  bool fails_at(std::uint32_t t, const Weights& w) const {
    std::uint32_t e;
    mpq_class s;
    if (on_edge(t, w, e, s)) return fails_on_edge(e, s);
    return fails_in_triangle(t, w);
  }

  std::uint32_t edge_id(std::uint32_t a, std::uint32_t b, bool fails, std::uint32_t parent) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    const auto [it, fresh] = edge_ids_.try_emplace(key, static_cast<std::uint32_t>(k_.edges.size()));
    if (fresh) k_.edges.push_back({{std::min(a, b), std::max(a, b)}, parent, fails});
    return it->second;
  }

  void add_triangle(std::uint32_t t, const std::array<std::uint32_t, 3>& v, const std::array<Weights, 3>& w) {
    RefinedTriangle3 x;
    x.v = v;
    Weights centroid;
    for (int k = 0; k < 3; ++k) centroid[k] = (w[0][k] + w[1][k] + w[2][k]) / 3;
    x.fails = fails_in_triangle(t, centroid);
    for (int i = 0; i < 3; ++i) {
      const int a = (i + 1) % 3, b = (i + 2) % 3;
      Weights mid;
      for (int k = 0; k < 3; ++k) mid[k] = (w[a][k] + w[b][k]) / 2;
      std::uint32_t e = kNoIndex;
      mpq_class s;
      on_edge(t, mid, e, s);
      x.e[i] = edge_id(v[a], v[b], fails_at(t, mid), e);
    }
    k_.triangles.push_back(x);
  }

  // A convex piece of t as triangles of K: a fan from its first corner, or from its centroid
  // when a side carries split points (cut points of the neighbouring triangles).
  void add_piece(std::uint32_t t, const Polygon& poly) {
    std::vector<std::uint32_t> ids;
    std::vector<Weights> ws;
    bool inserted = false;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Weights &a = poly[i], &b = poly[(i + 1) % poly.size()];
      ids.push_back(vertex_id(t, a));
      ws.push_back(a);
      for (int k = 0; k < 3; ++k) {
        if (sgn(a[k]) != 0 || sgn(b[k]) != 0) continue;  // the side lies on the edge opposite corner k
        const ComplexTriangle& tr = mc_.triangle(t);
        const std::uint32_t e = tr.e[k];
        const int j = tr.v[(k + 1) % 3] == mc_.edge(e).v[1] ? (k + 1) % 3 : (k + 2) % 3;
        const mpq_class lo = std::min(a[j], b[j]), hi = std::max(a[j], b[j]);
        std::vector<mpq_class> between;
        for (const mpq_class& s : edge_params_[e])
          if (s > lo && s < hi) between.push_back(s);
        if (a[j] > b[j]) std::reverse(between.begin(), between.end());
        for (const mpq_class& s : between) {
          Weights x;
          x[k] = 0;
          x[j] = s;
          x[3 - k - j] = 1 - s;
          ids.push_back(edge_point_id(e, s));
          ws.push_back(x);
          inserted = true;
        }
      }
    }
    if (!inserted) {
      for (std::size_t i = 1; i + 1 < ids.size(); ++i) add_triangle(t, {ids[0], ids[i], ids[i + 1]}, {ws[0], ws[i], ws[i + 1]});
      return;
    }
    Weights c{0, 0, 0};
    for (const Weights& w : poly)
      for (int k = 0; k < 3; ++k) c[k] += w[k] / static_cast<long>(poly.size());
    const std::uint32_t center = vertex_id(t, c);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const std::size_t j = (i + 1) % ids.size();
      add_triangle(t, {center, ids[i], ids[j]}, {c, ws[i], ws[j]});
    }
  }

  void add_segment(std::uint32_t e) {
    const ComplexEdge& ed = mc_.edge(e);
    std::vector<std::uint32_t> ids = {ed.v[0]};
    std::vector<mpq_class> s = {0};
    for (std::size_t i = 0; i < edge_params_[e].size(); ++i) {
      ids.push_back(edge_first_[e] + static_cast<std::uint32_t>(i));
      s.push_back(edge_params_[e][i]);
    }
    ids.push_back(ed.v[1]);
    s.push_back(1);
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) edge_id(ids[i], ids[i + 1], fails_on_edge(e, (s[i] + s[i + 1]) / 2), e);
  }

  const MedialComplex& mc_;
  const AxisValues3& values_;
  const PruningThresholds3& t_;
  std::vector<std::vector<mpq_class>> edge_params_;
  std::vector<std::uint32_t> edge_first_;
  std::vector<std::vector<Polygon>> pieces_;
  std::vector<std::pair<Weights, std::uint32_t>> interior_;  // of the current triangle
  std::unordered_map<std::uint64_t, std::uint32_t> edge_ids_;
  Refined k_;
};

Refined subdivide(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& thresholds) {
  return Subdivision(mc, values, thresholds).build();
}

std::uint64_t uncertified_vertices(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& t) {
  if (values.vertex_bt_error.empty()) return 0;
  std::uint64_t count = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const double bt = values.vertex_bt[v], err = values.vertex_bt_error[v];
    if (!std::isfinite(bt) || !std::isfinite(err)) continue;
    const mpq_class b(bt), r(mc.vertex(v).radius), e(err);
    bool close = false;
    if (t.erosion) close |= abs(b - r - *t.erosion) <= e;
    if (t.tubularity) close |= abs((1 - *t.tubularity) * b - r) <= (1 - *t.tubularity) * e;
    count += close ? 1 : 0;
  }
  return count;
}

}  // namespace pruning3

PrunedAxis3 prune_axis3(const MedialComplex& mc, const AxisValues3& values, const PruningThresholds3& thresholds) {
  const auto start = std::chrono::steady_clock::now();
  if (values.vertex_bt.size() != mc.vertex_count() || values.corner_bt.size() != mc.triangle_count() ||
      (!values.vertex_bt_error.empty() && values.vertex_bt_error.size() != mc.vertex_count()))
    throw std::invalid_argument("prune3d: one burning time per vertex and three per triangle are needed");
  if ((thresholds.erosion && sgn(*thresholds.erosion) < 0) ||
      (thresholds.tubularity && (sgn(*thresholds.tubularity) < 0 || *thresholds.tubularity > 1)))
    throw std::invalid_argument("prune3d: thresholds must be ET >= 0 and ST in [0, 1]");
  pruning3::Refined k = pruning3::subdivide(mc, values, thresholds);
  PrunedAxis3 out = pruning3::collapse(mc, std::move(k));
  out.betti_axis = complex_betti(mc);
  if (out.betti_refined != out.betti_axis || out.betti_pruned != out.betti_axis)
    throw std::logic_error("prune3d: Betti numbers changed: axis " + betti_text(out.betti_axis) + ", subdivided " +
                           betti_text(out.betti_refined) + ", pruned " + betti_text(out.betti_pruned));
  out.stats.uncertified = pruning3::uncertified_vertices(mc, values, thresholds);
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace grassfire
