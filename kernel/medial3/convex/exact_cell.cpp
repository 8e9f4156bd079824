// exact_cell.cpp -- see exact_cell.h.
#include "medial3/convex/exact_cell.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grassfire {

namespace {

template <class T>
using Vec3 = std::array<T, 3>;

template <class T>
Vec3<T> cross3(const Vec3<T>& u, const Vec3<T>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

template <class T>
T dot3(const Vec3<T>& u, const Vec3<T>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// Cramer's rule for the point on three planes n_i . x + d_i = 0, homogeneously:
// W = n1 . (n2 x n3), (X, Y, Z) = -(d1 n2 x n3 + d2 n3 x n1 + d3 n1 x n2).
template <class T>
std::array<T, 4> cramer(const std::array<const std::array<T, 4>*, 3>& p) {
  Vec3<T> n[3];
  for (int i = 0; i < 3; ++i) n[i] = {(*p[i])[0], (*p[i])[1], (*p[i])[2]};
  const Vec3<T> c23 = cross3(n[1], n[2]), c31 = cross3(n[2], n[0]), c12 = cross3(n[0], n[1]);
  std::array<T, 4> out;
  for (int k = 0; k < 3; ++k) out[k] = T(0) - ((*p[0])[3] * c23[k] + (*p[1])[3] * c31[k] + (*p[2])[3] * c12[k]);
  out[3] = dot3(n[0], c23);
  return out;
}

// Plane coefficients and vertices are finite, but their double enclosures may overflow
// (coordinates near 1e308): an enclosure with an infinite or NaN end decides nothing.
int certified(const Interval& x) {
  if (!std::isfinite(x.lo) || !std::isfinite(x.hi)) return 2;
  if (x.lo > 0) return 1;
  if (x.hi < 0) return -1;
  return 2;  // undecided
}

std::vector<std::uint32_t> sorted_union(std::vector<std::uint32_t> a, std::uint32_t id) {
  auto it = std::lower_bound(a.begin(), a.end(), id);
  if (it == a.end() || *it != id) a.insert(it, id);
  return a;
}

}  // namespace

HomogeneousPoint point_on_planes(const std::array<RadicalNumber, 4>& a, const std::array<RadicalNumber, 4>& b,
                                 const std::array<RadicalNumber, 4>& c, NumberStats* stats) {
  HomogeneousPoint h;
  h.c = cramer<RadicalNumber>({&a, &b, &c});
  h.w_sign = sign(h.c[3], stats);
  if (h.w_sign == 0) throw std::logic_error("exact_cell: defining planes are dependent");
  return h;
}

LazyPoint3::LazyPoint3(const ExactPoint3& p)
    : approx_{enclose(p.x), enclose(p.y), enclose(p.z)}, rational_(true), point_(p) {
  auto h = std::make_shared<HomogeneousPoint>();
  h->c = {RadicalNumber(p.x), RadicalNumber(p.y), RadicalNumber(p.z), RadicalNumber(1)};
  exact_ = h;
}

LazyPoint3::LazyPoint3(std::array<CellPlane, 3> planes, const std::array<Interval, 3>& approx)
    : planes_(planes.begin(), planes.end()), approx_(approx) {}

LazyPoint3::LazyPoint3(std::shared_ptr<const HomogeneousPoint> exact, const std::array<Interval, 3>& approx)
    : approx_(approx), exact_(std::move(exact)) {}

const HomogeneousPoint& LazyPoint3::exact() const {
  if (!exact_)
    exact_ = std::make_shared<HomogeneousPoint>(point_on_planes(planes_[0].coef(), planes_[1].coef(), planes_[2].coef()));
  return *exact_;
}

void ClipStats::merge(const ClipStats& o) {
  sign_tests += o.sign_tests;
  by_support += o.by_support;
  by_structure += o.by_structure;
  by_filter += o.by_filter;
  by_exact += o.by_exact;
  exact_points += o.exact_points;
  number.merge(o.number);
}

CellPlane::CellPlane(Coefficients coef, std::uint64_t label) : label_(label) {
  for (int k = 0; k < 4; ++k) approx_[k] = coef[k].approx();
  coef_ = std::make_shared<const Coefficients>(std::move(coef));
}

CellPlane::CellPlane(std::function<Coefficients()> make, const std::array<Interval, 4>& approx, std::uint64_t label)
    : make_(std::move(make)), approx_(approx), label_(label) {}

CellPlane::CellPlane(Coefficients coef, const std::array<Interval, 4>& approx, std::uint64_t label)
    : coef_(std::make_shared<const Coefficients>(std::move(coef))), approx_(approx), label_(label) {}

const CellPlane::Coefficients& CellPlane::coef() const {
  if (!coef_) coef_ = std::make_shared<const Coefficients>(make_());
  return *coef_;
}

CellPlane make_cell_plane(std::array<RadicalNumber, 4> coef, std::uint64_t label) { return CellPlane(std::move(coef), label); }

CellPlane rational_plane(const mpq_class& a, const mpq_class& b, const mpq_class& c, const mpq_class& d,
                         std::uint64_t label) {
  return make_cell_plane({RadicalNumber(a), RadicalNumber(b), RadicalNumber(c), RadicalNumber(d)}, label);
}

std::uint32_t PlaneSet::add(CellPlane p) {
  planes_.push_back(std::move(p));
  return static_cast<std::uint32_t>(planes_.size() - 1);
}

const HomogeneousPoint& PlaneSet::exact(const CellVertex& v) {
  if (!v.exact) {
    if (v.defining[0] == kNoPlane) throw std::logic_error("exact_cell: vertex without exact point or planes");
    auto h = std::make_shared<HomogeneousPoint>(point_on_planes(
        planes_[v.defining[0]].coef(), planes_[v.defining[1]].coef(), planes_[v.defining[2]].coef(), &stats.number));
    ++stats.exact_points;
    // The cache is logically const: the value is a function of the defining planes.
    const_cast<CellVertex&>(v).exact = h;
  }
  return *v.exact;
}

int PlaneSet::side(std::uint32_t id, const CellVertex& v) {
  ++stats.sign_tests;
  if (std::binary_search(v.support.begin(), v.support.end(), id)) {
    ++stats.by_support;
    return 0;
  }
  const CellPlane& p = planes_[id];
  const Interval value = p.approx()[0] * v.approx[0] + p.approx()[1] * v.approx[1] + p.approx()[2] * v.approx[2] + p.approx()[3];
  const int s = certified(value);
  if (s != 2) {
    ++stats.by_filter;
    return s;
  }
  if (structural_zero_ && structural_zero_(id, v)) {
    ++stats.by_structure;
    return 0;
  }
  ++stats.by_exact;
  const HomogeneousPoint& h = exact(v);
  const CellPlane::Coefficients& c = p.coef();
  const RadicalNumber e = c[0] * h.c[0] + c[1] * h.c[1] + c[2] * h.c[2] + c[3] * h.c[3];
  return sign(e, &stats.number) * h.w_sign;
}

CellVertex PlaneSet::vertex_on(std::array<std::uint32_t, 3> defining, std::vector<std::uint32_t> support) {
  CellVertex v;
  v.defining = defining;
  v.support = std::move(support);
  const std::array<Interval, 4> h =
      cramer<Interval>({&planes_[defining[0]].approx(), &planes_[defining[1]].approx(), &planes_[defining[2]].approx()});
  if (certified(h[3]) != 2) {
    for (int k = 0; k < 3; ++k) v.approx[k] = h[k] / h[3];
    return v;
  }
  // The double enclosure of W straddles zero: enclose the exact coordinates instead.
  const HomogeneousPoint& e = exact(v);
  for (int k = 0; k < 3; ++k) {
    double err = 0;
    const double mid = approximate_quotient(e.c[k], e.c[3], 53, &err).get_d();
    v.approx[k] = Interval(round_down(mid - err), round_up(mid + err));
  }
  return v;
}

CellVertex rational_vertex(const ExactPoint3& p, std::vector<std::uint32_t> support, const std::array<double, 3>& origin) {
  CellVertex v;
  v.support = std::move(support);
  std::sort(v.support.begin(), v.support.end());
  v.approx = {enclose(p.x) - origin[0], enclose(p.y) - origin[1], enclose(p.z) - origin[2]};
  auto h = std::make_shared<HomogeneousPoint>();
  h->c = {RadicalNumber(p.x), RadicalNumber(p.y), RadicalNumber(p.z), RadicalNumber(1)};
  v.exact = h;
  return v;
}

ConvexCell::ConvexCell(PlaneSet& planes, std::vector<CellVertex> vertices, std::vector<CellFace> faces)
    : planes_(&planes), vertices_(std::move(vertices)), faces_(std::move(faces)) {}

std::uint32_t ConvexCell::crossing_vertex(std::uint32_t a, std::uint32_t b, std::uint32_t face_plane) {
  const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
  for (Crossing& c : crossings_)
    if (c.a == lo && c.b == hi) {
      c.face_planes[1] = face_plane;
      return c.vertex;
    }
  const auto id = static_cast<std::uint32_t>(vertices_.size() + crossings_.size());
  crossings_.push_back({lo, hi, id, {face_plane, kNoPlane}});
  return id;
}

// Builds the vertices created on cut edges: each lies on the two faces of its edge (whose
// planes are independent, being distinct faces of a convex polytope) and on the new plane.
void ConvexCell::finish_crossings(std::uint32_t id) {
  for (const Crossing& c : crossings_) {
    if (c.face_planes[1] == kNoPlane) throw std::logic_error("exact_cell: cut edge seen by one face only");
    const std::vector<std::uint32_t>& sa = vertices_[c.a].support;
    const std::vector<std::uint32_t>& sb = vertices_[c.b].support;
    std::vector<std::uint32_t> common;
    std::set_intersection(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(common));
    vertices_.push_back(planes_->vertex_on({c.face_planes[0], c.face_planes[1], id}, sorted_union(common, id)));
  }
}

ConvexCell::Clip ConvexCell::clip(std::uint32_t id) {
  side_.assign(vertices_.size(), 1);
  std::vector<char>& used = used_;  // scratch kept across clips: clips are many and small
  used.assign(vertices_.size(), 0);
  for (const CellFace& f : faces_)
    for (std::uint32_t v : f.vertices) used[v] = 1;
  bool any_pos = false, any_neg = false;
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    if (!used[v]) continue;
    side_[v] = planes_->side(id, vertices_[v]);
    any_pos |= side_[v] > 0;
    any_neg |= side_[v] < 0;
  }
  if (!any_neg) {
    if (!any_pos) throw std::logic_error("exact_cell: a full-dimensional cell lies in a plane");
    faces_.clear();
    return Clip::Emptied;
  }
  for (std::uint32_t v = 0; v < vertices_.size(); ++v)
    if (used[v] && side_[v] == 0) vertices_[v].support = sorted_union(vertices_[v].support, id);
  if (!any_pos) {
    for (CellFace& f : faces_) {
      const bool in_plane = std::all_of(f.vertices.begin(), f.vertices.end(), [&](std::uint32_t v) { return side_[v] == 0; });
      if (in_plane) f.planes.push_back(id);
    }
    return Clip::Untouched;
  }
  crossings_.clear();
  const auto first_new = static_cast<std::uint32_t>(vertices_.size());
  auto on_plane = [&](std::uint32_t v) { return v >= first_new || side_[v] == 0; };
  std::vector<CellFace> kept;
  kept.reserve(faces_.size() + 1);
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& cap_next = cap_next_;  // cap edges w -> u
  cap_next.clear();
  auto next_on_cap = [&](std::uint32_t w) {
    for (const auto& e : cap_next)
      if (e.first == w) return e.second;
    return kNoPlane;
  };
  for (CellFace& f : faces_) {
    CellFace out;
    const std::size_t n = f.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t a = f.vertices[k], b = f.vertices[(k + 1) % n];
      if (side_[a] <= 0) out.vertices.push_back(a);
      if (side_[a] * side_[b] < 0) out.vertices.push_back(crossing_vertex(a, b, f.planes[0]));
    }
    if (out.vertices.size() < 3) continue;
    const std::size_t m = out.vertices.size();
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t u = out.vertices[k], w = out.vertices[(k + 1) % m];
      if (on_plane(u) && on_plane(w)) {  // the cap runs the shared edge backwards
        bool seen = false;
        for (auto& e : cap_next)
          if (e.first == w) e.second = u, seen = true;
        if (!seen) cap_next.emplace_back(w, u);
      }
    }
    out.planes = std::move(f.planes);
    kept.push_back(std::move(out));
  }
  finish_crossings(id);
  CellFace cap;
  cap.planes = {id};
  if (cap_next.size() < 3) throw std::logic_error("exact_cell: degenerate cap");
  std::uint32_t u = std::min_element(cap_next.begin(), cap_next.end())->first;  // as the map's first key
  for (std::size_t guard = 0; guard <= cap_next.size(); ++guard) {
    cap.vertices.push_back(u);
    u = next_on_cap(u);
    if (u == kNoPlane) throw std::logic_error("exact_cell: open cap chain");
    if (u == cap.vertices.front()) break;
  }
  if (cap.vertices.size() != cap_next.size()) throw std::logic_error("exact_cell: cap is not one cycle");
  kept.push_back(std::move(cap));
  faces_ = std::move(kept);
  return Clip::Cut;
}

}  // namespace grassfire
