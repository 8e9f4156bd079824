// junction_kinks.cpp -- see junction_kinks.h.
#include "burn3/exact/junction_kinks.h"

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include "burn3/exact/window_values.h"
#include "number/multiquadratic.h"
#include "number/sqrt_field.h"

namespace grassfire {

ExactPoint3 edge_point_at(const MedialComplex& mc, std::uint32_t edge, const mpq_class& l) {
  const ExactPoint3& a = mc.vertex(mc.edge(edge).v[0]).exact;
  return a + l * (mc.vertex(mc.edge(edge).v[1]).exact - a);
}

namespace {

using XV = Certifier::ExactVector;


// A certified bracket [l1, l2] around `at` where sign_at changes sign (each sign certified,
// or 0 for a proved zero at that end), narrowed by bisection to about 2^-100 of its width
// (Arb decides there unless the compared values are themselves that uncertain: the bracket
// becomes the kink's rational enclosure, which the kink's own source carries into its
// windows' Arb evaluations; at 2^-50, joint.ma's kinks of kinks compounded to 1e-5).
struct Bracket {
  mpq_class lo, hi;
  bool ok = false;
};
// [lo, hi] with certified opposite signs at its ends narrowed by bisection (slo: the sign at lo).
Bracket narrowed(const std::function<int(const mpq_class&)>& sign_at, mpq_class lo, mpq_class hi, int slo) {
  for (int i = 0; i < 100; ++i) {
    const mpq_class mid((lo + hi) / 2);
    const int sm = sign_at(mid);
    if (sm == kUndecided || sm == 0) break;
    (sm == slo ? lo : hi) = mid;
  }
  return {lo, hi, true};
}
Bracket bracket(const std::function<int(const mpq_class&)>& sign_at, double at) {
  for (const double delta : {1e-6, 1e-9, 1e-3, 1e-12}) {
    mpq_class lo(std::max(0.0, at - delta)), hi(std::min(1.0, at + delta));
    const int slo = sign_at(lo), shi = sign_at(hi);
    if (slo == kUndecided || shi == kUndecided || slo == 0 || shi == 0 || slo == shi) continue;
    return narrowed(sign_at, lo, hi, slo);
  }
  return {};
}

Interval rational_enclosure(const mpq_class& lo, const mpq_class& hi) {
  const Interval a = enclose(lo), b = enclose(hi);
  return {a.lo, b.hi};
}

// Exact data of a window's time along the edge in its frame's metric: a point source
// sigma + sqrt(gamma + 2 beta lambda + l2 lambda^2), or a plane wave c0 + c1 lambda.
struct EdgeTime {
  bool line = false;
  ExactSum sigma, gamma, beta, c0, c1;
  mpq_class l2;
};

ExactSum mul(const ExactSum& a, const ExactSum& b) { return multiply_simplified(a, b); }

std::optional<EdgeTime> edge_time(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                                  std::uint32_t w) {
  const Certifier::ExactWindow* e = cert.exact_window(w);
  if (!e) return std::nullopt;
  const ExactSum* sigma = cert.exact_sigma(s.windows[w].pseudo);
  if (!sigma) return std::nullopt;
  const auto& ev = u.complex().edge(edge).v;
  const auto a = u.vertex_uv(e->frame, ev[0]), b = u.vertex_uv(e->frame, ev[1]);
  const mpq_class g1 = u.g1(e->frame), g2 = u.g2(e->frame);
  const std::array<mpq_class, 2> d{b[0] - a[0], b[1] - a[1]};
  EdgeTime t;
  t.sigma = *sigma;
  t.l2 = g1 * d[0] * d[0] + g2 * d[1] * d[1];
  if (!e->line) {
    const XV as{ExactSum::rational(a[0]) - e->s[0], ExactSum::rational(a[1]) - e->s[1]};
    t.gamma = scaled(mul(as[0], as[0]), g1) + scaled(mul(as[1], as[1]), g2);
    t.beta = scaled(as[0], g1 * d[0]) + scaled(as[1], g2 * d[1]);
    t.gamma.simplify(), t.beta.simplify();
    return t;
  }
  // distance to the line = inner * cross(D, X - p) * sqrt(g1 g2 / |D|^2) (window_certify.cpp)
  const std::optional<mpq_class> n2 = cert.line_length2(w);
  if (!n2) return std::nullopt;
  ExactSum k = ExactSum::sqrt_of(g1 * g2 / *n2);
  k.simplify();
  if (e->inner < 0) k.scale(-1);
  const XV ap{ExactSum::rational(a[0]) - e->p[0], ExactSum::rational(a[1]) - e->p[1]};
  t.line = true;
  t.c0 = *sigma + mul(k, mul(e->d[0], ap[1]) - mul(e->d[1], ap[0]));
  t.c1 = mul(k, scaled(e->d[0], d[1]) - scaled(e->d[1], d[0]));
  t.c0.simplify(), t.c1.simplify();
  return t;
}

// The exact stage is for small data (planar sheets with short rational coordinates): past
// this many bits in all the coefficients, field inverses cost too much and the certified
// enclosure is the answer.
constexpr std::size_t kMaxExactBits = 2048;
std::size_t bits(const mpq_class& q) {
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2);
}
std::size_t bits(const ExactSum& x) {
  std::size_t b = bits(x.rational_part());
  for (const SqrtTerm& t : x.sqrt_terms()) b += bits(t.coef) + bits(t.radicand);
  return b;
}

// ExactSums (without constants) as elements of one multiquadratic field.
class Field {
 public:
  bool add(const ExactSum& x) {
    if (!x.constant_terms().empty()) return false;
    for (const SqrtTerm& t : x.sqrt_terms()) basis_.adjoin(t.radicand);
    return true;
  }
  Multiquadratic of(const ExactSum& x) const {
    Multiquadratic r(basis_, x.rational_part());
    for (const SqrtTerm& t : x.sqrt_terms()) {
      QuadraticBasis copy = basis_;  // adjoin is idempotent on a known radicand
      r += Multiquadratic(basis_, t.coef) * Multiquadratic::root(basis_, copy.adjoin(t.radicand));
    }
    return r;
  }
  Multiquadratic q(const mpq_class& x) const { return Multiquadratic(basis_, x); }

