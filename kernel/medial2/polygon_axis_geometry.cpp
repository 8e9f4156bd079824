// polygon_axis_geometry.cpp -- see polygon_axis_geometry.h.
#include "medial2/polygon_axis_geometry.h"

#include <algorithm>
#include <cmath>

#include "medial2/polygon_axis_symmetry.h"
#include "number/mpfr_bounds.h"
#include "number/parabolic_arc.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

Interval abs_of(const Interval& a) {
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return -a;
  return {0.0, std::fmax(-a.lo, a.hi)};
}
Ball abs_of(const Ball& a) {
  Ball r;
  arb_abs(r.get(), a.get());
  return r;
}

template <class T>
T length_of(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<T>& a, const CircleValue<T>& b) {
  if (!e.parabolic) {
    const T dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy);
  }
  const std::uint32_t focus = s.is_point(e.site_a) ? e.site_a : e.site_b;
  const std::uint32_t line = s.is_point(e.site_a) ? e.site_b : e.site_a;
  const Point2 f = s.vertex[focus], la = s.vertex[s.seg_start(line)], lb = s.vertex[s.seg_end(line)];
  const T fx(f.x), fy(f.y);
  const T dx = T(lb.x) - T(la.x), dy = T(lb.y) - T(la.y);
  const T len = sqrt(dx * dx + dy * dy);
  // Focal parameter: the distance from the focus to the directrix (left side positive).
  const T p = (dx * (fy - T(la.y)) - dy * (fx - T(la.x))) / len;
  const T xa = (dx * (a.x - fx) + dy * (a.y - fy)) / len;
  const T xb = (dx * (b.x - fx) + dy * (b.y - fy)) / len;
  return abs_of(parabola_arc_primitive(xb, p) - parabola_arc_primitive(xa, p));
}

// Evaluates f() in Arb at increasing precision until it is accurate to `bits` bits; the
// last ball is kept, since the burning engine asks for the same constants repeatedly.
struct BallCache {
  Ball value;
  long accuracy = -1;
};
template <class F>
void enclose_with_ball(long bits, mpfr_ptr lo, mpfr_ptr hi, BallCache& cache, F&& f) {
  if (cache.accuracy < bits) {
    for (long work = bits + 64;; work *= 2) {
      BallPrecision guard(work);
      cache.value = f();
      cache.accuracy = cache.value.accuracy_bits();
      if (cache.accuracy >= bits || work > 16 * (bits + 64)) break;
    }
  }
  cache.value.to_mpfr(lo, hi);
}

class CircleRadius : public CertifiedConstant {
 public:
  CircleRadius(std::shared_ptr<const PolygonSites> s, VoronoiCircle c, std::string id)
      : sites_(std::move(s)), circle_(c), id_(std::move(id)) {}
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
    enclose_with_ball(mpfr_get_prec(lo), lo, hi, cache_, [&] { return solve_ball(*sites_, circle_).r; });
  }
  std::string identity() const override { return id_; }

 private:
  std::shared_ptr<const PolygonSites> sites_;
  VoronoiCircle circle_;
  std::string id_;
  mutable BallCache cache_;
};

class EdgeLength : public CertifiedConstant {
 public:
  EdgeLength(std::shared_ptr<const PolygonSites> s, AxisEdgeData e, VoronoiCircle a, VoronoiCircle b, std::string id)
      : sites_(std::move(s)), edge_(e), a_(a), b_(b), id_(std::move(id)) {}
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
    enclose_with_ball(mpfr_get_prec(lo), lo, hi, cache_, [&] {
      return length_of(*sites_, edge_, solve_ball(*sites_, a_), solve_ball(*sites_, b_));
    });
  }
  std::string identity() const override { return id_; }

 private:
  std::shared_ptr<const PolygonSites> sites_;
  AxisEdgeData edge_;
  VoronoiCircle a_, b_;
  std::string id_;
  mutable BallCache cache_;
};

