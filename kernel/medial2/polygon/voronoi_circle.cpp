// voronoi_circle.cpp -- see voronoi_circle.h.
#include "medial2/polygon/voronoi_circle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "geometry2/predicates2.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

using Exact = RootSum;

bool surely_nonzero(const Interval& a) { return a.lo > 0 || a.hi < 0; }
bool surely_nonzero(const Ball& a) { return a.sign() == 1 || a.sign() == -1; }
bool surely_nonzero(const Exact& a) { return exact_sign(a.v) != 0; }
bool surely_nonzero(const DDBall& a) { return a.sign() == 1 || a.sign() == -1; }
// m > 0 certainly, in the enclosure types (never for the exact forms, which keep their
// formulas): where sqrt(N1 N2) - m cancels (nearly parallel lines), the enclosures use
// sqrt(N1 N2) - m = det^2 / (sqrt(N1 N2) + m) (Lagrange: N1 N2 - m^2 = det^2).
bool surely_positive(const Interval& a) { return a.lo > 0; }
bool surely_positive(const Ball& a) { return a.sign() == 1; }
bool surely_positive(const DDBall& a) { return a.sign() == 1; }
bool surely_positive(const Exact&) { return false; }
DDBall combine(const DDBall& a, const DDBall& b) { return intersect(a, b); }
Interval combine(const Interval& a, const Interval& b) { return intersect(a, b); }
Ball combine(const Ball& a, const Ball& b) { return intersect(a, b); }
Exact combine(const Exact& a, const Exact&) { return a; }
template <class T>
T whole();
template <>
Interval whole<Interval>() {
  const double inf = std::numeric_limits<double>::infinity();
  return {-inf, inf};
}
template <>
Ball whole<Ball>() {
  Ball b;
  arb_indeterminate(b.get());
  return b;
}
template <>
DDBall whole<DDBall>() {
  return DDBall::whole();
}
template <>
Exact whole<Exact>() {
  throw std::logic_error("voronoi_circle: both root forms have a zero denominator");
}

// n1 / d1 and n2 / d2 are two forms of the same root (the second avoids cancellation).
template <class T>
T two_forms(const T& n1, const T& d1, const T& n2, const T& d2) {
  const bool ok1 = surely_nonzero(d1), ok2 = surely_nonzero(d2);
  if (ok1 && ok2) return combine(n1 / d1, n2 / d2);
  if (ok1) return n1 / d1;
  if (ok2) return n2 / d2;
  return whole<T>();
}

template <class T>
struct Pt {
  T x, y;
};
// A segment's line n.X + c = 0, n the left normal (into the polygon), N = |n|^2.
template <class T>
struct Line {
  T nx, ny, c, N;
};

// Coordinates about an origin o (the enclosures: see solve), or as they are (o null: the
// exact forms).
template <class T>
T about(double x, const double* o) {
  return o ? T(x) - T(*o) : T(x);
}
template <class T>
Pt<T> point_of(const PolygonSites& s, std::uint32_t site, const Point2* o = nullptr) {
  return {about<T>(s.vertex[site].x, o ? &o->x : nullptr), about<T>(s.vertex[site].y, o ? &o->y : nullptr)};
}
template <class T>
Line<T> line_of(const PolygonSites& s, std::uint32_t site, const Point2* o = nullptr) {
  const Point2 a = s.vertex[s.seg_start(site)], b = s.vertex[s.seg_end(site)];
  Line<T> l;
  l.nx = T(a.y) - T(b.y);
  l.ny = T(b.x) - T(a.x);
  l.c = -(l.nx * about<T>(a.x, o ? &o->x : nullptr) + l.ny * about<T>(a.y, o ? &o->y : nullptr));
  l.N = l.nx * l.nx + l.ny * l.ny;
  return l;
}

template <class T>
CircleValue<T> solve_ppp(const Pt<T>& p1, const Pt<T>& p2, const Pt<T>& p3) {
  const T bx = p2.x - p1.x, by = p2.y - p1.y, cx = p3.x - p1.x, cy = p3.y - p1.y;
  const T d = T(2.0) * (bx * cy - by * cx);
  const T b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const T ux = (b2 * cy - c2 * by) / d, uy = (c2 * bx - b2 * cx) / d;
  return {p1.x + ux, p1.y + uy, sqrt(ux * ux + uy * uy)};
}