 private:
  QuadraticBasis basis_;
};

// The roots of a x^2 + b x + c (a or b nonzero) as exact sums.
std::vector<ExactSum> quadratic_roots(const Field& f, const Multiquadratic& a, const Multiquadratic& b,
                                      const Multiquadratic& c) {
  if (a.is_zero()) {
    if (b.is_zero()) return {};
    return {(f.q(-1) * c * b.inverse()).to_exact_sum()};
  }
  const Multiquadratic inv2a = (f.q(2) * a).inverse();
  const Multiquadratic mid = f.q(-1) * b * inv2a;
  const Multiquadratic delta = (b * b - f.q(4) * a * c) * inv2a * inv2a;
  const ExactSum d = delta.to_exact_sum();
  const int sd = exact_sign(d);
  if (sd < 0) return {};
  if (sd == 0) return {mid.to_exact_sum()};
  const ExactSum r = root_of_sum(d);
  return {mid.to_exact_sum() - r, mid.to_exact_sum() + r};
}

// Every root of time_p - time_q along the edge line is a root of the polynomial left after
// squaring (at most two: a quadratic in lambda); returns those roots (simplified), or none
// when the data is too large for the exact stage.
std::optional<std::vector<ExactSum>> candidate_roots(const EdgeTime& p, const EdgeTime& q) {
  Field f;
  std::size_t total = 0;
  for (const EdgeTime* t : {&p, &q}) {
    total += bits(t->l2);
    for (const ExactSum* x : {&t->sigma, &t->gamma, &t->beta, &t->c0, &t->c1}) {
      total += bits(*x);
      if (total > kMaxExactBits || !f.add(*x)) return std::nullopt;
    }
  }
  std::vector<ExactSum> roots;
  if (p.line && q.line) {
    roots = quadratic_roots(f, f.q(0), f.of(p.c1) - f.of(q.c1), f.of(p.c0) - f.of(q.c0));
  } else if (p.line != q.line) {
    // sqrt(P) = m0 + m1 lambda with P the point's quadratic: P - (m0 + m1 lambda)^2 = 0.
    const EdgeTime& pt = p.line ? q : p;
    const EdgeTime& ln = p.line ? p : q;
    const Multiquadratic m0 = f.of(ln.c0) - f.of(pt.sigma), m1 = f.of(ln.c1);
    roots = quadratic_roots(f, f.q(pt.l2) - m1 * m1, f.q(2) * f.of(pt.beta) - f.q(2) * m0 * m1,
                            f.of(pt.gamma) - m0 * m0);
  } else {
    // sqrt(Pp) - sqrt(Pq) = D: (l - D^2)^2 = 4 D^2 Pq with l = Pp - Pq linear.
    const Multiquadratic D = f.of(q.sigma) - f.of(p.sigma);
    const Multiquadratic l0 = f.of(p.gamma) - f.of(q.gamma), l1 = f.q(2) * (f.of(p.beta) - f.of(q.beta));
    if (D.is_zero()) {
      roots = quadratic_roots(f, f.q(0), l1, l0);
    } else {
      const Multiquadratic D2 = D * D, m = l0 - D2;
      roots = quadratic_roots(f, l1 * l1 - f.q(4) * D2 * f.q(q.l2), f.q(2) * l1 * m - f.q(8) * D2 * f.of(q.beta),
                              m * m - f.q(4) * D2 * f.of(q.gamma));
    }
  }
  for (ExactSum& r : roots) r.simplify();
  return roots;
}

std::optional<ExactSum> exact_crossing(const EdgeTime& p, const EdgeTime& q, const Bracket& br) {
  std::optional<std::vector<ExactSum>> candidates = candidate_roots(p, q);
  if (!candidates) return std::nullopt;
  std::vector<ExactSum>& roots = *candidates;
  // The crossing is the only candidate inside the certified bracket.
  // Roots with a certified constant (a square root that does not denest) are placed by
  // their enclosure only, and not kept as exact values (exact_sign cannot take them).
  std::optional<ExactSum> found;
  bool irrational = false;
  for (ExactSum& r : roots) {
    int in;
    if (r.constant_terms().empty()) {
      in = exact_sign(r - ExactSum::rational(br.lo)) > 0 && exact_sign(ExactSum::rational(br.hi) - r) > 0;
    } else {
      const Interval e = r.approx(), lo = enclose(br.lo), hi = enclose(br.hi);
      if (e.lo > lo.hi && e.hi < hi.lo) in = 1;
      else if (e.hi < lo.lo || e.lo > hi.hi) in = 0;
      else return std::nullopt;
    }
    if (!in) continue;
    if (found) return std::nullopt;
    irrational = !r.constant_terms().empty();
    found = std::move(r);
  }
  if (irrational) return std::nullopt;
  return found;
}

}  // namespace