// sqrt(x) for an exact sum x >= 0 that does not denest.
class SqrtOfSum : public CertifiedConstant {
 public:
  // The identity is built once: ExactSum::simplify asks for it on every merge.
  explicit SqrtOfSum(ExactSum x) : x_(std::move(x)), id_("sqrt[" + to_string(x_) + "]") {}
  void enclose(mpfr_ptr lo, mpfr_ptr hi) const override {
    x_.enclose(lo, hi);
    if (mpfr_sgn(lo) < 0) mpfr_set_zero(lo, 1);
    mpfr_sqrt(lo, lo, MPFR_RNDD);
    mpfr_sqrt(hi, hi, MPFR_RNDU);
  }
  std::string identity() const override { return id_; }

 private:
  ExactSum x_;
  std::string id_;
};

}  // namespace

Interval edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Interval>& a,
                     const CircleValue<Interval>& b) {
  return length_of(s, e, a, b);
}
Ball edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Ball>& a,
                 const CircleValue<Ball>& b) {
  return length_of(s, e, a, b);
}

PolygonAxisGeometry::PolygonAxisGeometry(std::shared_ptr<const PolygonSites> sites, mpq_class to_input,
                                         std::vector<AxisNodeData> nodes, std::vector<AxisEdgeData> edges)
    : sites_(std::move(sites)),
      to_input_(std::move(to_input)),
      nodes_(std::move(nodes)),
      edges_(std::move(edges)),
      circle_done_(nodes_.size(), 0),
      circles_(nodes_.size()),
      lengths_(edges_.size()),
      ball_circles_(nodes_.size()) {}

const AxisValueClasses& PolygonAxisGeometry::value_classes() const {
  if (!classes_) classes_ = std::make_shared<const AxisValueClasses>(axis_value_classes(*sites_, nodes_, edges_));
  return *classes_;
}

std::uint32_t PolygonAxisGeometry::radius_class(std::uint32_t node) const { return value_classes().node[node]; }
std::uint32_t PolygonAxisGeometry::length_class(std::uint32_t edge) const { return value_classes().edge[edge]; }
std::uint32_t PolygonAxisGeometry::joined_length_class(std::uint32_t first, std::uint32_t second) const {
  const AxisValueClasses& c = value_classes();
  const auto it = c.joined.find(joined_key(first, second));
  return it == c.joined.end() ? 0xffffffffu : it->second;
}

const CircleValue<Ball>& PolygonAxisGeometry::ball_circle(std::uint32_t i) const {
  if (!ball_circles_[i]) {
    BallPrecision guard(kBallBits);
    ball_circles_[i] = solve_ball(*sites_, nodes_[i].circle);
  }
  return *ball_circles_[i];
}

Ball PolygonAxisGeometry::ball_length(std::uint32_t edge) const {
  const AxisEdgeData& e = edges_[edge];
  BallPrecision guard(kBallBits);
  return edge_length(*sites_, e, ball_circle(e.u), ball_circle(e.v));
}

void PolygonAxisGeometry::scaled_to_input(const Ball& frame_value, mpfr_ptr lo, mpfr_ptr hi) const {
  frame_value.to_mpfr(lo, hi);  // to_input > 0: multiplying keeps the order
  mpfr_mul_q(lo, lo, to_input_.get_mpq_t(), MPFR_RNDD);
  mpfr_mul_q(hi, hi, to_input_.get_mpq_t(), MPFR_RNDU);
}

void PolygonAxisGeometry::enclose_radius(std::uint32_t node, mpfr_ptr lo, mpfr_ptr hi) const {
  if (mpfr_get_prec(lo) > 128 || mpfr_get_prec(hi) > 128) return MedialGeometry::enclose_radius(node, lo, hi);
  scaled_to_input(ball_circle(node).r, lo, hi);
}

void PolygonAxisGeometry::enclose_length(std::uint32_t edge, mpfr_ptr lo, mpfr_ptr hi) const {
  if (mpfr_get_prec(lo) > 128 || mpfr_get_prec(hi) > 128) return MedialGeometry::enclose_length(edge, lo, hi);
  scaled_to_input(ball_length(edge), lo, hi);
}

