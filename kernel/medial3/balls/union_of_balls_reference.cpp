// union_of_balls_reference.cpp -- see union_of_balls_reference.h.
#include "medial3/balls/union_of_balls_reference.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {

using Coords = std::array<RadicalNumber, 3>;
using Box = std::array<Interval, 3>;

struct RefVertex {
  BoundaryVertex v;  // as the builder describes its vertices (balls, side, z, n, s, point)
  Coords exact;
  Box approx;
};

struct Circle {
  std::uint32_t i, j;
  ExactPoint3 o, m;  // centre and axis direction c_j - c_i
  mpq_class alpha;   // squared radius
  bool nonempty = false;
};

Interval sqdist(const Box& a, const Box& b) {
  Interval s(0.0);
  for (int k = 0; k < 3; ++k) s += square(a[k] - b[k]);
  return s;
}

class Reference {
 public:
  Reference(const BallSet& b, RadicalTable* table) : b_(b), table_(table) {
    for (std::size_t i = 0; i < b.centers.size(); ++i) {
      centre_.push_back({enclose(b.centers[i].x), enclose(b.centers[i].y), enclose(b.centers[i].z)});
      root_.push_back(sqrt(enclose(b.squared_radii[i])));
    }
    find_vertices();
    find_circles();
    find_patches();
  }

  const std::vector<RefVertex>& vertices() const { return vertices_; }

  // "" when x (homogeneous, W^2 R^2 = d2) is a medial point with radius R; else why not.
  std::string check(const HomogeneousPoint& x, const RadicalNumber& d2) {
    const RadicalNumber sqw = x.c[3] * x.c[3];
    Box xa;
    for (int k = 0; k < 3; ++k) xa[k] = x.c[k].approx() / x.c[3].approx();
    const Interval r2 = d2.approx() / sqw.approx();
    nearest_ = 0;
    bool inside = false;
    for (std::size_t i = 0; i < b_.centers.size() && !inside; ++i) inside = sign(dist2(x, b_.centers[i]) - sqw * b_.squared_radii[i]) <= 0;
    if (!inside) return "not in the union";
    for (const RefVertex& u : vertices_) {
      if (sqdist(xa, u.approx).lo > r2.hi) continue;
      const int s = sign(dist2(x, u.exact) - d2, &stats_);
      if (s < 0) return "a boundary vertex is closer than R";
      nearest_ += s == 0;
    }
    for (const Circle& c : circles_)
      if (std::string why = check_circle(x, xa, sqw, d2, r2, c); !why.empty()) return why;
    for (std::uint32_t i = 0; i < b_.centers.size(); ++i)
      if (std::string why = check_sphere(x, xa, sqw, d2, r2, i); !why.empty()) return why;
    if (nearest_ == 0) return "R is not attained on the boundary";
    if (nearest_ == 1) return "only one nearest boundary point";
    return "";
  }

  NumberStats stats_;

 private:
  RadicalNumber dist2(const HomogeneousPoint& x, const ExactPoint3& p) const {
    RadicalNumber s;
    const mpq_class* pc[3] = {&p.x, &p.y, &p.z};
    for (int k = 0; k < 3; ++k) {
      const RadicalNumber d = x.c[k] - x.c[3] * *pc[k];
      s += d * d;
    }
    return s;
  }
  RadicalNumber dist2(const HomogeneousPoint& x, const Coords& p) const {
    RadicalNumber s;
    for (int k = 0; k < 3; ++k) {
      const RadicalNumber d = x.c[k] - x.c[3] * p[k];
      s += d * d;
    }
    return s;
  }
  RadicalNumber dot_with(const HomogeneousPoint& x, const ExactPoint3& origin, const ExactPoint3& d) const {
    // (X - W origin) . d
    return (x.c[0] - x.c[3] * origin.x) * d.x + (x.c[1] - x.c[3] * origin.y) * d.y + (x.c[2] - x.c[3] * origin.z) * d.z;
  }