bool identical_along_edge(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                          std::uint32_t wa, std::uint32_t wb) {
  if (cert.front_id(wa) == cert.front_id(wb)) return true;  // one front in one frame
  const auto p = edge_time(u, s, cert, edge, wa);
  const auto q = p ? edge_time(u, s, cert, edge, wb) : std::nullopt;
  if (!p || !q || p->line != q->line) return false;
  // Each difference proved 0 (the double enclosure rejects the others at once).
  auto zero = [](const ExactSum& a, const ExactSum& b) {
    if (!a.constant_terms().empty() || !b.constant_terms().empty()) return false;
    const ExactSum d = a - b;
    const int fast = certified_sign(d.approx());
    if (fast == 1 || fast == -1) return false;
    return exact_sign(d) == 0;
  };
  if (p->line) return zero(p->c0, q->c0) && zero(p->c1, q->c1);
  return p->l2 == q->l2 && zero(p->beta, q->beta) && zero(p->sigma, q->sigma) && zero(p->gamma, q->gamma);
}

std::optional<std::vector<ExactSum>> crossing_candidates(const Unfolding& u, const WindowStore& s, Certifier& cert,
                                                         std::uint32_t edge, std::uint32_t wa, std::uint32_t wb) {
  const auto p = edge_time(u, s, cert, edge, wa);
  const auto q = p ? edge_time(u, s, cert, edge, wb) : std::nullopt;
  if (!p || !q) return std::nullopt;
  try {
    return candidate_roots(*p, *q);
  } catch (const std::length_error&) {  // past the field's generator limit
    return std::nullopt;
  }
}