// Circle through P and Q tangent to L: centre M + t d on the bisector of P and Q, with
// a t^2 + 2 g0 g1 t + (g0^2 - N h0) = 0 (see voronoi_circle.h).
template <class T>
CircleValue<T> solve_pps(const Pt<T>& p, const Pt<T>& q, const Line<T>& l, bool linear, int root, int tangent) {
  if (tangent && !std::is_same_v<T, Exact>) {
    // A (P when tangent = 1, else Q) on L's line: the circle touches L at A, its centre is
    // A + R n / sqrt(N), and |X - B| = R gives R = -|A - B|^2 sqrt(N) / (2 n.(A - B))
    // (n.(A - B) != 0: not the linear case). The same circle as the quadratic's double
    // root below, without its cancellations.
    const Pt<T>& a = tangent == 1 ? p : q;
    const Pt<T>& b = tangent == 1 ? q : p;
    const T dx = a.x - b.x, dy = a.y - b.y;
    const T f = (dx * dx + dy * dy) / (T(2.0) * (l.nx * dx + l.ny * dy));
    return {a.x - f * l.nx, a.y - f * l.ny, -(f * sqrt(l.N))};
  }
  const T mx = T(0.5) * (p.x + q.x), my = T(0.5) * (p.y + q.y);
  const T dx = p.y - q.y, dy = q.x - p.x;
  const T g0 = l.nx * mx + l.ny * my + l.c, g1 = l.nx * dx + l.ny * dy;
  const T h2 = dx * dx + dy * dy, h0 = T(0.25) * h2;
  const T c0 = g0 * g0 - l.N * h0;
  T t;
  if (linear) {
    t = -c0 / (T(2.0) * g0 * g1);
  } else {
    const T a = g1 * g1 - l.N * h2;
    const T beta = sqrt(l.N * (g0 * g0 * h2 + a * h0));
    const T sb = root > 0 ? beta : -beta;
    t = two_forms(sb - g0 * g1, a, c0, -(g0 * g1) - sb);
  }
  return {mx + t * dx, my + t * dy, (g0 + g1 * t) / sqrt(l.N)};
}

// Circle through P tangent to L1 and L2 (non-parallel): centre X0 + R W, R a root of
// a R^2 + 2 b R + c = 0 with a = ((sqrt(N1 N2) - n1.n2) / det)^2.
template <class T>
struct PssQuadratic {
  T x0, y0, wx, wy, a, b, c;
};
template <class T>
PssQuadratic<T> pss_quadratic(const Pt<T>& p, const Line<T>& l1, const Line<T>& l2) {
  const T det = l1.nx * l2.ny - l1.ny * l2.nx;
  const T s1 = sqrt(l1.N), s2 = sqrt(l2.N), sm = sqrt(l1.N * l2.N);
  const T m = l1.nx * l2.nx + l1.ny * l2.ny;
  const T x0 = (l2.c * l1.ny - l1.c * l2.ny) / det, y0 = (l1.c * l2.nx - l2.c * l1.nx) / det;
  const T wx = (s1 * l2.ny - s2 * l1.ny) / det, wy = (l1.nx * s2 - l2.nx * s1) / det;
  const T ex = x0 - p.x, ey = y0 - p.y;
  const T k = surely_positive(m) ? det / (sm + m) : (sm - m) / det;
  return {x0, y0, wx, wy, k * k, ex * wx + ey * wy, ex * ex + ey * ey};
}

template <class T>
CircleValue<T> solve_pss(const Pt<T>& p, const Line<T>& l1, const Line<T>& l2, int root) {
  const PssQuadratic<T> q = pss_quadratic(p, l1, l2);
  const T sd = sqrt(q.b * q.b - q.a * q.c);
  const T ss = root > 0 ? sd : -sd;
  const T r = two_forms(ss - q.b, q.a, q.c, -q.b - ss);
  return {q.x0 + r * q.wx, q.y0 + r * q.wy, r};
}

// Circle through P tangent to Li and Lj, with P on Li: it touches Li at P, so its centre
// is P + R ni / |ni|, and the tangency to Lj, (nj . X + cj) / |nj| = R, is linear in R:
// R = gj |ni| / (|ni| |nj| - ni . nj) with gj = nj . P + cj.
template <class T>
CircleValue<T> solve_pss_tangent(const Pt<T>& p, const Line<T>& li, const Line<T>& lj) {
  const T si = sqrt(li.N), sij = sqrt(li.N * lj.N);
  const T m = li.nx * lj.nx + li.ny * lj.ny;
  const T g = lj.nx * p.x + lj.ny * p.y + lj.c;
  T r;
  if (surely_positive(m)) {
    const T det = li.nx * lj.ny - li.ny * lj.nx;
    r = g * si * (sij + m) / (det * det);
  } else {
    r = g * si / (sij - m);
  }
  const T k = r / si;
  return {p.x + k * li.nx, p.y + k * li.ny, r};
}