  void find_vertices() {
    auto key_less = [](const std::array<ExactPoint3, 3>& x, const std::array<ExactPoint3, 3>& y) {
      for (int i = 0; i < 3; ++i)
        if (int c = compare_lex(x[i], y[i])) return c < 0;
      return false;
    };
    std::map<std::array<ExactPoint3, 3>, bool, decltype(key_less)> seen(key_less);
    const auto n = static_cast<std::uint32_t>(b_.centers.size());
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j)
        for (std::uint32_t k = j + 1; k < n; ++k)
          for (RefVertex& v : triple_vertices(i, j, k))
            if (seen.emplace(boundary_vertex_key(v.v), true).second) vertices_.push_back(std::move(v));
  }

  // pow_l at z + side sqrt(s) n is pow_l(z) + s |n|^2 + side sqrt(s) 2 n . (z - c_l).
  int power_sign_at(const BoundaryVertex& v, std::uint32_t l) const {
    return sign_with_root(power(b_, l, v.z) + v.s * dot(v.n, v.n), v.side, 2 * dot(v.n, v.z - b_.centers[l]), v.s);
  }

  // The points on the spheres of balls i, j, k outside every other ball and not surrounded
  // by the balls through them.
  std::vector<RefVertex> triple_vertices(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    std::vector<RefVertex> out;
    const ExactPoint3 &ci = b_.centers[i], &cj = b_.centers[j], &ck = b_.centers[k];
    const ExactPoint3 d1 = cj - ci, d2 = ck - ci, n = cross(d1, d2);
    if (is_zero(n)) return out;
    // Power centre in the plane: 2 (z - c_i) . d_m = |d_m|^2 + w_i - w_m, z - c_i = l1 d1 + l2 d2.
    const mpq_class a11 = 2 * dot(d1, d1), a12 = 2 * dot(d1, d2), a22 = 2 * dot(d2, d2);
    const mpq_class r1 = dot(d1, d1) + b_.squared_radii[i] - b_.squared_radii[j];
    const mpq_class r2 = dot(d2, d2) + b_.squared_radii[i] - b_.squared_radii[k];
    const mpq_class det = a11 * a22 - a12 * a12;
    const mpq_class l1 = (r1 * a22 - r2 * a12) / det, l2 = (a11 * r2 - a12 * r1) / det;
    RefVertex r;
    BoundaryVertex& v = r.v;
    v.balls = {i, j, k};
    v.z = ci + l1 * d1 + l2 * d2;
    v.n = n;
    const mpq_class w = power(b_, i, v.z);
    if (sgn(w) > 0) return out;
    v.s = -w / dot(n, n);
    mpz_class sn = v.s.get_num(), sd = v.s.get_den();
    v.rational = mpz_perfect_square_p(sn.get_mpz_t()) && mpz_perfect_square_p(sd.get_mpz_t());
    if (v.rational) {
      mpz_sqrt(sn.get_mpz_t(), sn.get_mpz_t());
      mpz_sqrt(sd.get_mpz_t(), sd.get_mpz_t());
    } else {
      v.radical = table_->add(v.s);
    }
    for (int side : {1, -1}) {
      if (side < 0 && sgn(v.s) == 0) break;
      v.side = side;
      bool valid = true;
      for (std::uint32_t l = 0; l < b_.centers.size() && valid; ++l)
        if (l != i && l != j && l != k) valid = power_sign_at(v, l) >= 0;
      if (!valid) continue;
      if (v.rational) {
        v.point = v.z + mpq_class(side * make_rational(sn, sd)) * n;
        if (interior_of_union(b_, v.point)) continue;
      }
      r.exact = v.coordinates(*table_);
      for (int m = 0; m < 3; ++m) r.approx[m] = r.exact[m].approx();
      out.push_back(r);
    }
    return out;
  }

  bool on_sphere(const RefVertex& r, std::uint32_t i) const {
    const BoundaryVertex& v = r.v;
    if (std::find(v.balls.begin(), v.balls.end(), i) != v.balls.end()) return true;
    return v.rational ? sgn(power(b_, i, v.point)) == 0 : power_sign_at(v, i) == 0;
  }

  // Circles of intersecting spheres; `nonempty`: some point of the circle is on the boundary.
  void find_circles() {
    const auto n = static_cast<std::uint32_t>(b_.centers.size());
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j) {
        Circle c{i, j, {}, b_.centers[j] - b_.centers[i], 0};
        const mpq_class m2 = dot(c.m, c.m);
        if (sgn(m2) == 0) continue;
        const mpq_class lambda = (m2 + b_.squared_radii[i] - b_.squared_radii[j]) / (2 * m2);
        c.o = b_.centers[i] + lambda * c.m;
        c.alpha = -power(b_, i, c.o);
        if (sgn(c.alpha) <= 0) continue;
        for (const RefVertex& v : vertices_) c.nonempty |= on_sphere(v, i) && on_sphere(v, j);
        if (!c.nonempty) c.nonempty = circle_point_free(c);
        circles_.push_back(c);
      }
  }

  // A circle without boundary vertices is wholly free or wholly covered, except for
  // degenerate points on further spheres; so test points in a few directions and call the
  // circle free when one lies strictly outside every other ball.
  bool circle_point_free(const Circle& c) const {
    for (const ExactPoint3& d : {ExactPoint3{1, 0, 0}, ExactPoint3{0, 1, 0}, ExactPoint3{1, 2, 3}, ExactPoint3{3, -1, 2}}) {
      const ExactPoint3 e = cross(c.m, d);
      if (is_zero(e)) continue;
      const mpq_class s = c.alpha / dot(e, e);  // y = o + sqrt(s) e
      bool outside = true;
      for (std::uint32_t l = 0; l < b_.centers.size() && outside; ++l)
        outside = l == c.i || l == c.j ||
                  sign_with_root(power(b_, l, c.o) + s * dot(e, e), 1, 2 * dot(e, c.o - b_.centers[l]), s) > 0;
      if (outside) return true;
    }
    return false;
  }

  void find_patches() {
    for (std::uint32_t i = 0; i < b_.centers.size(); ++i) {
      bool free = false;
      for (const RefVertex& v : vertices_) free |= on_sphere(v, i);
      for (const Circle& c : circles_) free |= c.nonempty && (c.i == i || c.j == i);
      // No vertex, no free circle: a whole free sphere (up to tangency points) or none.
      const mpq_class& w = b_.squared_radii[i];
      for (const ExactPoint3& d : {ExactPoint3{1, 0, 0}, ExactPoint3{0, 1, 0}, ExactPoint3{1, 2, 3}, ExactPoint3{3, -1, 2}}) {
        if (free) break;
        const mpq_class s = w / dot(d, d);  // y = c_i + sqrt(s) d
        free = true;
        for (std::uint32_t l = 0; l < b_.centers.size() && free; ++l)
          free = l == i || sign_with_root(power(b_, l, b_.centers[i]) + w, 1, 2 * dot(d, b_.centers[i] - b_.centers[l]), s) > 0;
      }
      patch_.push_back(free);
    }
  }

  std::string check_circle(const HomogeneousPoint& x, const Box& xa, const RadicalNumber& sqw, const RadicalNumber& d2,
                           const Interval& r2, const Circle& c) {
    // Filter: d^2 = |q|^2 + alpha - 2 sqrt(alpha) rho with q = x - o, rho the distance to the axis.
    const Box ob{enclose(c.o.x), enclose(c.o.y), enclose(c.o.z)};
    const Box mb{enclose(c.m.x), enclose(c.m.y), enclose(c.m.z)};
    const Interval q2 = sqdist(xa, ob), m2 = enclose(dot(c.m, c.m));
    Interval qm(0.0);
    for (int k = 0; k < 3; ++k) qm += (xa[k] - ob[k]) * mb[k];
    Interval rho2 = q2 - square(qm) / m2;
    rho2.lo = std::max(rho2.lo, 0.0);
    rho2.hi = std::max(rho2.hi, 0.0);
    const Interval a = sqrt(enclose(c.alpha));
    if ((q2 + enclose(c.alpha) - Interval(2) * a * sqrt(rho2)).lo > r2.hi) return "";
    const RadicalNumber Q2 = dist2(x, c.o), Qm = dot_with(x, c.o, c.m);
    const mpq_class inv_m2 = 1 / dot(c.m, c.m);
    const RadicalNumber P = Q2 - Qm * Qm * inv_m2;  // W^2 rho^2
    const RadicalNumber g = Q2 + sqw * c.alpha - d2;
    if (sign(P, &stats_) == 0) {  // on the axis: every point of the circle is at the same distance
      if (!c.nonempty) return "";
      const int s = sign(g, &stats_);
      if (s < 0) return "a boundary circle is closer than R";
      if (s == 0) nearest_ += 2;
      return "";
    }
    bool on_vertex = false;
    for (std::uint32_t l = 0; l < b_.centers.size(); ++l) {
      if (l == c.i || l == c.j) continue;
      const ExactPoint3 ol = c.o - b_.centers[l];
      const mpq_class al = power(b_, l, c.o) + c.alpha;
      const RadicalNumber bl = (dot_with(x, c.o, ol) - Qm * (dot(c.m, ol) * inv_m2)) * mpq_class(2 * x.w_sign);
      const int s = sign_two_roots(RadicalNumber(al), P, bl, RadicalNumber(c.alpha), &stats_);
      if (s < 0) return "";  // the nearest point of the circle is inside another ball
      on_vertex |= s == 0;
    }
    // On a third sphere the point is a vertex candidate, decided there (it may also be an
    // interior point that the balls through it surround).
    if (on_vertex) return "";
    const int s = sign_plus_root(g, RadicalNumber(-2), P * c.alpha, &stats_);
    if (s < 0) return "a boundary arc is closer than R";
    if (s == 0) ++nearest_;
    return "";
  }

  std::string check_sphere(const HomogeneousPoint& x, const Box& xa, const RadicalNumber& sqw, const RadicalNumber& d2,
                           const Interval& r2, std::uint32_t i) {
    const Interval e2 = sqdist(xa, centre_[i]);
    if ((e2 - enclose(b_.squared_radii[i])).lo > 0) return "";  // x outside B_i: not a nearest sphere
    const Interval d = root_[i] - sqrt(e2);
    if (d.lo > 0 && square(d).lo > r2.hi) return "";
    const RadicalNumber E = dist2(x, b_.centers[i]);
    const RadicalNumber wi = sqw * b_.squared_radii[i];
    if (sign(E - wi, &stats_) >= 0) return "";
    if (sign(E, &stats_) == 0) {  // x = c_i: the whole free part of the sphere at distance r_i
      const int s = sign(wi - d2, &stats_);
      if (s < 0 && patch_[i]) return "a boundary sphere patch is closer than R";
      if (s == 0 && patch_[i]) nearest_ += 2;
      return "";
    }
    bool on_circle = false;
    for (std::uint32_t l = 0; l < b_.centers.size(); ++l) {
      if (l == i) continue;
      const ExactPoint3 cl = b_.centers[i] - b_.centers[l];
      const mpq_class al = dot(cl, cl) + b_.squared_radii[i] - b_.squared_radii[l];
      const RadicalNumber bl = dot_with(x, b_.centers[i], cl) * mpq_class(2 * x.w_sign);
      const int s = sign_two_roots(RadicalNumber(al), E, bl, RadicalNumber(b_.squared_radii[i]), &stats_);
      if (s < 0) return "";  // the radial point is inside another ball
      on_circle |= s == 0;
    }
    if (on_circle) return "";  // a circle or vertex candidate, decided there
    const int s = sign_plus_root(wi + E - d2, RadicalNumber(-2), wi * E, &stats_);
    if (s < 0) return "a boundary sphere point is closer than R";
    if (s == 0) ++nearest_;
    return "";
  }

  const BallSet& b_;
  RadicalTable* table_;
  std::vector<Box> centre_;
  std::vector<Interval> root_;
  std::vector<RefVertex> vertices_;
  std::vector<Circle> circles_;
  std::vector<bool> patch_;
  int nearest_ = 0;
};

