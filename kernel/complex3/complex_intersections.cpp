// complex_intersections.cpp -- exact improper-intersection search (see header). The only
// translation unit of complex3 that includes CGAL.
#include "complex3/complex_intersections.h"

#include "complex3/exact_predicates3.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

// Integer vectors: every cone test below is a sign of a product that is homogeneous in
// each direction, so a direction may be scaled by its common denominator (a positive
// integer) and the signs come out of integer arithmetic, without rational normalisation.
struct IVec {
  mpz_class x, y, z;
};
IVec icross(const IVec& a, const IVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
int idot_sign(const IVec& a, const IVec& b) { return sgn(mpz_class(a.x * b.x + a.y * b.y + a.z * b.z)); }
bool izero(const IVec& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }
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
// q - p scaled by W_p W_q > 0.
IVec direction(const Homogeneous& p, const Homogeneous& q) {
  return {q.x * p.w - p.x * q.w, q.y * p.w - p.y * q.w, q.z * p.w - p.z * q.w};
}

// The cone of a cell at its vertex v: the directions of its edges at v (one or two).
struct Cone {
  IVec a, b, normal;  // b and normal are meaningful for a triangle's cone
  bool planar;        // two directions: the sector from a to b, normal = a x b
};

// Is direction u in the closed cone? (u in the plane, between a and b.)
bool in_cone(const Cone& c, const IVec& u) {
  if (izero(u)) return false;
  if (!c.planar) return izero(icross(c.a, u)) && idot_sign(c.a, u) > 0;
  if (idot_sign(c.normal, u) != 0) return false;
  return idot_sign(c.normal, icross(c.a, u)) >= 0 && idot_sign(c.normal, icross(u, c.b)) >= 0;
}

class Tester {
 public:
  explicit Tester(const RawComplex& raw) {
    for (const ExactPoint3& p : raw.vertices) {
      points_.emplace_back(exact_ft(p.x), exact_ft(p.y), exact_ft(p.z));
      h_.push_back(homogeneous(p));
    }
  }

  // Do cells a and b meet outside their common vertices?
  bool improper(const Cell& a, const Cell& b) const {
    std::vector<std::uint32_t> common;
    for (int i = 0; i < a.n; ++i)
      for (int j = 0; j < b.n; ++j)
        if (a.v[i] == b.v[j]) common.push_back(a.v[i]);
    if (common.size() >= 2) return false;  // a shared edge: settled by the angular order
    if (common.empty()) return !(a.n == 3 && b.n == 3 && separated(a, b)) && meets(a, b);
    return cones_overlap(cone(a, common[0]), cone(b, common[0]));
  }

 private:
  // Two flat cells sharing only v meet beyond v iff their cones at v do (near v each cell
  // is its cone, and the intersection of two convex cells through v is convex).
  Cone cone(const Cell& c, std::uint32_t v) const {
    std::vector<IVec> dirs;
    for (int i = 0; i < c.n; ++i)
      if (c.v[i] != v) dirs.push_back(direction(h_[v], h_[c.v[i]]));
    if (dirs.size() == 1) return {dirs[0], dirs[0], {}, false};
    return {dirs[0], dirs[1], icross(dirs[0], dirs[1]), true};
  }
  static bool cones_overlap(const Cone& p, const Cone& q) {
    if (!p.planar || !q.planar) {  // a ray against a ray or a sector
      const Cone& ray = p.planar ? q : p;
      return in_cone(p.planar ? p : q, ray.a);
    }
    const IVec line = icross(p.normal, q.normal);
    if (!izero(line)) {  // two planes through v meet in a line: both cones must contain a ray of it
      const IVec back = {-line.x, -line.y, -line.z};
      return (in_cone(p, line) && in_cone(q, line)) || (in_cone(p, back) && in_cone(q, back));
    }
    // One plane: two sectors of angle < pi overlap iff one holds a boundary ray of the other.
    return in_cone(p, q.a) || in_cone(p, q.b) || in_cone(q, p.a) || in_cone(q, p.b);
  }
  // An exact certificate that two triangles without a common vertex are disjoint: one lies
  // strictly on one side of the other's plane, or they are coplanar and an edge line of one
  // separates them strictly (for convex polygons in a plane such a line exists iff they are
  // disjoint). False means "not certified here": the full test decides.
  bool separated(const Cell& a, const Cell& b) const {
    const IVec na = icross(direction(h_[a.v[0]], h_[a.v[1]]), direction(h_[a.v[0]], h_[a.v[2]]));
    int sides[3];
    for (int i = 0; i < 3; ++i) sides[i] = idot_sign(na, direction(h_[a.v[0]], h_[b.v[i]]));
    if (sides[0] == sides[1] && sides[1] == sides[2] && sides[0] != 0) return true;
    const bool coplanar = sides[0] == 0 && sides[1] == 0 && sides[2] == 0;
    if (!coplanar) {
      const IVec nb = icross(direction(h_[b.v[0]], h_[b.v[1]]), direction(h_[b.v[0]], h_[b.v[2]]));
      for (int i = 0; i < 3; ++i) sides[i] = idot_sign(nb, direction(h_[b.v[0]], h_[a.v[i]]));
      return sides[0] == sides[1] && sides[1] == sides[2] && sides[0] != 0;
    }
    return separating_edge(a, b, na) || separating_edge(b, a, na);
  }
  bool separating_edge(const Cell& a, const Cell& b, const IVec& n) const {
    for (int e = 0; e < 3; ++e) {
      const Homogeneous &p = h_[a.v[e]], &q = h_[a.v[(e + 1) % 3]];
      const IVec pq = direction(p, q);
      const int inner = idot_sign(n, icross(pq, direction(p, h_[a.v[(e + 2) % 3]])));
      bool all_outside = true;
      for (int i = 0; i < 3 && all_outside; ++i) all_outside = idot_sign(n, icross(pq, direction(p, h_[b.v[i]]))) == -inner;
      if (all_outside) return true;
    }
    return false;
  }

  bool meets(const Cell& a, const Cell& b) const {
    if (a.n < b.n) return meets(b, a);
    const Point& a0 = points_[a.v[0]];
    if (a.n == 3) {
      const Triangle t(a0, points_[a.v[1]], points_[a.v[2]]);
      if (b.n == 3) return CGAL::do_intersect(t, Triangle(points_[b.v[0]], points_[b.v[1]], points_[b.v[2]]));
      if (b.n == 2) return CGAL::do_intersect(t, Segment(points_[b.v[0]], points_[b.v[1]]));
      return t.has_on(points_[b.v[0]]);
    }
    if (a.n == 2) {
      const Segment s(a0, points_[a.v[1]]);
      if (b.n == 2) return CGAL::do_intersect(s, Segment(points_[b.v[0]], points_[b.v[1]]));
      return s.has_on(points_[b.v[0]]);
    }
    return points_[a.v[0]] == points_[b.v[0]];
  }
  std::vector<Point> points_;
  std::vector<Homogeneous> h_;
};

}  // namespace

std::optional<std::string> first_improper_intersection(const RawComplex& raw) {
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
  const Tester tester(raw);
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
