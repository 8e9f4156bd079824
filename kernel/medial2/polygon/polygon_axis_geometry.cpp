// polygon_axis_geometry.cpp -- see polygon_axis_geometry.h.
#include "medial2/polygon/polygon_axis_geometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "medial2/polygon/polygon_axis_symmetry.h"
#include "number/mpfr_bounds.h"
#include "number/parabolic_arc.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

Ball abs_of(const Ball& a) {
  Ball r;
  arb_abs(r.get(), a.get());
  return r;
}

// A parabolic edge in its focus frame: the focal parameter p (the distance from the focus
// to the directrix, left side positive) and the abscissae of the ends along the directrix.
template <class T>
struct ParabolaFrame {
  T p, xa, xb;
};

template <class T>
ParabolaFrame<T> parabola_frame(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<T>& a,
                                const CircleValue<T>& b) {
  const std::uint32_t focus = s.is_point(e.site_a) ? e.site_a : e.site_b;
  const std::uint32_t line = s.is_point(e.site_a) ? e.site_b : e.site_a;
  const Point2 f = s.vertex[focus], la = s.vertex[s.seg_start(line)], lb = s.vertex[s.seg_end(line)];
  const T fx(f.x), fy(f.y);
  const T dx = T(lb.x) - T(la.x), dy = T(lb.y) - T(la.y);
  const T len = sqrt(dx * dx + dy * dy);
  return {(dx * (fy - T(la.y)) - dy * (fx - T(la.x))) / len, (dx * (a.x - fx) + dy * (a.y - fy)) / len,
          (dx * (b.x - fx) + dy * (b.y - fy)) / len};
}

template <class T>
T length_of(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<T>& a, const CircleValue<T>& b) {
  if (!e.parabolic) {
    const T dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy);
  }
  const ParabolaFrame<T> q = parabola_frame(s, e, a, b);
  return abs_of(parabola_arc_primitive(q.xb, q.p) - parabola_arc_primitive(q.xa, q.p));
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

// S(xi) at exact p and xi as a constant, with xi >= 0 by the oddness of S (mirror images
// of an arc have opposite abscissas): coefficient times constant.
ExactSum primitive(const ExactSum& p, ExactSum xi) {
  NumberStats st;
  const int s = sign(xi, &st);
  if (s == 0 && st.uncertified_zero == 0) return ExactSum();
  if (s < 0) xi.scale(-1);
  ExactSum out = ExactSum::constant(arc_primitive_constant(p, std::move(xi)));
  if (s < 0) out.scale(-1);
  return out;
}

}  // namespace

Interval edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Interval>& a,
                     const CircleValue<Interval>& b) {
  return length_of(s, e, a, b);
}
Ball edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<Ball>& a,
                 const CircleValue<Ball>& b) {
  return length_of(s, e, a, b);
}

// The algebraic parts in double-double, which absorbs the cancellation of S(xi_v) -
// S(xi_u) on short arcs far from the focus; the transcendental part as one asinh,
// asinh(zv) - asinh(zu) = asinh(zv sqrt(1 + zu^2) - zu sqrt(1 + zv^2)) (sinh of a
// difference), whose argument is formed in double-double too. Both parts have the sign
// of xi_v - xi_u, so their sum does not cancel.
Interval edge_length(const PolygonSites& s, const AxisEdgeData& e, const CircleValue<DDBall>& a,
                     const CircleValue<DDBall>& b) {
  using T = DDBall;
  if (!e.parabolic) {
    const T dx = a.x - b.x, dy = a.y - b.y;
    return sqrt(dx * dx + dy * dy).to_interval();
  }
  const ParabolaFrame<T> q = parabola_frame(s, e, a, b);
  const T &p = q.p, &xa = q.xa, &xb = q.xb;
  const T za = xa / p, zb = xb / p;
  const T ca = sqrt(T(1.0) + za * za), cb = sqrt(T(1.0) + zb * zb);
  const Interval algebraic = (xb * cb - xa * ca).to_interval();
  const Interval transcendental = asinh_enclosure((zb * ca - za * cb).to_interval());
  return abs_of(half(algebraic) + half(p.to_interval() * transcendental));
}

namespace {

// Site indices name a value only inside one axis: the same indices in another frame (a
// translated or scaled copy) or another polygon are another value. Every identity built
// from indices carries this token, unique per geometry object in the process.
std::string fresh_identity_token() {
  static std::atomic<std::uint64_t> counter{0};
  return "axis#" + std::to_string(++counter) + ":";
}

}  // namespace