// The balls without exact repetitions (a repeated ball changes nothing in the union, but
// its sphere would hide every point of the original's from "outside every other ball").
BallSet distinct_balls(const BallSet& b) {
  BallSet out;
  out.source = b.source;
  std::set<std::array<mpq_class, 4>> seen;
  for (std::size_t i = 0; i < b.centers.size(); ++i)
    if (seen.insert({b.centers[i].x, b.centers[i].y, b.centers[i].z, b.squared_radii[i]}).second) {
      out.centers.push_back(b.centers[i]);
      out.squared_radii.push_back(b.squared_radii[i]);
    }
  return out;
}

void fail(DefinitionCheck* c, const std::string& what) {
  if (c->failures++ == 0) c->first_failure = what;
}

}  // namespace

bool same_boundary_vertices(const BallSet& balls, const UnionOfBallsAxis& axis, std::string* why) {
  const BallSet distinct = distinct_balls(balls);
  Reference ref(distinct, axis.radicals.get());
  auto key_less = [](const std::array<ExactPoint3, 3>& x, const std::array<ExactPoint3, 3>& y) {
    for (int i = 0; i < 3; ++i)
      if (int c = compare_lex(x[i], y[i])) return c < 0;
    return false;
  };
  std::set<std::array<ExactPoint3, 3>, decltype(key_less)> mine(key_less), theirs(key_less);
  for (const RefVertex& v : ref.vertices()) mine.insert(boundary_vertex_key(v.v));
  for (const BoundaryVertex& v : axis.boundary) theirs.insert(boundary_vertex_key(v));
  if (mine.size() == theirs.size() && std::equal(mine.begin(), mine.end(), theirs.begin(),
                                                 [&](const auto& x, const auto& y) { return !key_less(x, y) && !key_less(y, x); }))
    return true;
  *why = "brute force finds " + std::to_string(mine.size()) + " boundary vertices, the builder " + std::to_string(theirs.size());
  return false;
}