LongInterval PolygonAxisGeometry::enclose_radius_long(std::uint32_t node) const {
  MpfrBounds b(80);
  enclose_radius(node, b.lo, b.hi);
  return {mpfr_get_ld(b.lo, MPFR_RNDD), mpfr_get_ld(b.hi, MPFR_RNDU)};
}

LongInterval PolygonAxisGeometry::enclose_length_long(std::uint32_t edge) const {
  MpfrBounds b(80);
  enclose_length(edge, b.lo, b.hi);
  return {mpfr_get_ld(b.lo, MPFR_RNDD), mpfr_get_ld(b.hi, MPFR_RNDU)};
}

std::string PolygonAxisGeometry::node_identity(std::uint32_t i) const {
  std::string id = "vertex{";
  for (std::uint32_t s : nodes_[i].sites) id += std::to_string(s) + ",";
  return id + "}" + identity(nodes_[i].circle);
}

const std::optional<CircleValue<ExactSum>>& PolygonAxisGeometry::exact_circle(std::uint32_t i) const {
  if (!circle_done_[i]) {
    circles_[i] = solve_exact(*sites_, nodes_[i].circle);
    circle_done_[i] = 1;
  }
  return circles_[i];
}

ExactSum PolygonAxisGeometry::exact_radius(std::uint32_t node) const {
  ExactSum r;
  if (const auto& c = exact_circle(node))
    r = c->r;
  else
    r = ExactSum::constant(std::make_shared<CircleRadius>(sites_, nodes_[node].circle, node_identity(node)));
  r.scale(to_input_);
  return r;
}

// The arc length |S(xi_v) - S(xi_u)| depends only on the focal parameter p and the two
// abscissas; S is odd, so (p, {xi_u, xi_v}) up to a common sign names the value. Equal
// arcs (mirror-symmetric shapes) then share one identity and cancel exactly; without
// exact end circles the identity falls back to the sites.
std::string PolygonAxisGeometry::arc_identity(const AxisEdgeData& e, const std::string& ends) const {
  const auto& a = exact_circle(e.u);
  const auto& b = exact_circle(e.v);
  if (a && b) {
    try {
      const PolygonSites& s = *sites_;
      const std::uint32_t f = s.is_point(e.site_a) ? e.site_a : e.site_b;
      const std::uint32_t l = s.is_point(e.site_a) ? e.site_b : e.site_a;
      const Point2 fp = s.vertex[f], la = s.vertex[s.seg_start(l)], lb = s.vertex[s.seg_end(l)];
      const RootSum dx = RootSum(lb.x) - RootSum(la.x), dy = RootSum(lb.y) - RootSum(la.y);
      const RootSum len = sqrt(dx * dx + dy * dy);
      const RootSum p = (dx * (RootSum(fp.y) - RootSum(la.y)) - dy * (RootSum(fp.x) - RootSum(la.x))) / len;
      RootSum xu = (dx * (RootSum(a->x) - RootSum(fp.x)) + dy * (RootSum(a->y) - RootSum(fp.y))) / len;
      RootSum xv = (dx * (RootSum(b->x) - RootSum(fp.x)) + dy * (RootSum(b->y) - RootSum(fp.y))) / len;
      const int sum_sign = exact_sign((xu + xv).v);
      if (sum_sign < 0 || (sum_sign == 0 && exact_sign(xu.v) < 0)) {
        xu = -xu;
        xv = -xv;
      }
      std::string su = to_string(xu.v), sv = to_string(xv.v);
      if (sv < su) std::swap(su, sv);
      return "arc[" + to_string(p.v) + ";" + su + ";" + sv + "]";
    } catch (const NestedRadical&) {
    }
  }
  return "arc(" + std::to_string(e.site_a) + "," + std::to_string(e.site_b) + ";" + ends + ")";
}

