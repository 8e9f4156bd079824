// union_of_balls_axis.cpp -- see union_of_balls_axis.h.
#include "medial3/balls/union_of_balls_axis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

#include "medial3/balls/union_tet_axis.h"
#include "geometry3/exact_predicates3.h"
#include "support/cpu_clock.h"
#include "number/simplest_rational.h"

namespace grassfire {

namespace {

using Clock = std::chrono::steady_clock;


// An output value from a certified enclosure: a simple rational inside it when `is_value`
// confirms it exactly, else the midpoint with its error; `precise` when the enclosure is
// too wide to be useful (ill-conditioned points).
mpq_class output_value(const Interval& iv, const std::function<bool(const mpq_class&)>& is_value,
                       const std::function<mpq_class(double*)>& precise, bool reference, bool* exact, double* error) {
  *exact = false;
  const double scale = std::max({1.0, std::fabs(iv.lo), std::fabs(iv.hi)});
  if (iv.hi - iv.lo > 1e-9 * scale) return precise(error);
  // A real number's enclosure of width w holds a rational of denominator <= d with
  // probability about d^2 w; with d^2 w <= 1e-4 a false candidate (costing one exact test)
  // is rare, and symmetric configurations, whose values have small denominators, pass.
  const double width = std::max(iv.hi - iv.lo, 1e-300);
  const auto max_bits = static_cast<long>(std::floor(std::log2(std::sqrt(1e-4 / width))));
  const auto bits = static_cast<std::size_t>(max_bits);
  if (const auto q = max_bits < 1 ? std::nullopt
                     : reference  ? simplest_rational_reference(mpq_class(iv.lo), mpq_class(iv.hi), bits)
                                  : simplest_rational(iv.lo, iv.hi, bits);
      q && is_value(*q)) {
    *exact = true;
    *error = 0;
    return *q;
  }
  *error = iv.radius();
  return mpq_class(iv.mid());
}

class Assembler {
 public:
  Assembler(const BallSet& balls, const AlphaComplex& k, UnionOfBallsAxis* out, bool samples, bool reference)
      : balls_(balls), k_(k), out_(out), samples_(samples), reference_(reference) {
    for (std::size_t v = 0; v < out->boundary.size(); ++v) {
      const auto& bv = out->boundary[v];
      if (bv.side > 0 || !mirror_.count(bv.balls)) mirror_[bv.balls] = v;
    }
  }

  void add_tet_axis(TetAxis&& t) {
    for (TetAxisVertex& v : t.vertices) {
      if (v.feature.size() == 1) v.point = std::make_shared<LazyPoint3>(balls_.centers[v.feature[0]]);
      const auto id = new_vertex(v.point, static_cast<std::int64_t>(v.nearest), -1);
      if (v.feature.size() == 1) ball_vertex_[v.feature[0]] = id;
      if (v.feature.size() == 2) edge_points_[{v.feature[0], v.feature[1]}].push_back(id);
    }
    for (const TetAxisPolygon& p : t.polygons) {
      fan(p.vertices, p.v);
      if (samples_) add_sample(p);
    }
    out_->tet_polygons = t.polygons.size();
  }

  void add_singular_simplices() {
    for (std::uint32_t s = 0; s < k_.simplices().size(); ++s) {
      if (!k_.is_singular(s)) continue;
      const PowerSimplex& p = k_.exact(s);
      ++out_->singular_simplices[p.dim];
      const auto index = static_cast<std::uint32_t>(out_->singular.size());
      out_->singular.push_back(p);
      std::vector<std::uint32_t> corner;
      for (int i = 0; i <= p.dim; ++i) corner.push_back(ball_vertex(p.balls[i], index));
      if (p.dim == 1) out_->complex.segments.push_back({corner[0], corner[1]});
      if (p.dim == 2) singular_triangle(p, index, corner);
    }
  }

  void finish() {
    for (std::size_t v = 0; v < records_.size(); ++v) finish_vertex(v);
    add_border_rules();
  }

 private:
  struct Record {
    std::shared_ptr<const LazyPoint3> point;
    std::int64_t nearest, simplex;
  };

  std::uint32_t new_vertex(std::shared_ptr<const LazyPoint3> p, std::int64_t nearest, std::int64_t simplex) {
    records_.push_back({std::move(p), nearest, simplex});
    return static_cast<std::uint32_t>(records_.size() - 1);
  }

  static std::shared_ptr<const LazyPoint3> rational_point(const ExactPoint3& x) { return std::make_shared<LazyPoint3>(x); }

