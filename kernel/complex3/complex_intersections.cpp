// complex_intersections.cpp -- exact improper-intersection search (see header). The only
// translation unit of complex3 that includes CGAL.
#include "complex3/complex_intersections.h"

#include "geometry3/exact_predicates3.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <tuple>
#include <vector>

namespace grassfire {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Triangle = K::Triangle_3;

struct Cell {
  std::array<std::uint32_t, 3> v;
  int n;  // 3: triangle, 2: segment
  std::size_t id;
};

using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const Cell*, CGAL::Box_intersection_d::ID_EXPLICIT>;

K::FT exact_ft(const mpq_class& q) { return K::FT(CGAL::Epeck_ft(q.get_mpq_t())); }

std::string name(const Cell& c) { return std::string(c.n == 3 ? "triangle " : "segment ") + std::to_string(c.id); }

// Vectors over N = Interval (the filter) or mpz_class (exact). Every cone and side test
// below is the sign of a product that is homogeneous in each direction, so the exact stage
// may scale a direction by its common denominator (a positive integer) and take the signs
// from integer arithmetic, without rational normalisation; the filter uses the
// differences of the interval enclosures themselves.
template <class N>
struct Vec {
  N x, y, z;
};
template <class N>
Vec<N> vcross(const Vec<N>& a, const Vec<N>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class N>
N vdot(const Vec<N>& a, const Vec<N>& b) {
  return N(a.x * b.x + a.y * b.y + a.z * b.z);
}

// A vertex in homogeneous integer coordinates (X, Y, Z) / W, W > 0.
struct Homogeneous {
  mpz_class x, y, z, w;
};
Homogeneous homogeneous(const ExactPoint3& p) {
  Homogeneous h;
  mpz_lcm(h.w.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
  mpz_lcm(h.w.get_mpz_t(), h.w.get_mpz_t(), p.z.get_den_mpz_t());
  h.x = p.x.get_num() * (h.w / p.x.get_den());
  h.y = p.y.get_num() * (h.w / p.y.get_den());
  h.z = p.z.get_num() * (h.w / p.z.get_den());
  return h;
}

// The homogeneous coordinates of the vertices the exact stage met, each computed once.
class HomogeneousCache {
 public:
  explicit HomogeneousCache(const FilteredPoints& points) : points_(points) {}
  const Homogeneous& at(std::uint32_t v) const {
    if (h_.empty()) h_.resize(points_.size());
    if (!h_[v]) h_[v] = std::make_unique<Homogeneous>(homogeneous(points_.exact(v)));
    return *h_[v];
  }

 private:
  const FilteredPoints& points_;
  mutable std::vector<std::unique_ptr<Homogeneous>> h_;
};

// The exact stage: directions q - p scaled by W_p W_q > 0, signs of integers.
struct ExactSigns {
  using N = mpz_class;
  const HomogeneousCache& h;
  Vec<N> direction(std::uint32_t from, std::uint32_t to) const {
    const Homogeneous &p = h.at(from), &q = h.at(to);
    return {q.x * p.w - p.x * q.w, q.y * p.w - p.y * q.w, q.z * p.w - p.z * q.w};
  }
  int sign(const mpz_class& v) const { return sgn(v); }
};

// The filter: directions from the enclosures; a sign the interval does not certify is
// recorded, and the caller then discards the answer and asks ExactSigns.
struct IntervalSigns {
  using N = Interval;
  const FilteredPoints& points;
  mutable bool undecided = false;
  Vec<N> direction(std::uint32_t from, std::uint32_t to) const {
    const IntervalPoint3 &p = points.box(from), &q = points.box(to);
    return {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  }
  int sign(const Interval& v) const {
    const int s = certified_sign(v);
    if (s != kUndecided) return s;
    undecided = true;
    return 0;
  }
};

// The cone of a cell at its vertex v: the directions of its edges at v (one or two).
template <class N>
struct Cone {
  Vec<N> a, b, normal;  // b and normal are meaningful for a triangle's cone
  bool planar;          // two directions: the sector from a to b, normal = a x b
};

// The exact geometry of cells, over either kind of signs (the answers agree whenever the
// filter certified every sign it used).
template <class Signs>
class CellTests {
 public:
  using N = typename Signs::N;
  using V = Vec<N>;
  explicit CellTests(const Signs& signs) : s_(signs) {}

  bool is_zero(const V& a) const { return s_.sign(a.x) == 0 && s_.sign(a.y) == 0 && s_.sign(a.z) == 0; }
  int dot_sign(const V& a, const V& b) const { return s_.sign(vdot(a, b)); }

  // Is direction u in the closed cone? (u in the plane, between a and b.) `in_plane`: u is
  // known to lie in the plane of a planar cone (a cross product with its normal), where the
  // plane test is zero identically and an interval could not certify it.
  bool in_cone(const Cone<N>& c, const V& u, bool in_plane = false) const {
    if (is_zero(u)) return false;
    if (!c.planar) return is_zero(vcross(c.a, u)) && dot_sign(c.a, u) > 0;
    if (!in_plane && dot_sign(c.normal, u) != 0) return false;
    return dot_sign(c.normal, vcross(c.a, u)) >= 0 && dot_sign(c.normal, vcross(u, c.b)) >= 0;
  }
  Cone<N> cone(const Cell& c, std::uint32_t v) const {
    std::uint32_t ends[2] = {v, v};
    int n = 0;
    for (int i = 0; i < c.n; ++i)
      if (c.v[i] != v) ends[n++] = c.v[i];
    const V a = s_.direction(v, ends[0]);
    if (n == 1) return {a, a, {}, false};
    const V b = s_.direction(v, ends[1]);
    return {a, b, vcross(a, b), true};
  }
  // Two flat cells sharing only v meet beyond v iff their cones at v do (near v each cell
  // is its cone, and the intersection of two convex cells through v is convex).
  bool cones_overlap(const Cone<N>& p, const Cone<N>& q) const {
    if (!p.planar || !q.planar) {  // a ray against a ray or a sector
      const Cone<N>& ray = p.planar ? q : p;
      return in_cone(p.planar ? p : q, ray.a);
    }
    const V line = vcross(p.normal, q.normal);
    if (!is_zero(line)) {  // two planes through v meet in a line: both cones must contain a ray of it
      const V back = {-line.x, -line.y, -line.z};
      return (in_cone(p, line, true) && in_cone(q, line, true)) || (in_cone(p, back, true) && in_cone(q, back, true));
    }
    // One plane: two sectors of angle < pi overlap iff one holds a boundary ray of the other.
    return in_cone(p, q.a) || in_cone(p, q.b) || in_cone(q, p.a) || in_cone(q, p.b);
  }
  // A certificate that two triangles without a common vertex are disjoint: one lies
  // strictly on one side of the other's plane, or they are coplanar and an edge line of one
  // separates them strictly (for convex polygons in a plane such a line exists iff they are
  // disjoint). False means "not certified here": the full test decides.
  bool separated(const Cell& a, const Cell& b) const {
    const V na = vcross(s_.direction(a.v[0], a.v[1]), s_.direction(a.v[0], a.v[2]));
    int sides[3];
    for (int i = 0; i < 3; ++i) sides[i] = dot_sign(na, s_.direction(a.v[0], b.v[i]));
    if (sides[0] == sides[1] && sides[1] == sides[2] && sides[0] != 0) return true;
    const bool coplanar = sides[0] == 0 && sides[1] == 0 && sides[2] == 0;
    if (!coplanar) {
      const V nb = vcross(s_.direction(b.v[0], b.v[1]), s_.direction(b.v[0], b.v[2]));
      for (int i = 0; i < 3; ++i) sides[i] = dot_sign(nb, s_.direction(b.v[0], a.v[i]));
      return sides[0] == sides[1] && sides[1] == sides[2] && sides[0] != 0;
    }
    return separating_edge(a, b, na) || separating_edge(b, a, na);
  }
 private:
  bool separating_edge(const Cell& a, const Cell& b, const V& n) const {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t p = a.v[e];
      const V pq = s_.direction(p, a.v[(e + 1) % 3]);
      const int inner = dot_sign(n, vcross(pq, s_.direction(p, a.v[(e + 2) % 3])));
      bool all_outside = true;
      for (int i = 0; i < 3 && all_outside; ++i) all_outside = dot_sign(n, vcross(pq, s_.direction(p, b.v[i]))) == -inner;
      if (all_outside) return true;
    }
    return false;
  }
  const Signs& s_;
};

// A filter certificate that two cells without a common vertex are disjoint: an axis on
// which every vertex of b projects strictly beyond every vertex of a (certified in interval
// arithmetic). Axes: the triangles' normals, their in-plane edge normals, and the cross
// products of an edge of each (the separating axis theorem; any axis that separates is a
// proof, so a missed one only sends the pair to the exact stage).
bool separated_on_some_axis(const FilteredPoints& points, const Cell& a, const Cell& b) {
  using V = Vec<Interval>;
  const auto at = [&](std::uint32_t v) { return points.box(v); };
  const auto dir = [&](std::uint32_t p, std::uint32_t q) {
    const IntervalPoint3 &x = at(p), &y = at(q);
    return V{y[0] - x[0], y[1] - x[1], y[2] - x[2]};
  };
  const auto separates = [&](const V& axis) {
    int side = 0;
    for (int i = 0; i < a.n; ++i)
      for (int j = 0; j < b.n; ++j) {
        const int s = certified_sign(vdot(axis, dir(a.v[i], b.v[j])));
        if (s != 1 && s != -1) return false;
        if (side == 0) side = s;
        if (s != side) return false;
      }
    return true;
  };
  std::array<V, 3> edges_a, edges_b;
  const int na = a.n == 3 ? 3 : 1, nb = b.n == 3 ? 3 : 1;
  for (int i = 0; i < na; ++i) edges_a[i] = dir(a.v[i], a.v[(i + 1) % a.n]);
  for (int j = 0; j < nb; ++j) edges_b[j] = dir(b.v[j], b.v[(j + 1) % b.n]);
  for (const auto& [cell, edges, count] : {std::tuple(&a, &edges_a, na), std::tuple(&b, &edges_b, nb)}) {
    if (cell->n != 3) continue;
    const V normal = vcross((*edges)[0], (*edges)[1]);
    if (separates(normal)) return true;
    for (int i = 0; i < count; ++i)
      if (separates(vcross(normal, (*edges)[i]))) return true;
  }
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j)
      if (separates(vcross(edges_a[i], edges_b[j]))) return true;
  return false;
}

class Tester {
 public:
  explicit Tester(const FilteredPoints& points) : points_(points), homogeneous_(points) {}

  // Do cells a and b meet outside their common vertices? The filter first; the exact
  // stage when it left a sign undecided or found no certificate of disjointness.
  bool improper(const Cell& a, const Cell& b) const {
    int shared = 0;
    std::uint32_t common = 0;
    for (int i = 0; i < a.n; ++i)
      for (int j = 0; j < b.n; ++j)
        if (a.v[i] == b.v[j]) ++shared, common = a.v[i];
    if (shared >= 2) return false;  // a shared edge: settled by the angular order
    if (usable(a) && usable(b)) {
      const IntervalSigns signs{points_};
      const CellTests<IntervalSigns> filter(signs);
      bool answer = false, certain = true;
      if (shared == 0) certain = separated_on_some_axis(points_, a, b);
      else answer = filter.cones_overlap(filter.cone(a, common), filter.cone(b, common));
      if (certain && !signs.undecided) {
        ++points_.counts().filtered;
        return answer;
      }
    }
    ++points_.counts().exact;
    const ExactSigns signs{homogeneous_};
    const CellTests<ExactSigns> exact(signs);
    if (shared == 0) return !(a.n == 3 && b.n == 3 && exact.separated(a, b)) && meets(a, b);
    return exact.cones_overlap(exact.cone(a, common), exact.cone(b, common));
  }

 private:
  bool usable(const Cell& c) const {
    for (int i = 0; i < c.n; ++i)
      if (!points_.usable(c.v[i])) return false;
    return true;
  }
  Point point(std::uint32_t v) const {
    const ExactPoint3& p = points_.exact(v);
    return Point(exact_ft(p.x), exact_ft(p.y), exact_ft(p.z));
  }
  bool meets(const Cell& a, const Cell& b) const {
    if (a.n < b.n) return meets(b, a);
    const Point a0 = point(a.v[0]);
    if (a.n == 3) {
      const Triangle t(a0, point(a.v[1]), point(a.v[2]));
      if (b.n == 3) return CGAL::do_intersect(t, Triangle(point(b.v[0]), point(b.v[1]), point(b.v[2])));
      if (b.n == 2) return CGAL::do_intersect(t, Segment(point(b.v[0]), point(b.v[1])));
      return t.has_on(point(b.v[0]));
    }
    if (a.n == 2) {
      const Segment s(a0, point(a.v[1]));
      if (b.n == 2) return CGAL::do_intersect(s, Segment(point(b.v[0]), point(b.v[1])));
      return s.has_on(point(b.v[0]));
    }
    return a0 == point(b.v[0]);
  }
  const FilteredPoints& points_;
  HomogeneousCache homogeneous_;
};

}  // namespace

std::optional<std::string> first_improper_intersection(const RawComplex& raw) {
  const FilteredPoints points(raw.vertices);
  return first_improper_intersection(raw, points);
}

std::optional<std::string> first_improper_intersection(const RawComplex& raw, const FilteredPoints& points) {
  std::vector<Cell> cells;
  for (std::size_t t = 0; t < raw.triangles.size(); ++t) cells.push_back({raw.triangles[t], 3, t});
  for (std::size_t s = 0; s < raw.segments.size(); ++s) cells.push_back({{raw.segments[s][0], raw.segments[s][1], 0}, 2, s});
  std::vector<std::array<double, 3>> lo(raw.vertices.size()), hi(raw.vertices.size());
  for (std::size_t v = 0; v < raw.vertices.size(); ++v) {
    const mpq_class* c[3] = {&raw.vertices[v].x, &raw.vertices[v].y, &raw.vertices[v].z};
    for (int i = 0; i < 3; ++i) {  // the nearest double, widened by an ulp: encloses the rational
      const double d = c[i]->get_d();
      lo[v][i] = std::nextafter(d, -std::numeric_limits<double>::infinity());
      hi[v][i] = std::nextafter(d, std::numeric_limits<double>::infinity());
    }
  }
  std::vector<Box> boxes;
  boxes.reserve(cells.size());
  for (const Cell& c : cells) {
    double blo[3], bhi[3];
    for (int i = 0; i < 3; ++i) {
      blo[i] = lo[c.v[0]][i], bhi[i] = hi[c.v[0]][i];
      for (int k = 1; k < c.n; ++k) blo[i] = std::min(blo[i], lo[c.v[k]][i]), bhi[i] = std::max(bhi[i], hi[c.v[k]][i]);
    }
    boxes.emplace_back(blo, bhi, &c);
  }
  const Tester tester(points);
  std::optional<std::string> found;
  auto callback = [&](const Box& a, const Box& b) {
    if (found) return;
    const Cell *ca = a.handle(), *cb = b.handle();
    if (cb->n > ca->n || (cb->n == ca->n && cb->id < ca->id)) std::swap(ca, cb);  // a deterministic message
    if (tester.improper(*ca, *cb)) found = name(*ca) + " and " + name(*cb) + " intersect (the complex is not embedded)";
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), callback);
  return found;
}

}  // namespace grassfire
