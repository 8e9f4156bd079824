// simplest_rational.cpp -- see simplest_rational.h.
#include "number/simplest_rational.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace grassfire {

namespace {

using U = unsigned __int128;

mpq_class to_mpq(U num, U den, bool negative) {
  auto to_mpz = [](U x) {
    mpz_class z;
    const std::uint64_t parts[2] = {static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(x >> 64)};
    mpz_import(z.get_mpz_t(), 2, -1, sizeof(std::uint64_t), 0, 0, parts);
    return z;
  };
  mpq_class q(to_mpz(num), to_mpz(den));
  q.canonicalize();
  return negative ? mpq_class(-q) : q;
}

// [a, b] with 0 < a = an / ad <= b = bn / bd: the continued fraction of the simplest
// rational is the common prefix of those of a and b, then the smallest term that fits.
// Convergents h/k: terms are >= 1 after the first, so k never decreases and the final
// denominator is at least every k on the way; a term >= 2^max_bits after the first makes
// k that large. So k < 2^40 and terms < 2^40 while going on, and h <= (x + 1) k < 2^111
// (x < 2^30); the numerators never grow (Euclid), and n bd <= bn + bd.
std::optional<mpq_class> simplest_positive(U an, U ad, U bn, U bd, std::size_t max_bits, bool negative) {
  const U limit = U(1) << max_bits;
  U hp = 1, hpp = 0, kp = 0, kpp = 1;  // h_{-1}, h_{-2}, k_{-1}, k_{-2}
  for (int depth = 0; depth <= 64; ++depth) {
    const U n = (an + ad - 1) / ad;  // ceil(a)
    const bool last = n * bd <= bn;  // n <= b: the last term
    const U term = last ? n : n - 1;  // else floor(a) < b < n: go on with [1 / (b - fl), 1 / (a - fl)]
    if (kp > 0 && term >= limit) return std::nullopt;
    const U k = term * kp + kpp;
    if (k >= limit) return std::nullopt;
    const U h = term * hp + hpp;
    if (last) return to_mpq(h, k, negative);
    hpp = hp, hp = h, kpp = kp, kp = k;
    const U next_an = bd, next_ad = bn - term * bd, next_bn = ad, next_bd = an - term * ad;
    an = next_an, ad = next_ad, bn = next_bn, bd = next_bd;
  }
  return std::nullopt;
}

// x = m 2^e with the integer m (|m| < 2^53): the exponent e.
int binary_exponent(double x) {
  int e = 0;
  std::frexp(x, &e);
  return e - 53;
}

}  // namespace

std::optional<mpq_class> simplest_rational_reference(const mpq_class& lo, const mpq_class& hi, std::size_t max_bits) {
  struct Recursion {
    std::size_t max_bits;
    std::optional<mpq_class> operator()(mpq_class a, mpq_class b, int depth) const {
      if (depth > 64) return std::nullopt;
      if (sgn(a) <= 0 && sgn(b) >= 0) return mpq_class(0);
      if (sgn(b) < 0) {
        auto r = (*this)(-b, -a, depth);
        if (r) *r = -*r;
        return r;
      }
      mpz_class n;
      mpz_cdiv_q(n.get_mpz_t(), a.get_num_mpz_t(), a.get_den_mpz_t());
      if (mpq_class(n) <= b) return mpq_class(n);
      const mpq_class fl(n - 1);
      auto r = (*this)(1 / (b - fl), 1 / (a - fl), depth + 1);
      if (!r) return r;
      mpq_class out = fl + 1 / *r;
      if (mpz_sizeinbase(out.get_den_mpz_t(), 2) > max_bits) return std::nullopt;
      return out;
    }
  };
  return Recursion{max_bits}(lo, hi, 0);
}

std::optional<mpq_class> simplest_rational(double lo, double hi, std::size_t max_bits) {
  if (lo <= 0 && hi >= 0) return mpq_class(0);
  const bool negative = hi < 0;
  const double a = negative ? -hi : lo, b = negative ? -lo : hi;
  const int shift = -std::min(binary_exponent(a), binary_exponent(b));  // common denominator 2^shift
  if (max_bits < 1 || max_bits > 40 || !(b < 0x1p30) || shift > 90)
    return simplest_rational_reference(mpq_class(lo), mpq_class(hi), max_bits);
  // a, b < 2^30 with denominator 2^shift <= 2^90: numerators < 2^120.
  const U den = shift > 0 ? U(1) << shift : U(1);
  const U an = static_cast<U>(std::ldexp(a, shift > 0 ? shift : 0)), bn = static_cast<U>(std::ldexp(b, shift > 0 ? shift : 0));
  return simplest_positive(an, den, bn, den, max_bits, negative);
}

}  // namespace grassfire