  std::uint32_t ball_vertex(std::uint32_t ball, std::uint32_t simplex) {
    auto it = ball_vertex_.find(ball);
    if (it == ball_vertex_.end()) it = ball_vertex_.emplace(ball, new_vertex(rational_point(balls_.centers[ball]), -1, simplex)).first;
    if (records_[it->second].simplex < 0) records_[it->second].simplex = simplex;
    return it->second;
  }

  void fan(const std::vector<std::uint32_t>& ring, std::int64_t nearest) {
    for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
      out_->complex.triangles.push_back({ring[0], ring[k], ring[k + 1]});
      triangle_nearest_.push_back(nearest);
    }
  }

  // Parameter of a point along the line c_a -> c_b, as an exact comparison key.
  bool before(std::uint32_t x, std::uint32_t y, const ExactPoint3& a, const ExactPoint3& d) {
    const HomogeneousPoint& p = records_[x].point->exact();
    const HomogeneousPoint& q = records_[y].point->exact();
    // t_p < t_q  <=>  ((X_p - W_p a) . d) W_q - ((X_q - W_q a) . d) W_p < 0 when W_p W_q > 0.
    auto along = [&](const HomogeneousPoint& h) {
      return (h.c[0] - h.c[3] * a.x) * d.x + (h.c[1] - h.c[3] * a.y) * d.y + (h.c[2] - h.c[3] * a.z) * d.z;
    };
    return sign(along(p) * q.c[3] - along(q) * p.c[3]) * p.w_sign * q.w_sign < 0;
  }

  // The triangle of three centres; axis vertices of adjacent tetrahedra on its edges are
  // inserted, and then it is fanned from its (rational) centroid.
  void singular_triangle(const PowerSimplex& p, std::uint32_t s, const std::vector<std::uint32_t>& corner) {
    std::vector<std::uint32_t> ring;
    bool extra = false;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = p.balls[e], b = p.balls[(e + 1) % 3];
      ring.push_back(corner[e]);
      auto it = edge_points_.find({std::min(a, b), std::max(a, b)});
      if (it == edge_points_.end()) continue;
      std::vector<std::uint32_t> pts = it->second;
      const ExactPoint3& ca = balls_.centers[a];
      const ExactPoint3 d = balls_.centers[b] - ca;
      std::sort(pts.begin(), pts.end(), [&](std::uint32_t x, std::uint32_t y) { return before(x, y, ca, d); });
      ring.insert(ring.end(), pts.begin(), pts.end());
      extra |= !pts.empty();
    }
    const std::int64_t nearest = mirror_.count({p.balls[0], p.balls[1], p.balls[2]})
                                     ? static_cast<std::int64_t>(mirror_.at({p.balls[0], p.balls[1], p.balls[2]}))
                                     : -1;
    if (!extra) {
      fan(ring, nearest);
      return;
    }
    const ExactPoint3 g = make_rational(1, 3) * (balls_.centers[p.balls[0]] + balls_.centers[p.balls[1]] + balls_.centers[p.balls[2]]);
    const std::uint32_t c = new_vertex(rational_point(g), -1, s);
    for (std::size_t k = 0; k < ring.size(); ++k) {
      out_->complex.triangles.push_back({c, ring[k], ring[(k + 1) % ring.size()]});
      triangle_nearest_.push_back(nearest);
    }
  }

  void add_sample(const TetAxisPolygon& p) {
    // A rational point near the centroid, moved along the axis of largest normal component
    // onto the bisector plane: it lies on the plane exactly (2 radicals at most).
    std::array<double, 3> c{0, 0, 0};
    for (std::uint32_t v : p.vertices)
      for (int k = 0; k < 3; ++k) c[k] += records_[v].point->approx()[k].mid() / static_cast<double>(p.vertices.size());
    const CellPlane::Coefficients& plane = p.plane->coef();
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (plane[k].approx().mid() * plane[k].approx().mid() > plane[axis].approx().mid() * plane[axis].approx().mid()) axis = k;
    const ExactPoint3 q{mpq_class(c[0]), mpq_class(c[1]), mpq_class(c[2])};
    const RadicalNumber value = plane[0] * q.x + plane[1] * q.y + plane[2] * q.z + plane[3];
    auto h = std::make_shared<HomogeneousPoint>();
    const mpq_class* qc[3] = {&q.x, &q.y, &q.z};
    for (int k = 0; k < 3; ++k) h->c[k] = plane[axis] * *qc[k] - (k == axis ? value : RadicalNumber(0));
    h->c[3] = plane[axis];
    h->w_sign = sign(h->c[3]);
    if (h->w_sign == 0) return;
    out_->samples.push_back({h, p.v, p.u});
  }

