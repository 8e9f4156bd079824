// junction_books.cpp -- the closed-form three-page books (junction_books.h).
#include "burn3/junction_books.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "burn3/bracket_support.h"

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ExactPoint3 along(const mpq_class& x, const ExactPoint3& dir, const mpq_class& s) {
  return {x + s * dir.x, s * dir.y, s * dir.z};
}

// The spine's geometry in the plane z = 0: N(x) = (x, y(x)), y = 0 for x <= 1/2 and
// -2 bend (x - 1/2) beyond (one piece when bend = 0); u(x) its arclength.
struct Spine {
  double bend, stretch;
  explicit Spine(const JunctionBook& b) : bend(b.bend.get_d()), stretch(std::sqrt(1 + 4 * bend * bend)) {}
  double y(double x) const { return x <= 0.5 ? 0.0 : -2 * bend * (x - 0.5); }
  double u(double x) const { return x <= 0.5 ? x : 0.5 + (x - 0.5) * stretch; }
  // The length of the shortest path in page A (above the spine; its one reflex corner is
  // (1/2, 0) when bend > 0) between plane points p and q.
  double in_a(double px, double py, double qx, double qy) const {
    const double d = std::hypot(px - qx, py - qy);
    if (bend <= 0 || (px - 0.5) * (qx - 0.5) >= 0) return d;
    const double y_half = py + (qy - py) * (0.5 - px) / (qx - px);
    return y_half >= 0 ? d : std::hypot(px - 0.5, py) + std::hypot(qx - 0.5, qy);
  }
};

// The pieces phi_j of BT_N (junction_books.h) as functions of x: BT_N = min over j of phi_j,
// each convex on [0, 1/2] and on [1/2, 1] (distances to a point along a straight piece; the
// A-arrival across the corner is the distance via the corner, convex on each piece too).
std::vector<std::function<double(double)>> spine_pieces(const JunctionBook& book) {
  const double H = book.height_b.get_d(), W = book.width_c.get_d();
  const Spine sp(book);
  std::vector<JunctionBookSource> in_a, on_n;
  for (const auto& s : book.sources) (sgn(s.s) > 0 ? in_a : on_n).push_back(s);
  auto arrival_a = [sp](const JunctionBookSource& s, double x) {
    return s.t0.get_d() + sp.in_a(s.x.get_d(), sp.y(s.x.get_d()) + s.s.get_d(), x, sp.y(x));
  };
  auto a = [=](double x) {
    double r = kInf;
    for (const auto& s : in_a) r = std::min(r, arrival_a(s, x));
    return r;
  };
  auto o = [=](double x) {
    double r = kInf;
    for (const auto& s : on_n) r = std::min(r, s.t0.get_d() + std::abs(sp.u(x) - sp.u(s.x.get_d())));
    return r;
  };
  std::vector<std::function<double(double)>> p;
  p.push_back([=](double x) { return W + sp.y(x); });  // C's plane wave (W when straight)
  for (const auto& s : in_a) p.push_back([=](double x) { return std::max(arrival_a(s, x), H); });
  for (const auto& s : on_n) p.push_back([=](double x) { return s.t0.get_d() + std::abs(sp.u(x) - sp.u(s.x.get_d())); });
  // The ends of N: star links with f = infinity burn at their first arrival (docs/design.md 5),
  // and fire runs along N from them.
  const double e0 = std::min({H, a(0.0), o(0.0)}), e1 = std::min({H, a(1.0), o(1.0)}), end = sp.u(1.0);
  p.push_back([=](double x) { return e0 + sp.u(x); });
  p.push_back([=](double x) { return e1 + end - sp.u(x); });
  return p;
}

// min over x in [0, 1] of f, convex on [0, 1/2] and [1/2, 1]; `scan` adds a scan of 4001
// points first (for page A of a bent book, where f need not be convex).
double piecewise_minimum(const std::function<double(double)>& f, bool scan) {
  double best = std::min(golden_section_minimum(f, 0.0, 0.5),
                         golden_section_minimum(f, 0.5, 1.0));
  if (!scan) return best;
  double arg = 0;
  for (int i = 0; i <= 4000; ++i)
    if (f(i / 4000.0) < best) best = f(i / 4000.0), arg = i / 4000.0;
  const double lo = std::max(0.0, arg - 1.0 / 4000), hi = std::min(1.0, arg + 1.0 / 4000);
  return std::min(best, golden_section_minimum(f, lo, hi));
}

}  // namespace