// Circle through P tangent to two anti-parallel lines (a strip): R is half the width,
// the centre on the mid-line at sqrt(d1 d2) from P's foot, on the side that makes the
// tangency points run L1, L2, P counter-clockwise.
template <class T>
CircleValue<T> solve_pss_parallel(const Pt<T>& p, const Line<T>& l1, const Line<T>& l2) {
  const T s1 = sqrt(l1.N), s2 = sqrt(l2.N);
  const T d1 = (l1.nx * p.x + l1.ny * p.y + l1.c) / s1, d2 = (l2.nx * p.x + l2.ny * p.y + l2.c) / s2;
  const T r = T(0.5) * (d1 + d2);
  const T ux = l1.nx / s1, uy = l1.ny / s1;
  const T tau = sqrt(d1 * d2), off = d1 - r;
  return {p.x - off * ux + tau * uy, p.y - off * uy - tau * ux, r};
}

// Incircle of three lines: n_i . X - sqrt(N_i) R = -c_i, by Cramer's rule.
template <class T>
CircleValue<T> solve_sss(const Line<T>& a, const Line<T>& b, const Line<T>& c) {
  const T sa = -sqrt(a.N), sb = -sqrt(b.N), sc = -sqrt(c.N);
  auto det3 = [](const T& a1, const T& a2, const T& a3, const T& b1, const T& b2, const T& b3, const T& c1,
                 const T& c2, const T& c3) {
    return a1 * (b2 * c3 - b3 * c2) - a2 * (b1 * c3 - b3 * c1) + a3 * (b1 * c2 - b2 * c1);
  };
  const T d = det3(a.nx, a.ny, sa, b.nx, b.ny, sb, c.nx, c.ny, sc);
  const T ra = -a.c, rb = -b.c, rc = -c.c;
  const T dx = det3(ra, a.ny, sa, rb, b.ny, sb, rc, c.ny, sc);
  const T dy = det3(a.nx, ra, sa, b.nx, rb, sb, c.nx, rc, sc);
  const T dr = det3(a.nx, a.ny, ra, b.nx, b.ny, rb, c.nx, c.ny, rc);
  return {dx / d, dy / d, dr / d};
}

// The circle with its sites' coordinates about o (null: as they are).
template <class T>
CircleValue<T> solve_about(const PolygonSites& s, const VoronoiCircle& c, const Point2* o) {
  const auto& id = c.sites;
  auto point_of = [&](std::uint32_t site) { return grassfire::point_of<T>(s, site, o); };
  auto line_of = [&](std::uint32_t site) { return grassfire::line_of<T>(s, site, o); };
  switch (c.kind) {
    case CircleKind::Apex: {
      const Pt<T> p = point_of(id[0]);
      return {p.x, p.y, T(0.0)};
    }
    case CircleKind::PPP: return solve_ppp(point_of(id[0]), point_of(id[1]), point_of(id[2]));
    case CircleKind::PPS:
    case CircleKind::PPSLinear:
      return solve_pps(point_of(id[0]), point_of(id[1]), line_of(id[2]), c.kind == CircleKind::PPSLinear, c.root,
                       c.tangent);
    case CircleKind::PSS:
      if (c.tangent) return solve_pss_tangent(point_of(id[0]), line_of(id[c.tangent]), line_of(id[3 - c.tangent]));
      return solve_pss(point_of(id[0]), line_of(id[1]), line_of(id[2]), c.root);
    case CircleKind::PSSParallel: return solve_pss_parallel(point_of(id[0]), line_of(id[1]), line_of(id[2]));
    case CircleKind::SSS: return solve_sss(line_of(id[0]), line_of(id[1]), line_of(id[2]));
  }
  throw std::logic_error("voronoi_circle: unknown kind");
}

