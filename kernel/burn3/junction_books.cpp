// junction_books.cpp -- the closed-form three-page books (junction_books.h).
#include "burn3/junction_books.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace grassfire {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ExactPoint3 along(const mpq_class& x, const ExactPoint3& dir, const mpq_class& s) {
  return {x + s * dir.x, s * dir.y, s * dir.z};
}

// min over x' in [0, 1] of f(x') for a convex f (golden-section search).
double convex_minimum(const std::function<double(double)>& f) {
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double lo = 0.0, hi = 1.0;
  double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
  double f1 = f(m1), f2 = f(m2);
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    if (f1 <= f2) {
      hi = m2, m2 = m1, f2 = f1, m1 = hi - g * (hi - lo), f1 = f(m1);
    } else {
      lo = m1, m1 = m2, f1 = f2, m2 = lo + g * (hi - lo), f2 = f(m2);
    }
  }
  return std::min({f(lo), f(hi), f1, f2});
}

// The convex pieces phi_j of BT_N (junction_books.h): BT_N = min over j of phi_j.
std::vector<std::function<double(double)>> spine_pieces(const JunctionBook& book) {
  const double H = book.height_b.get_d(), W = book.width_c.get_d();
  std::vector<JunctionBookSource> in_a, on_n;
  for (const auto& s : book.sources) (sgn(s.s) > 0 ? in_a : on_n).push_back(s);
  auto a = [in_a](double x) {
    double r = kInf;
    for (const auto& s : in_a) r = std::min(r, s.t0.get_d() + std::hypot(x - s.x.get_d(), s.s.get_d()));
    return r;
  };
  auto o = [on_n](double x) {
    double r = kInf;
    for (const auto& s : on_n) r = std::min(r, s.t0.get_d() + std::abs(x - s.x.get_d()));
    return r;
  };
  std::vector<std::function<double(double)>> p;
  p.push_back([W](double) { return W; });
  for (const auto& s : in_a) {
    const double xi = s.x.get_d(), si = s.s.get_d(), ti = s.t0.get_d();
    p.push_back([=](double x) { return std::max(ti + std::hypot(x - xi, si), H); });
  }
  for (const auto& s : on_n) {
    const double xi = s.x.get_d(), ti = s.t0.get_d();
    p.push_back([=](double x) { return ti + std::abs(x - xi); });
  }
  // The ends of N: star links with f = infinity burn at their first arrival (DESIGN.md 5),
  // and fire runs along N from them.
  const double e0 = std::min({H, a(0.0), o(0.0)}), e1 = std::min({H, a(1.0), o(1.0)});
  p.push_back([e0](double x) { return e0 + x; });
  p.push_back([e1](double x) { return e1 + 1.0 - x; });
  return p;
}

}  // namespace

RawComplex junction_book_complex(const JunctionBook& book) {
  RawComplex raw;
  raw.source = "junction book " + book.name;
  const ExactPoint3 a{0, 1, 0};
  const mpq_class zero(0), one(1), H = book.height_b, W = book.width_c;
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
  switch (p.page) {
    case 'A': return along(p.x, ExactPoint3{0, 1, 0}, p.s);
    case 'B': return along(p.x, book.b, p.s);
    case 'C': return along(p.x, book.c, p.s);
    default: return along(p.x, ExactPoint3{0, 1, 0}, mpq_class(0));
  }
}

double junction_book_spine_time(const JunctionBook& book, double x) {
  double r = kInf;
  for (const auto& phi : spine_pieces(book)) r = std::min(r, phi(x));
  return r;
}

double junction_book_burning_time(const JunctionBook& book, const JunctionBookPoint& p) {
  const double x = p.x.get_d(), s = p.s.get_d();
  if (p.page == 'N' || sgn(p.s) == 0) return junction_book_spine_time(book, x);
  double direct = kInf;
  if (p.page == 'B') direct = book.height_b.get_d() - s;
  if (p.page == 'C') direct = book.width_c.get_d() - s;
  if (p.page == 'A')
    for (const auto& src : book.sources)
      direct = std::min(direct, src.t0.get_d() + std::hypot(x - src.x.get_d(), s - src.s.get_d()));
  double r = direct;
  for (const auto& phi : spine_pieces(book))
    r = std::min(r, convex_minimum([&](double xp) { return phi(xp) + std::hypot(x - xp, s); }));
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