PolygonAxisGeometry::PolygonAxisGeometry(std::shared_ptr<const PolygonSites> sites, mpq_class to_input,
                                         std::vector<AxisNodeData> nodes, std::vector<AxisEdgeData> edges)
    : identity_token_(fresh_identity_token()),
      sites_(std::move(sites)),
      to_input_(std::move(to_input)),
      nodes_(std::move(nodes)),
      edges_(std::move(edges)),
      circles_(nodes_.size()),
      radicals_(nodes_.size()),
      lengths_(edges_.size()),
      ball_circles_(nodes_.size()),
      dd_circles_(nodes_.size()) {}

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
    ball_circles_[i] = std::make_unique<const CircleValue<Ball>>(solve_ball(*sites_, nodes_[i].circle));
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

const CircleValue<DDBall>& PolygonAxisGeometry::dd_circle(std::uint32_t i) const {
  if (!dd_circles_[i])
    dd_circles_[i] = std::make_unique<const CircleValue<DDBall>>(solve_dd(*sites_, nodes_[i].circle));
  return *dd_circles_[i];
}

DDBall PolygonAxisGeometry::scaled_to_input(const DDBall& frame_value) const {
  // to_input = num / den; exact when both integers fit a double's 53 bits (10^K, 1, ...).
  const mpz_class &num = to_input_.get_num(), &den = to_input_.get_den();
  if (mpz_sizeinbase(num.get_mpz_t(), 2) > 53 || mpz_sizeinbase(den.get_mpz_t(), 2) > 53) return DDBall::whole();
  return frame_value * DDBall(to_input_.get_num().get_d()) / DDBall(to_input_.get_den().get_d());
}

LongInterval PolygonAxisGeometry::enclose_radius_long(std::uint32_t node) const {
  const DDBall r = scaled_to_input(dd_circle(node).r);
  if (r.accurate_to(70)) return r.to_long_interval();
  MpfrBounds b(80);
  enclose_radius(node, b.lo, b.hi);
  return {mpfr_get_ld(b.lo, MPFR_RNDD), mpfr_get_ld(b.hi, MPFR_RNDU)};
}

LongInterval PolygonAxisGeometry::enclose_length_long(std::uint32_t edge) const {
  const AxisEdgeData& e = edges_[edge];
  if (!e.parabolic) {
    const CircleValue<DDBall>&a = dd_circle(e.u), &b = dd_circle(e.v);
    const DDBall dx = a.x - b.x, dy = a.y - b.y;
    const DDBall len = scaled_to_input(sqrt(dx * dx + dy * dy));
    if (len.accurate_to(70)) return len.to_long_interval();
  }
  MpfrBounds b(80);
  enclose_length(edge, b.lo, b.hi);
  return {mpfr_get_ld(b.lo, MPFR_RNDD), mpfr_get_ld(b.hi, MPFR_RNDU)};
}

std::string PolygonAxisGeometry::node_identity(std::uint32_t i) const {
  std::string id = identity_token_ + "vertex{";
  for (std::uint32_t s : nodes_[i].sites) id += std::to_string(s) + ",";
  return id + "}" + identity(nodes_[i].circle);
}

const std::optional<CircleValue<ExactSum>>& PolygonAxisGeometry::exact_circle(std::uint32_t i) const {
  if (!circles_[i])
    circles_[i] = std::make_unique<const std::optional<CircleValue<ExactSum>>>(solve_exact(*sites_, nodes_[i].circle));
  return *circles_[i];
}

const std::optional<CircleValue<ExactSum>>& PolygonAxisGeometry::radical_circle(std::uint32_t i) const {
  if (!radicals_[i])
    radicals_[i] = std::make_unique<const std::optional<CircleValue<ExactSum>>>(
        exact_circle(i) ? exact_circle(i) : solve_radical(*sites_, nodes_[i].circle));
  return *radicals_[i];
}

ExactSum PolygonAxisGeometry::exact_radius(std::uint32_t node) const {
  ExactSum r;
  if (const auto& c = radical_circle(node))
    r = c->r;
  else
    r = ExactSum::constant(std::make_shared<CircleRadius>(sites_, nodes_[node].circle, node_identity(node)));
  r.scale(to_input_);
  return r;
}