std::vector<double> approx_crossings(const Unfolding& u, const WindowStore& s, std::uint32_t edge, std::uint32_t wa,
                                     std::uint32_t wb, double lo, double hi) {
  // Only certified sign changes count: two windows equal along a stretch (ties, e.g. a
  // kink's own source beyond the kink) have no crossing there, whatever the rounding says.
  constexpr int kSamples = 32;
  const EdgeImage ea(u, s.windows[wa], edge), eb(u, s.windows[wb], edge);
  auto g = [&](double l) { return certified_sign(ea.time(s.windows[wa], l) - eb.time(s.windows[wb], l)); };
  std::vector<double> roots;
  double x0 = lo;
  int g0 = g(lo);
  for (int i = 1; i <= kSamples; ++i) {
    const double x1 = lo + (hi - lo) * i / kSamples;
    const int g1 = g(x1);
    if (g1 == kUndecided || g1 == 0) continue;
    if (g0 != kUndecided && g0 != 0 && g1 != g0) {
      double a = x0, b = x1;
      for (int k = 0; k < 80; ++k) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        const int gm = g(m);
        if (gm == kUndecided || gm == 0) break;
        (gm == g0 ? a : b) = m;
      }
      if (a > lo && b < hi) roots.push_back(0.5 * (a + b));
    }
    x0 = x1, g0 = g1;
  }
  return roots;
}

namespace {

// The crossing's parameter from a certified bracket: its rational enclosure, and the exact
// root of the squared equation that is the only candidate inside it, where one is found.
KinkParameter crossing_in(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                          std::uint32_t wa, std::uint32_t wb, const Bracket& br) {
  KinkParameter k;
  k.certified = true;
  k.lambda = rational_enclosure(br.lo, br.hi);
  k.bracket = std::array<mpq_class, 2>{br.lo, br.hi};
  const auto p = edge_time(u, s, cert, edge, wa);
  const auto q = p ? edge_time(u, s, cert, edge, wb) : std::nullopt;
  if (!p || !q) return k;
  try {
    k.exact = exact_crossing(*p, *q, br);
  } catch (const std::length_error&) {  // past the field's generator limit
    k.exact.reset();
  }
  if (k.exact) {
    const Interval e = k.exact->approx();
    k.lambda = {std::max(k.lambda.lo, e.lo), std::min(k.lambda.hi, e.hi)};
  }
  return k;
}

// The sign of time(wa) - time(wb) at the edge point l: outside the Newton enclosure of a
// root proved unique on [lo0, hi0] (Certifier::crossing_root_on_edge), that root's side;
// elsewhere the staged comparison.
std::function<int(const mpq_class&)> crossing_sign(const Unfolding& u, Certifier& cert, std::uint32_t edge,
                                                   std::uint32_t wa, std::uint32_t wb, double lo0, double hi0) {
  auto root = std::make_shared<std::optional<Certifier::EdgeRoot>>(
      lo0 < hi0 ? cert.crossing_root_on_edge(wa, wb, edge, lo0, hi0, 256) : std::nullopt);
  const mpq_class qlo(lo0), qhi(hi0);
  const MedialComplex& mc = u.complex();
  return [=, &cert, &mc](const mpq_class& l) {
    if (*root && qlo <= l && l <= qhi) {
      if (l < (*root)->lo) return -(*root)->slope;
      if (l > (*root)->hi) return (*root)->slope;
    }
    const ExactPoint3 p = edge_point_at(mc, edge, l);
    const Target x{kNoIndex, &p, 0, edge, &l};
    return cert.compare_times(wa, x, wb, x, true);
  };
}

}  // namespace

KinkParameter kink_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                             std::uint32_t wa, std::uint32_t wb, double at) {
  const Bracket br =
      bracket(crossing_sign(u, cert, edge, wa, wb, std::max(0.0, at - 1e-6), std::min(1.0, at + 1e-6)), at);
  if (!br.ok) {
    KinkParameter k;
    k.lambda = Interval(at);
    return k;
  }
  return crossing_in(u, s, cert, edge, wa, wb, br);
}