// The enclosures are computed about a vertex of the circle's first site and translated
// back: in the frame's coordinates a line's c = -n.A is large against n.X + c near the
// circle (|A| ~ 10^6 against a local feature size ~ 10^2 on the benchmark's curves), and
// each rounded operation on those magnitudes loses the bits of the cancellation. The
// exact forms are computed in the frame's coordinates as they are.
template <class T>
CircleValue<T> solve(const PolygonSites& s, const VoronoiCircle& c) {
  if constexpr (std::is_same_v<T, Exact>) {
    return solve_about<T>(s, c, nullptr);
  } else {
    if (c.kind == CircleKind::Apex) return solve_about<T>(s, c, nullptr);
    const std::uint32_t first = c.sites[0];
    const Point2 o = s.vertex[s.is_point(first) ? first : s.seg_start(first)];
    const CircleValue<T> local = solve_about<T>(s, c, &o);
    return {local.x + T(o.x), local.y + T(o.y), local.r};
  }
}

mpq_class q(double d) { return mpq_class(d); }

// The PPS root choice (see classify_circle): the exact sign of rhs - beta w, with
// linear (a = 0) and double-root (delta = 0) cases. First in double-double balls, which
// decide every case whose quantities they separate from zero; exactly otherwise.
template <class T>
struct PpsTest {
  T aa, delta, test;
};

template <class T>
PpsTest<T> pps_test(const Point2& p, const Point2& qq, const Point2& a, const Point2& b) {
  const T nx = T(a.y) - T(b.y), ny = T(b.x) - T(a.x);
  const T c = -(nx * T(a.x) + ny * T(a.y)), N = nx * nx + ny * ny;
  const T mx = (T(p.x) + T(qq.x)) * T(0.5), my = (T(p.y) + T(qq.y)) * T(0.5);
  const T dx = T(p.y) - T(qq.y), dy = T(qq.x) - T(p.x);
  const T g0 = nx * mx + ny * my + c, g1 = nx * dx + ny * dy;
  const T h2 = dx * dx + dy * dy, h0 = h2 * T(0.25);
  const T aa = g1 * g1 - N * h2;
  const T delta = g0 * g0 * h2 + aa * h0;
  // orient(P, Q, foot) > 0  <=>  (alpha + sigma beta) w - g0 k a < 0, with a < 0.
  const T k = (T(qq.x) - T(p.x)) * ny - (T(qq.y) - T(p.y)) * nx;
  const T w = N * h2 - g1 * k, alpha = -(g0 * g1);
  const T rhs = g0 * k * aa - alpha * w;
  return {aa, delta, rhs - sqrt(N * delta) * w};
}

// `on_line`: 1 when P lies on L's line, 2 when Q does (and P does not), else 0.
int pps_root(const PolygonSites& s, std::uint32_t ps, std::uint32_t qs, std::uint32_t ls, bool* linear,
             std::uint8_t* on_line) {
  const Point2 p = s.vertex[ps], qq = s.vertex[qs];
  const Point2 a = s.vertex[s.seg_start(ls)], b = s.vertex[s.seg_end(ls)];
  // A point on L's line (typically a segment's own endpoint): with u = (P - Q) / 2,
  // a = -4 (n.u)^2 and, when g(P) = 0 or g(Q) = 0, delta = 4 |u|^2 ((n.u)^2 + (n x u)^2 -
  // N |u|^2) = 0 (Lagrange's identity): one circle, touching L at that point. a = 0 (the
  // linear case) exactly when PQ is parallel to L, i.e. when both points lie on its line.
  // These are the exact path's answers below (linear, else root 1 for delta = 0), from
  // exact orientations instead of rationals.
  const int op = orientation(a, b, p), oq = orientation(a, b, qq);
  *on_line = op == 0 ? 1 : oq == 0 ? 2 : 0;
  if (*on_line) {
    *linear = op == 0 && oq == 0;
    return 1;
  }
  const PpsTest<DDBall> f = pps_test<DDBall>(p, qq, a, b);
  const int fa = f.aa.sign(), fd = f.delta.sign(), ft = f.test.sign();
  if ((fa == 1 || fa == -1) && fd == 1 && (ft == 1 || ft == -1)) {
    *linear = false;
    return ft;
  }
  const mpq_class nx = q(a.y) - q(b.y), ny = q(b.x) - q(a.x);
  const mpq_class c = -(nx * q(a.x) + ny * q(a.y)), N = nx * nx + ny * ny;
  const mpq_class mx = (q(p.x) + q(qq.x)) / 2, my = (q(p.y) + q(qq.y)) / 2;
  const mpq_class dx = q(p.y) - q(qq.y), dy = q(qq.x) - q(p.x);
  const mpq_class g0 = nx * mx + ny * my + c, g1 = nx * dx + ny * dy;
  const mpq_class h2 = dx * dx + dy * dy, h0 = h2 / 4;
  const mpq_class aa = g1 * g1 - N * h2;
  *linear = sgn(aa) == 0;
  if (*linear) return 1;
  const mpq_class delta = g0 * g0 * h2 + aa * h0;
  if (sgn(delta) == 0) return 1;
  const mpq_class k = (q(qq.x) - q(p.x)) * ny - (q(qq.y) - q(p.y)) * nx;
  const mpq_class w = N * h2 - g1 * k, alpha = -g0 * g1;
  const mpq_class rhs = g0 * k * aa - alpha * w;
  ExactSum test = ExactSum::rational(rhs);
  ExactSum beta_w = ExactSum::sqrt_of(N * delta);
  beta_w.scale(w);
  test -= beta_w;
  return sign(test) > 0 ? 1 : -1;
}