// The focal parameter p = cross(d, F - A) / |d| and the abscissas xi = d.(X - F) / |d| of
// the arc's ends (d the directrix segment's direction, F the focus), from the end circles'
// exact or radical forms. Collinear segments give one frame, so pieces of one parabola
// split at a collinear vertex share the abscissa of their common end.
std::optional<ArcForm> PolygonAxisGeometry::arc_form(const AxisEdgeData& e) const {
  const auto& a = radical_circle(e.u);
  const auto& b = radical_circle(e.v);
  if (!a || !b) return std::nullopt;
  const PolygonSites& s = *sites_;
  const std::uint32_t f = s.is_point(e.site_a) ? e.site_a : e.site_b;
  const std::uint32_t l = s.is_point(e.site_a) ? e.site_b : e.site_a;
  const Point2 fp = s.vertex[f], la = s.vertex[s.seg_start(l)], lb = s.vertex[s.seg_end(l)];
  const mpq_class fx(fp.x), fy(fp.y), dx = mpq_class(lb.x) - mpq_class(la.x), dy = mpq_class(lb.y) - mpq_class(la.y);
  const mpq_class squared = dx * dx + dy * dy;
  ExactSum inverse_length = ExactSum::sqrt_of(squared);  // 1 / |d| = sqrt(|d|^2) / |d|^2
  inverse_length.scale(1 / squared);
  auto abscissa = [&](const CircleValue<ExactSum>& c) {
    ExactSum u = c.x - ExactSum::rational(fx), v = c.y - ExactSum::rational(fy);
    return multiply_radical(u.scale(dx) + v.scale(dy), inverse_length);
  };
  const mpq_class cross = dx * (fy - mpq_class(la.y)) - dy * (fx - mpq_class(la.x));
  return ArcForm{multiply(ExactSum::rational(cross), inverse_length), abscissa(*a), abscissa(*b)};
}

namespace {

// |S(xi_v) - S(xi_u)| = sigma (S(xi_v) - S(xi_u)) with sigma the sign of xi_v - xi_u,
// nonzero on an edge of positive length; nullopt when that sign is not certified.
std::optional<ExactSum> primitive_difference(const ArcForm& f) {
  NumberStats st;
  const int sigma = sign(f.xv - f.xu, &st);
  if (sigma == 0 || st.uncertified_zero != 0) return std::nullopt;
  ExactSum out = primitive(f.p, f.xv) - primitive(f.p, f.xu);
  out.scale(sigma);
  return out;
}

}  // namespace

ExactSum PolygonAxisGeometry::frame_length(std::uint32_t edge) const {
  const AxisEdgeData& e = edges_[edge];
  const std::string iu = node_identity(e.u), iv = node_identity(e.v);
  const std::string ends = iu < iv ? iu + ";" + iv : iv + ";" + iu;
  if (e.parabolic) {
    if (const std::optional<ArcForm> form = arc_form(e))
      if (std::optional<ExactSum> length = primitive_difference(*form)) return *length;
    const std::string id = "arc(" + std::to_string(e.site_a) + "," + std::to_string(e.site_b) + ";" + ends + ")";
    return ExactSum::constant(std::make_shared<EdgeLength>(sites_, e, nodes_[e.u].circle, nodes_[e.v].circle, id));
  }
  const auto& a = radical_circle(e.u);
  const auto& b = radical_circle(e.v);
  if (a && b)
    if (std::optional<ExactSum> projected = straight_length(e, *a, *b)) return *projected;
  const auto& pa = exact_circle(e.u);
  const auto& pb = exact_circle(e.v);
  if (!pa || !pb)
    return ExactSum::constant(
        std::make_shared<EdgeLength>(sites_, e, nodes_[e.u].circle, nodes_[e.v].circle, "segment(" + ends + ")"));
  const ExactSum dx = pa->x - pb->x, dy = pa->y - pb->y;
  ExactSum squared = multiply(dx, dx) + multiply(dy, dy);
  squared.simplify();
  return sqrt_term(squared);
}