  void finish_vertex(std::size_t v) {
    const Record& r = records_[v];
    AxisVertexInfo info;
    info.point = r.point;
    info.nearest = r.nearest;
    info.simplex = r.simplex;
    std::array<mpq_class, 3> x;
    mpq_class r2;
    if (const ExactPoint3* p = r.point->rational()) {
      x = {p->x, p->y, p->z};
      info.exact = rational_radius(*p, r, &r2);
    } else {
      info.exact = approximate(r, &x, &r2);
    }
    out_->complex.vertices.push_back({x[0], x[1], x[2]});
    out_->complex.radius_squared.push_back(sgn(r2) < 0 ? mpq_class(0) : r2);
    out_->vertex_info.push_back(std::move(info));
  }

  // R^2 at a rational point: |x - z|^2 - w on a singular simplex (power centre z, power w),
  // else |x - v|^2 for the nearest boundary vertex v = z' + sqrt(s) n (rational unless the
  // point lies off the plane of v's triangle).
  bool rational_radius(const ExactPoint3& p, const Record& r, mpq_class* r2) {
    if (r.simplex >= 0) {
      const PowerSimplex& s = out_->singular[static_cast<std::size_t>(r.simplex)];
      *r2 = squared_distance(p, s.centre) - s.power;
      return true;
    }
    const auto c = out_->boundary[static_cast<std::size_t>(r.nearest)].coordinates(*out_->radicals);
    const RadicalNumber dx = c[0] - p.x, dy = c[1] - p.y, dz = c[2] - p.z;
    const RadicalNumber d2 = dx * dx + dy * dy + dz * dz;
    if (d2.rational_value(r2)) return true;
    double err = 0;
    *r2 = approximate_quotient(d2, RadicalNumber(1), 64, &err);
    out_->radius_squared_error = std::max(out_->radius_squared_error, err);
    return false;
  }

  // Coordinates and R^2 of an irrational vertex from the enclosures.
  bool approximate(const Record& r, std::array<mpq_class, 3>* x, mpq_class* r2) {
    const LazyPoint3& p = *r.point;
    const std::uint32_t v = static_cast<std::uint32_t>(r.nearest);
    bool all_exact = true;
    for (int k = 0; k < 3; ++k) {
      bool e = false;
      double err = 0;
      (*x)[k] = output_value(
          p.approx()[k], [&](const mpq_class& q) { return sign(p.exact().c[k] - p.exact().c[3] * q) == 0; },
          [&](double* error) { return approximate_quotient(p.exact().c[k], p.exact().c[3], 64, error); }, reference_, &e,
          &err);
      all_exact &= e;
      out_->coordinate_error = std::max(out_->coordinate_error, err);
    }
    const BoundaryVertex& b = out_->boundary[v];
    Interval d2(0.0);
    for (int k = 0; k < 3; ++k) d2 += square(p.approx()[k] - b.approx[k]);
    auto exact_d2 = [&]() {  // (W^2 |x - v|^2, W^2)
      const HomogeneousPoint& h = p.exact();
      const auto c = b.coordinates(*out_->radicals);
      RadicalNumber s;
      for (int k = 0; k < 3; ++k) {
        const RadicalNumber d = h.c[k] - h.c[3] * c[k];
        s += d * d;
      }
      return std::make_pair(s, h.c[3] * h.c[3]);
    };
    bool e = false;
    double err = 0;
    *r2 = output_value(
        d2,
        [&](const mpq_class& q) {
          const auto [num, den] = exact_d2();
          return sign(num - den * q) == 0;
        },
        [&](double* error) {
          const auto [num, den] = exact_d2();
          return approximate_quotient(num, den, 64, error);
        },
        reference_, &e, &err);
    out_->radius_squared_error = std::max(out_->radius_squared_error, err);
    return all_exact && e;
  }

  // R(x) = |x - p| along a border edge, p the nearest boundary vertex of its triangle.
  void add_border_rules() {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edge_triangles;
    const auto& tris = out_->complex.triangles;
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int k = 0; k < 3; ++k)
        edge_triangles[{std::min(tris[t][k], tris[t][(k + 1) % 3]), std::max(tris[t][k], tris[t][(k + 1) % 3])}].push_back(t);
    for (const auto& [e, ts] : edge_triangles) {
      if (ts.size() != 1 || triangle_nearest_[ts[0]] < 0) continue;
      const BoundaryVertex& b = out_->boundary[static_cast<std::size_t>(triangle_nearest_[ts[0]])];
      BorderIgnition rule;
      rule.edge = {e.first, e.second};
      rule.rule = IgnitionRule::DistanceToPoint;
      if (b.rational) {
        rule.point = b.point;
      } else {
        mpq_class* p[3] = {&rule.point.x, &rule.point.y, &rule.point.z};
        for (int k = 0; k < 3; ++k) {
          *p[k] = mpq_class(b.approx[k].mid());
          out_->rule_point_error = std::max(out_->rule_point_error, b.approx[k].radius());
        }
      }
      out_->complex.border_rules.push_back(rule);
    }
  }

  const BallSet& balls_;
  const AlphaComplex& k_;
  UnionOfBallsAxis* out_;
  bool samples_, reference_;
  std::vector<Record> records_;
  std::map<std::uint32_t, std::uint32_t> ball_vertex_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edge_points_;
  std::map<std::array<std::uint32_t, 3>, std::size_t> mirror_;
  std::vector<std::int64_t> triangle_nearest_;
};