int cross_sign(const PolygonSites& s, std::uint32_t l1, std::uint32_t l2) {
  const Point2 a1 = s.vertex[s.seg_start(l1)], b1 = s.vertex[s.seg_end(l1)];
  const Point2 a2 = s.vertex[s.seg_start(l2)], b2 = s.vertex[s.seg_end(l2)];
  // cross(n1, n2) = cross(d1, d2) for the left normals n = rot90(d). Integer frames
  // (|x| < 2^31, the Boost path) fit 128-bit integers exactly.
  auto small = [](const Point2& v) {
    return std::fabs(v.x) < 0x1p31 && std::fabs(v.y) < 0x1p31 && v.x == std::floor(v.x) && v.y == std::floor(v.y);
  };
  if (small(a1) && small(b1) && small(a2) && small(b2)) {
    const auto i = [](double x) { return static_cast<std::int64_t>(x); };
    const __int128 c = static_cast<__int128>(i(b1.x) - i(a1.x)) * (i(b2.y) - i(a2.y)) -
                       static_cast<__int128>(i(b1.y) - i(a1.y)) * (i(b2.x) - i(a2.x));
    return c > 0 ? 1 : c < 0 ? -1 : 0;
  }
  const mpq_class d1x = q(b1.x) - q(a1.x), d1y = q(b1.y) - q(a1.y);
  const mpq_class d2x = q(b2.x) - q(a2.x), d2y = q(b2.y) - q(a2.y);
  return sgn(mpq_class(d1x * d2y - d1y * d2x));
}

}  // namespace

const char* to_string(CircleKind kind) {
  switch (kind) {
    case CircleKind::Apex: return "apex";
    case CircleKind::PPP: return "PPP";
    case CircleKind::PPS: return "PPS";
    case CircleKind::PPSLinear: return "PPS-linear";
    case CircleKind::PSS: return "PSS";
    case CircleKind::PSSParallel: return "PSS-parallel";
    case CircleKind::SSS: return "SSS";
  }
  return "unknown";
}

VoronoiCircle classify_circle(const PolygonSites& s, const VoronoiTopology::Vertex& v) {
  VoronoiCircle c;
  c.sites = v.sites;
  if (v.apex) return c;
  const int points = static_cast<int>(s.is_point(v.sites[0])) + s.is_point(v.sites[1]) + s.is_point(v.sites[2]);
  // Rotate the counter-clockwise triple into the roles of the formulas.
  auto rotate_until = [&](auto pred) {
    for (int i = 0; i < 3 && !pred(); ++i) std::rotate(c.sites.begin(), c.sites.begin() + 1, c.sites.end());
  };
  switch (points) {
    case 3: c.kind = CircleKind::PPP; break;
    case 2: {
      rotate_until([&] { return !s.is_point(c.sites[2]); });
      bool linear = false;
      std::uint8_t on_line = 0;
      c.root = static_cast<std::int8_t>(pps_root(s, c.sites[0], c.sites[1], c.sites[2], &linear, &on_line));
      c.kind = linear ? CircleKind::PPSLinear : CircleKind::PPS;
      if (c.kind == CircleKind::PPS) c.tangent = on_line;
      break;
    }
    case 1: {
      rotate_until([&] { return s.is_point(c.sites[0]); });
      const int cs = cross_sign(s, c.sites[1], c.sites[2]);
      c.kind = cs == 0 ? CircleKind::PSSParallel : CircleKind::PSS;
      c.root = static_cast<std::int8_t>(cs > 0 ? -1 : 1);
      if (c.kind == CircleKind::PSS)
        for (std::uint8_t i = 1; i <= 2 && !c.tangent; ++i) {
          const Point2 a = s.vertex[s.seg_start(c.sites[i])], b = s.vertex[s.seg_end(c.sites[i])];
          if (orientation(a, b, s.vertex[c.sites[0]]) == 0) c.tangent = i;
        }
      break;
    }
    default: c.kind = CircleKind::SSS; break;
  }
  return c;
}