// A straight edge lies on the bisector of its two sites, whose direction w is exact:
// rot90(Q - P) for two points, the normal n for a point on a segment's line, and
// rot90(u1 - u2) for two lines with unit inward normals u1, u2 (equal signed distances).
// Its length is |(X_u - X_v) . w| / |w|. The numerator is a sum of square roots (and of
// square roots of sums when an end is a nested-radical circle: solve_radical); so is
// 1 / |w| for the first two and for anti-parallel lines (|w| = 2), and then the length
// is an ExactSum. For two crossing lines 1 / |w|^2 = q is a sum of square roots, and
// the length sum_i c_i sqrt(r_i) sqrt(q) = sum_i c_i sqrt(r_i q) is written with square
// roots of sums (number/sqrt_field.h): pieces of one bisector then telescope, and pieces
// of bisectors of congruent line pairs share the radicand q, so burn times along
// differently split bisectors cancel exactly (exact equality of radicands).
std::optional<ExactSum> PolygonAxisGeometry::straight_length(const AxisEdgeData& e, const CircleValue<ExactSum>& a,
                                                             const CircleValue<ExactSum>& b) const {
  const PolygonSites& s = *sites_;
  try {
    RootSum wx, wy;
    if (s.is_point(e.site_a) && s.is_point(e.site_b)) {
      const Point2 p = s.vertex[e.site_a], q = s.vertex[e.site_b];
      wx = RootSum(p.y) - RootSum(q.y);
      wy = RootSum(q.x) - RootSum(p.x);
    } else {
      auto normal = [&](std::uint32_t site, RootSum& nx, RootSum& ny) {
        const Point2 p = s.vertex[s.seg_start(site)], q = s.vertex[s.seg_end(site)];
        nx = RootSum(p.y) - RootSum(q.y);
        ny = RootSum(q.x) - RootSum(p.x);
      };
      RootSum n1x, n1y;
      normal(s.is_point(e.site_a) ? e.site_b : e.site_a, n1x, n1y);
      if (s.is_point(e.site_a) || s.is_point(e.site_b)) {
        wx = n1x;
        wy = n1y;
      } else {
        RootSum n2x, n2y;
        normal(e.site_b, n2x, n2y);
        const RootSum l1 = sqrt(n1x * n1x + n1y * n1y), l2 = sqrt(n2x * n2x + n2y * n2y);
        const RootSum ux = n1x / l1 - n2x / l2, uy = n1y / l1 - n2y / l2;
        wx = -uy;
        wy = ux;
        // Two segments of one line (a collinear vertex): the bisector is its normal there.
        if (exact_sign((wx * wx + wy * wy).v) == 0) {
          wx = n1x;
          wy = n1y;
        }
      }
    }
    // X_u, X_v may hold square roots of sums (solve_radical): multiply_radical keeps them.
    ExactSum along = multiply_radical(a.x - b.x, wx.v) + multiply_radical(a.y - b.y, wy.v);
    along.simplify();
    const RootSum ww = wx * wx + wy * wy;
    NumberStats st;
    const int sa = sign(along, &st), sw = exact_sign(ww.v);
    if (sa == 0 || st.uncertified_zero != 0 || sw <= 0) return std::nullopt;
    if (sa < 0) along.scale(-1);
    const RootSum q = RootSum(1.0) / ww;
    if (std::optional<mpq_class> root = q.v.sqrt_terms().empty() ? rational_sqrt(q.v.rational_part()) : std::nullopt)
      return along.scale(*root);
    if (q.v.sqrt_terms().empty()) return multiply_radical(along, ExactSum::sqrt_of(q.v.rational_part()));
    // sum_i c_i sqrt(r_i q) + sum_k d_k sqrt(E_k q), each root denested when it can be.
    ExactSum out;
    auto add_root = [&](const mpq_class& c, ExactSum radicand) {
      ExactSum term = sqrt_term(multiply(radicand, q.v));
      out += term.scale(c);
    };
    if (sgn(along.rational_part()) != 0) add_root(along.rational_part(), ExactSum::rational(1));
    for (const SqrtTerm& t : along.sqrt_terms()) add_root(t.coef, ExactSum::rational(t.radicand));
    for (const ConstantTerm& t : along.constant_terms()) {
      if (!t.value->radicand()) return std::nullopt;
      add_root(t.coef, *t.value->radicand());
    }
    out.simplify();
    return out;
  } catch (const NestedRadical&) {
    return std::nullopt;
  }
}

ExactSum PolygonAxisGeometry::exact_length(std::uint32_t edge) const {
  if (!lengths_[edge]) {
    ExactSum l = frame_length(edge);
    l.scale(to_input_);
    lengths_[edge] = std::make_unique<const ExactSum>(std::move(l));
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