RawComplex junction_book_complex(const JunctionBook& book) {
  RawComplex raw;
  raw.source = "junction book " + book.name;
  const ExactPoint3 a{0, 1, 0};
  const mpq_class zero(0), one(1), H = book.height_b, W = book.width_c;
  if (sgn(book.bend) != 0) {
    // Spine n0 (0, 0, 0), nm (1/2, 0, 0), n1 (1, -bend, 0); A up to y = 1, B up to z = H,
    // C down to y = -W, each in two pieces: vertices n0 nm n1, then per page (p0, pm, p1).
    const mpq_class half(1, 2);
    raw.vertices = {{zero, zero, zero}, {half, zero, zero}, {one, -book.bend, zero},
                    {zero, one, zero},  {half, one, zero},  {one, one, zero},
                    {zero, zero, H},    {half, zero, H},    {one, -book.bend, H},
                    {zero, -W, zero},   {half, -W, zero},   {one, -W, zero}};
    raw.radius_squared.assign(raw.vertices.size(), mpq_class(0));
    for (std::uint32_t p : {3u, 6u, 9u}) {
      for (std::uint32_t k : {0u, 1u}) {
        raw.triangles.push_back({k, k + 1, p + k + 1});
        raw.triangles.push_back({k, p + k + 1, p + k});
        raw.border_rules.push_back({{p + k, p + k + 1}, p == 3 ? IgnitionRule::Never : IgnitionRule::Linear, {}});
      }
      raw.border_rules.push_back({{0, p}, IgnitionRule::Never, {}});
      raw.border_rules.push_back({{2, p + 2}, IgnitionRule::Never, {}});
    }
    return raw;
  }
  raw.vertices = {{zero, zero, zero}, {one, zero, zero}, along(zero, a, one), along(one, a, one),
                  along(zero, book.b, H), along(one, book.b, H), along(zero, book.c, W), along(one, book.c, W)};
  raw.radius_squared.assign(raw.vertices.size(), mpq_class(0));
  for (std::uint32_t p : {2u, 4u, 6u}) {
    raw.triangles.push_back({0, 1, p + 1});
    raw.triangles.push_back({0, p + 1, p});
    raw.border_rules.push_back({{0, p}, IgnitionRule::Never, {}});
    raw.border_rules.push_back({{1, p + 1}, IgnitionRule::Never, {}});
    raw.border_rules.push_back({{p, p + 1}, p == 2 ? IgnitionRule::Never : IgnitionRule::Linear, {}});
  }
  return raw;
}

ExactPoint3 junction_book_point(const JunctionBook& book, const JunctionBookPoint& p) {
  const mpq_class half(1, 2);
  const mpq_class y = p.x <= half ? mpq_class(0) : mpq_class(-2 * book.bend * (p.x - half));
  const ExactPoint3 n{p.x, y, 0};
  switch (p.page) {
    case 'A': return {n.x, n.y + p.s, n.z};
    case 'B': return sgn(book.bend) != 0 ? ExactPoint3{n.x, n.y, p.s} : along(p.x, book.b, p.s);
    case 'C': return sgn(book.bend) != 0 ? ExactPoint3{n.x, n.y - p.s, n.z} : along(p.x, book.c, p.s);
    default: return n;
  }
}

double junction_book_spine_time(const JunctionBook& book, double x) {
  double r = kInf;
  for (const auto& phi : spine_pieces(book)) r = std::min(r, phi(x));
  return r;
}

double junction_book_burning_time(const JunctionBook& book, const JunctionBookPoint& p) {
  const Spine sp(book);
  const double x = p.x.get_d(), s = p.s.get_d(), y = sp.y(x);
  if (p.page == 'N' || sgn(p.s) == 0) return junction_book_spine_time(book, x);
  // d(x'): the length of the shortest path in p's page from N(x') to p (junction_books.h).
  std::function<double(double)> d;
  double direct = kInf;
  if (p.page == 'A') {
    d = [=](double xp) { return sp.in_a(xp, sp.y(xp), x, y + s); };
    for (const auto& src : book.sources)
      if (sgn(src.s) > 0)
        direct = std::min(direct, src.t0.get_d() + sp.in_a(src.x.get_d(), sp.y(src.x.get_d()) + src.s.get_d(), x, y + s));
  } else if (p.page == 'B') {
    d = [=](double xp) { return std::hypot(sp.u(x) - sp.u(xp), s); };  // B unfolded flat
    direct = book.height_b.get_d() - s;
  } else {
    // C: in the plane z = 0 below the spine when bent, else the rectangle along c
    d = [=](double xp) { return sp.bend > 0 ? std::hypot(x - xp, y - s - sp.y(xp)) : std::hypot(x - xp, s); };
    direct = book.width_c.get_d() + (sp.bend > 0 ? y : 0.0) - s;
  }
  double r = direct;
  for (const auto& phi : spine_pieces(book))
    r = std::min(r, piecewise_minimum([&](double xp) { return phi(xp) + d(xp); }, p.page == 'A' && sp.bend > 0));
  return r;
}