DefinitionCheck check_union_axis(const BallSet& balls, const UnionOfBallsAxis& axis) {
  DefinitionCheck c;
  std::string why;
  if (!same_boundary_vertices(balls, axis, &why)) fail(&c, why);
  const BallSet distinct = distinct_balls(balls);
  Reference ref(distinct, axis.radicals.get());
  auto claimed_by_vertex = [&](const HomogeneousPoint& x, std::size_t v) {
    const auto p = axis.boundary[v].coordinates(*axis.radicals);
    RadicalNumber s;
    for (int k = 0; k < 3; ++k) {
      const RadicalNumber d = x.c[k] - x.c[3] * p[k];
      s += d * d;
    }
    return s;
  };
  auto claimed_by_simplex = [&](const HomogeneousPoint& x, const PowerSimplex& p) {
    RadicalNumber s;
    const mpq_class* z[3] = {&p.centre.x, &p.centre.y, &p.centre.z};
    for (int k = 0; k < 3; ++k) {
      const RadicalNumber d = x.c[k] - x.c[3] * *z[k];
      s += d * d;
    }
    return s - x.c[3] * x.c[3] * p.power;
  };
  for (std::size_t v = 0; v < axis.vertex_info.size(); ++v) {
    const AxisVertexInfo& info = axis.vertex_info[v];
    if (info.nearest < 0 && info.simplex < 0) continue;
    ++c.points;
    const HomogeneousPoint& x = info.point->exact();
    const RadicalNumber d2 = info.nearest >= 0 ? claimed_by_vertex(x, static_cast<std::size_t>(info.nearest))
                                               : claimed_by_simplex(x, axis.singular[static_cast<std::size_t>(info.simplex)]);
    const std::string why_not = ref.check(x, d2);
    if (!why_not.empty()) fail(&c, "vertex " + std::to_string(v) + ": " + why_not);
  }
  for (const UnionAxisPolygonSample& s : axis.samples) {
    ++c.points;
    const std::string why_not = ref.check(*s.point, claimed_by_vertex(*s.point, s.v));
    if (!why_not.empty()) fail(&c, "polygon sample: " + why_not);
  }
  for (const PowerSimplex& p : axis.singular) {
    ExactPoint3 g{0, 0, 0};
    for (int i = 0; i <= p.dim; ++i) g = g + balls.centers[p.balls[i]];
    g = make_rational(1, p.dim + 1) * g;
    auto h = std::make_shared<HomogeneousPoint>();
    h->c = {RadicalNumber(g.x), RadicalNumber(g.y), RadicalNumber(g.z), RadicalNumber(1)};
    ++c.points;
    const std::string why_not = ref.check(*h, claimed_by_simplex(*h, p));
    if (!why_not.empty()) fail(&c, "centroid of a singular simplex: " + why_not);
  }
  return c;
}

}  // namespace grassfire