ExactSum PolygonAxisGeometry::frame_length(std::uint32_t edge) const {
  const AxisEdgeData& e = edges_[edge];
  const std::string iu = node_identity(e.u), iv = node_identity(e.v);
  const std::string ends = iu < iv ? iu + ";" + iv : iv + ";" + iu;
  if (e.parabolic) {
    const std::string id = arc_identity(e, ends);
    return ExactSum::constant(
        std::make_shared<EdgeLength>(sites_, e, nodes_[e.u].circle, nodes_[e.v].circle, id));
  }
  const auto& a = exact_circle(e.u);
  const auto& b = exact_circle(e.v);
  if (!a || !b)
    return ExactSum::constant(
        std::make_shared<EdgeLength>(sites_, e, nodes_[e.u].circle, nodes_[e.v].circle, "segment(" + ends + ")"));
  const ExactSum dx = a->x - b->x, dy = a->y - b->y;
  ExactSum squared = multiply(dx, dx) + multiply(dy, dy);
  squared.simplify();
  if (std::optional<ExactSum> root = sqrt_of_sum(squared)) return *root;
  return ExactSum::constant(std::make_shared<SqrtOfSum>(squared));
}

ExactSum PolygonAxisGeometry::exact_length(std::uint32_t edge) const {
  if (!lengths_[edge]) {
    ExactSum l = frame_length(edge);
    l.scale(to_input_);
    lengths_[edge] = std::move(l);
  }
  return *lengths_[edge];
}

namespace {

// A parabolic edge in input coordinates (doubles; for drawing only).
struct DrawnParabola {
  double fx, fy, ex, ey, ux, uy, p;
  Point2 at(double xi) const {
    const double eta = (xi * xi + p * p) / (2 * p);
    return {fx - p * ux + xi * ex + eta * ux, fy - p * uy + xi * ey + eta * uy};
  }
  double xi_of(const Point2& x) const { return ex * (x.x - fx) + ey * (x.y - fy); }
  double primitive(double xi) const {
    return 0.5 * xi * std::sqrt(1 + (xi / p) * (xi / p)) + 0.5 * p * std::asinh(xi / p);
  }
};

DrawnParabola drawn(const PolygonSites& s, const AxisEdgeData& e, double scale) {
  const std::uint32_t focus = s.is_point(e.site_a) ? e.site_a : e.site_b;
  const std::uint32_t line = s.is_point(e.site_a) ? e.site_b : e.site_a;
  const Point2 f = s.vertex[focus], a = s.vertex[s.seg_start(line)], b = s.vertex[s.seg_end(line)];
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  DrawnParabola d{f.x * scale, f.y * scale, dx / len, dy / len, -dy / len, dx / len, 0};
  d.p = (d.ux * (f.x - a.x) + d.uy * (f.y - a.y)) * scale;
  return d;
}

}  // namespace

Point2 PolygonAxisGeometry::point_along(const MedialGraph& g, std::uint32_t edge, std::uint32_t from,
                                        double s) const {
  const AxisEdgeData& e = edges_[edge];
  if (!e.parabolic) return MedialGeometry::point_along(g, edge, from, s);
  const DrawnParabola d = drawn(*sites_, e, to_input_.get_d());
  const double x0 = d.xi_of(g.node(from).position), x1 = d.xi_of(g.node(g.other_end(edge, from)).position);
  const double target = d.primitive(x0) + (x1 > x0 ? s : -s);
  double lo = std::fmin(x0, x1), hi = std::fmax(x0, x1);
  for (int i = 0; i < 80; ++i) {  // bisection: S is increasing
    const double mid = 0.5 * (lo + hi);
    (d.primitive(mid) < target ? lo : hi) = mid;
  }
  return d.at(0.5 * (lo + hi));
}

std::vector<Point2> PolygonAxisGeometry::polyline(const MedialGraph& g, std::uint32_t edge) const {
  const AxisEdgeData& e = edges_[edge];
  if (!e.parabolic) return MedialGeometry::polyline(g, edge);
  const DrawnParabola d = drawn(*sites_, e, to_input_.get_d());
  const Point2 a = g.node(g.edge(edge).u).position, b = g.node(g.edge(edge).v).position;
  const double x0 = d.xi_of(a), x1 = d.xi_of(b);
  std::vector<Point2> out{a};
  constexpr int kSamples = 16;
  for (int i = 1; i < kSamples; ++i) out.push_back(d.at(x0 + (x1 - x0) * i / kSamples));
  out.push_back(b);
  return out;
}

}  // namespace grassfire