KinkParameter kink_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                             std::uint32_t wa, std::uint32_t wb, const mpq_class& lo, const mpq_class& hi) {
  if (lo == hi) {  // a proved zero at a rational
    KinkParameter k;
    k.certified = true;
    k.lambda = enclose(lo);
    k.bracket = std::array<mpq_class, 2>{lo, hi};
    k.exact = ExactSum::rational(lo);
    return k;
  }
  const auto sign_at = crossing_sign(u, cert, edge, wa, wb, lo.get_d(), hi.get_d());
  const int slo = sign_at(lo);
  if (slo != 1 && slo != -1) {  // certified by the isolation at max_bits; not again at 256 bits
    KinkParameter k = crossing_in(u, s, cert, edge, wa, wb, {lo, hi, true});
    return k;
  }
  return crossing_in(u, s, cert, edge, wa, wb, narrowed(sign_at, lo, hi, slo));
}

KinkParameter ray_parameter(const Unfolding& u, const WindowStore& s, Certifier& cert, std::uint32_t edge,
                            std::uint32_t w, std::uint32_t bound_vertex, double at) {
  const MedialComplex& mc = u.complex();
  KinkParameter k;
  const Window& W = s.windows[w];
  const int j = W.bound[0] == bound_vertex ? 0 : 1;
  if (const Certifier::ExactWindow* e = W.root() ? nullptr : cert.exact_window(w)) {
    const auto& ev = mc.edge(edge).v;
    const auto a = u.vertex_uv(e->frame, ev[0]), b = u.vertex_uv(e->frame, ev[1]);
    const std::array<mpq_class, 2> d{b[0] - a[0], b[1] - a[1]};
    const XV& B = e->image[j];
    ExactSum num, den;
    if (!e->line) {  // cross(B - S, A - S) + lambda cross(B - S, d) = 0
      const XV bs{B[0] - e->s[0], B[1] - e->s[1]};
      const XV as{ExactSum::rational(a[0]) - e->s[0], ExactSum::rational(a[1]) - e->s[1]};
      num = mul(bs[0], as[1]) - mul(bs[1], as[0]);
      den = scaled(bs[0], d[1]) - scaled(bs[1], d[0]);
    } else {  // metric_dot(D, A - B) + lambda metric_dot(D, d) = 0
      const mpq_class g1 = u.g1(e->frame), g2 = u.g2(e->frame);
      num = mul(e->d[0], ExactSum::rational(a[0]) - B[0]);
      num.scale(g1);
      ExactSum n1 = mul(e->d[1], ExactSum::rational(a[1]) - B[1]);
      n1.scale(g2);
      num += n1;
      den = scaled(e->d[0], g1 * d[0]) + scaled(e->d[1], g2 * d[1]);
    }
    num.simplify(), den.simplify();
    Field f;
    if (bits(num) + bits(den) <= kMaxExactBits && f.add(num) && f.add(den)) {
      try {
        const Multiquadratic dn = f.of(den);
        if (!dn.is_zero()) {
          ExactSum l = (f.q(-1) * f.of(num) * dn.inverse()).to_exact_sum();
          l.simplify();
          k.lambda = l.approx();
          k.exact = std::move(l);
          k.certified = true;
          return k;
        }
      } catch (const std::length_error&) {
      }
    }
  }
  // The side function is affine along the edge: one Arb evaluation encloses its root, and
  // gives the certified sign at every point outside that enclosure (what side_if_certified
  // would certify there); points inside it are decided as before.
  const std::optional<Certifier::EdgeRoot> root = cert.ray_root_on_edge(w, j, edge, 256);
  const Bracket br = bracket(
      [&](const mpq_class& l) {
        if (root && l < root->lo) return -root->slope;
        if (root && l > root->hi) return root->slope;
        const ExactPoint3 p = edge_point_at(mc, edge, l);
        return cert.side_if_certified(w, j, Target{kNoIndex, &p, 0, edge, &l}, true);  // undecided: the bisection stops
      },
      at);
  k.certified = br.ok;
  k.lambda = br.ok ? rational_enclosure(br.lo, br.hi) : Interval(at);
  if (br.ok) k.bracket = std::array<mpq_class, 2>{br.lo, br.hi};
  return k;
}

}  // namespace grassfire