std::string identity(const VoronoiCircle& c) {
  return std::string(to_string(c.kind)) + "(" + std::to_string(c.sites[0]) + "," + std::to_string(c.sites[1]) + "," +
         std::to_string(c.sites[2]) + (c.root > 0 ? ")+" : ")-");
}

bool at_most_one_circle(const PolygonSites& s, const VoronoiCircle& c) {
  switch (c.kind) {
    case CircleKind::PPP:
    case CircleKind::SSS:
    case CircleKind::PPSLinear: return true;
    case CircleKind::Apex: return false;
    default: break;
  }
  if (c.kind == CircleKind::PSSParallel) {
    const Point2 a1 = s.vertex[s.seg_start(c.sites[1])], b1 = s.vertex[s.seg_end(c.sites[1])];
    const Point2 a2 = s.vertex[s.seg_start(c.sites[2])], b2 = s.vertex[s.seg_end(c.sites[2])];
    const mpq_class dot = (q(b1.x) - q(a1.x)) * (q(b2.x) - q(a2.x)) + (q(b1.y) - q(a1.y)) * (q(b2.y) - q(a2.y));
    if (sgn(dot) >= 0) return false;
  }
  for (std::uint32_t p : c.sites)
    for (std::uint32_t l : c.sites)
      if (s.is_point(p) && !s.is_point(l) &&
          orientation(s.vertex[s.seg_start(l)], s.vertex[s.seg_end(l)], s.vertex[p]) == 0)
        return true;
  return false;
}

CircleValue<Interval> solve_interval(const PolygonSites& s, const VoronoiCircle& c) { return solve<Interval>(s, c); }
CircleValue<Ball> solve_ball(const PolygonSites& s, const VoronoiCircle& c) { return solve<Ball>(s, c); }
CircleValue<DDBall> solve_dd(const PolygonSites& s, const VoronoiCircle& c) { return solve<DDBall>(s, c); }

std::optional<CircleValue<ExactSum>> solve_exact(const PolygonSites& s, const VoronoiCircle& c) {
  try {
    const CircleValue<Exact> e = solve<Exact>(s, c);
    return CircleValue<ExactSum>{e.x.v, e.y.v, e.r.v};
  } catch (const NestedRadical&) {
    return std::nullopt;
  }
}

// A PSS circle whose R is a nested radical: R = (sigma sqrt(b^2 - a c) - b) / a (solve_pss)
// with a, b, c sums of square roots, the outer root written with sqrt_term and carried
// through the centre X0 + R W by multiply_radical (number/sqrt_field.h).
std::optional<CircleValue<ExactSum>> solve_radical(const PolygonSites& s, const VoronoiCircle& c) {
  if (std::optional<CircleValue<ExactSum>> plain = solve_exact(s, c)) return plain;
  if (c.kind != CircleKind::PSS || c.tangent) return std::nullopt;
  try {
    const Pt<Exact> p = point_of<Exact>(s, c.sites[0]);
    const Line<Exact> l1 = line_of<Exact>(s, c.sites[1]), l2 = line_of<Exact>(s, c.sites[2]);
    const PssQuadratic<Exact> q = pss_quadratic(p, l1, l2);
    ExactSum root = sqrt_term((q.b * q.b - q.a * q.c).v);
    if (c.root < 0) root.scale(-1);
    const Exact inverse_a = Exact(1.0) / q.a;
    const ExactSum r = multiply_radical(root - q.b.v, inverse_a.v);
    ExactSum x = q.x0.v + multiply_radical(r, q.wx.v), y = q.y0.v + multiply_radical(r, q.wy.v);
    x.simplify();
    y.simplify();
    return CircleValue<ExactSum>{std::move(x), std::move(y), r};
  } catch (const NestedRadical&) {
    return std::nullopt;
  }
}

}  // namespace grassfire