namespace {

mpq_class q(long n, long d) { return mpq_class(n, d); }

// Check points around a source of A at x with depth d (dip half-width 3d/4 when it starts
// at H - 5d/4): in the dip, on its ends, just outside, far along N, and in each page.
void dip_checks(JunctionBook& b, const mpq_class& x, const mpq_class& d) {
  const mpq_class w = 3 * d / 4;
  for (const mpq_class& dx : std::vector<mpq_class>{0, w / 2, -w / 2, w, -w, 2 * w, -2 * w, q(1, 10)})
    b.checks.push_back({'N', x + dx, 0});
  b.checks.push_back({'C', x, d});
  b.checks.push_back({'C', x, q(1, 100)});
  b.checks.push_back({'C', x + w / 2, d / 2});
  b.checks.push_back({'B', x, d});
  b.checks.push_back({'A', x, d / 2});
}

JunctionBook dipping(const std::string& name, const std::vector<std::pair<mpq_class, mpq_class>>& at) {
  JunctionBook b;
  b.name = name;
  for (const auto& [x, d] : at) {
    b.sources.push_back({x, d, b.height_b - 5 * d / 4});
    dip_checks(b, x, d);
  }
  return b;
}

}  // namespace

std::vector<JunctionBook> junction_books() {
  std::vector<JunctionBook> r;
  {  // the docs' six-triangle book
    JunctionBook b;
    b.name = "docs book";
    b.sources.push_back({q(3, 10), q(1, 1000), q(997, 2000)});
    for (const mpq_class& x : std::vector<mpq_class>{q(3, 10), q(3, 10) + q(1, 2000), q(3, 10) - q(1, 2000), q(3, 10) + q(1, 100),
                               q(3, 10) - q(1, 100), q(1, 2)})
      b.checks.push_back({'N', x, 0});
    b.checks.push_back({'C', q(3, 10), q(1, 100)});
    b.checks.push_back({'C', q(3, 10), q(1, 10)});
    b.checks.push_back({'A', q(3, 10), q(1, 2000)});
    b.checks.push_back({'B', q(3, 10), q(1, 10)});
    r.push_back(b);
  }
  for (long e : {1000000L, 10000L, 1000L, 100L})
    r.push_back(dipping("dip depth 1/" + std::to_string(e), {{q(37, 100), q(1, e)}}));
  r.push_back(dipping("three dips", {{q(1, 5), q(1, 10000)}, {q(1, 2), q(1, 1000)}, {q(4, 5), q(1, 100)}}));
  {  // two crossings 6e-7 apart: depth 4e-7, start H - 5e-7, a = H at x +- 3e-7
    JunctionBook b = dipping("double crossing 6e-7", {{q(3, 10), q(4, 10000000)}});
    b.checks.push_back({'N', q(3, 10) + q(1, 1000000), 0});
    b.checks.push_back({'C', q(3, 10), q(1, 1000000)});
    r.push_back(b);
  }
  {  // tangent: start H - d, a(x) >= H with equality at x only
    JunctionBook b;
    b.name = "tangent front";
    const mpq_class x = q(41, 100), d = q(1, 1000);
    b.sources.push_back({x, d, b.height_b - d});
    dip_checks(b, x, d);
    b.checks.push_back({'N', x + q(1, 100000), 0});
    r.push_back(b);
  }
  {  // pages at about 2e-3 rad on either side of A (m = 1000: (m^2 - 1, 2m) / (m^2 + 1))
    JunctionBook b = dipping("near-degenerate dihedral angles", {{q(37, 100), q(1, 1000)}});
    const mpq_class m2 = 1000000, c = (m2 - 1) / (m2 + 1), s = mpq_class(2000) / (m2 + 1);
    b.b = {0, c, s};
    b.c = {0, c, -s};
    r.push_back(b);
  }
  {  // singular edges meeting at an angle of pi - 2e-3 (bend 1/1000): a dip at the corner,
     // a source near the corner whose front to the far piece bends around it in A
    JunctionBook b = dipping("spine bent by 2e-3 rad", {{q(1, 2), q(1, 1000)}, {q(9, 20), q(1, 100)}});
    b.bend = q(1, 1000);
    for (const mpq_class& x : std::vector<mpq_class>{q(51, 100), q(11, 20), q(3, 5), q(7, 10)}) b.checks.push_back({'N', x, 0});
    b.checks.push_back({'B', q(51, 100), q(1, 100)});
    b.checks.push_back({'C', q(53, 100), q(1, 100)});
    r.push_back(b);
  }
  {  // a source on N, and one 1e-6 next to N further along
    JunctionBook b;
    b.name = "source on N and next to N";
    b.sources.push_back({q(3, 10), 0, q(9, 20)});
    b.sources.push_back({q(7, 10), q(1, 1000000), b.height_b - q(5, 4000000)});
    for (const mpq_class& x : std::vector<mpq_class>{q(3, 10), q(31, 100), q(2, 5), q(7, 10), q(7, 10) + q(3, 8000000)})
      b.checks.push_back({'N', x, 0});
    for (char page : {'A', 'B', 'C'}) b.checks.push_back({page, q(3, 10), q(1, 100)});
    b.checks.push_back({'C', q(7, 10), q(1, 100)});
    r.push_back(b);
  }
  return r;
}

}  // namespace grassfire