BettiNumbers alpha_complex_betti(const AlphaComplex& k) {
  std::map<std::uint32_t, std::uint32_t> id;
  for (std::uint32_t s : k.of_dimension(0))
    if (k.in_complex(s)) id.emplace(k.simplices()[s].balls[0], static_cast<std::uint32_t>(id.size()));
  std::vector<std::array<std::uint32_t, 2>> e;
  std::vector<std::array<std::uint32_t, 3>> t;
  std::vector<std::array<std::uint32_t, 4>> h;
  for (std::uint32_t s = 0; s < k.simplices().size(); ++s) {
    if (!k.in_complex(s)) continue;
    const PowerSimplex& p = k.simplices()[s];
    if (p.dim == 1) e.push_back({id.at(p.balls[0]), id.at(p.balls[1])});
    if (p.dim == 2) t.push_back({id.at(p.balls[0]), id.at(p.balls[1]), id.at(p.balls[2])});
    if (p.dim == 3) h.push_back({id.at(p.balls[0]), id.at(p.balls[1]), id.at(p.balls[2]), id.at(p.balls[3])});
  }
  return betti_numbers(id.size(), e, t, h);
}

}  // namespace

void require_valid_balls(const BallSet& balls) {
  if (balls.centers.empty()) throw std::invalid_argument(balls.source + ": no balls");
  if (balls.squared_radii.size() != balls.centers.size())
    throw std::invalid_argument(balls.source + ": centres and radii differ in number");
  for (std::size_t i = 0; i < balls.squared_radii.size(); ++i)
    if (sgn(balls.squared_radii[i]) <= 0)
      throw std::invalid_argument(balls.source + ": ball " + std::to_string(i) + " has a non-positive squared radius");
}

UnionOfBallsAxis union_of_balls_axis(const BallSet& balls, const UnionOfBallsOptions& options) {
  require_valid_balls(balls);
  const auto start = Clock::now();
  UnionOfBallsAxis out;
  double stage_start = cpu_seconds();
  auto stage = [&](const char* name) {
    const double now = cpu_seconds();
    out.stage_seconds.emplace_back(name, now - stage_start);
    stage_start = now;
  };
  out.complex.source = balls.source + " (union-of-balls medial axis)";
  const RegularTriangulation rt = regular_triangulation(balls);
  out.triangulation_seconds = wall_seconds_since(start);
  stage("regular triangulation");
  const AlphaComplex k(balls, rt);
  stage("alpha complex (classification)");
  out.balls = balls.centers.size();
  out.hidden_balls = k.hidden_balls();
  out.triangulation_dimension = k.dimension();
  for (std::uint32_t s = 0; s < k.simplices().size(); ++s)
    if (k.in_complex(s)) ++out.alpha_simplices[k.simplices()[s].dim];
  out.union_betti = alpha_complex_betti(k);
  stage("betti numbers");
  out.radicals = std::make_shared<RadicalTable>();
  out.boundary = boundary_vertices(balls, k, out.radicals.get(), !options.reference);
  stage("boundary vertices");
  TetAxis tets = tet_axis(balls, k, out.boundary, *out.radicals, !options.reference);
  stage("voronoi cells in tetrahedra");
  out.stats = tets.stats;
  out.tetrahedra_candidates = tets.candidates;
  out.voronoi_cells = tets.cells_clipped;
  out.clips = tets.clips;
  out.beyond_reach = tets.beyond_reach;
  out.merged_by_position = tets.merged_by_position;
  out.key_collisions = tets.key_collisions;
  Assembler a(balls, k, &out, options.polygon_samples, options.reference);
  a.add_tet_axis(std::move(tets));
  a.add_singular_simplices();
  stage("assembly");
  a.finish();
  stage("output values and border rules");
  out.total_seconds = wall_seconds_since(start);
  return out;
}

}  // namespace grassfire
