// decimal_text.cpp -- see decimal_text.h.
#include "io/decimal_text.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include <mpfr.h>

namespace grassfire {

std::optional<mpq_class> parse_exact_decimal(const std::string& s, long max_exponent) {
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  std::string digits;
  long fraction_digits = 0;
  bool any = false;
  for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) digits += s[i], any = true;
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i)
      digits += s[i], ++fraction_digits, any = true;
  }
  if (!any || digits.size() > kMaxDecimalDigits) return std::nullopt;
  long exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) eneg = s[i++] == '-';
    std::string e;
    for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) e += s[i];
    if (e.empty() || e.size() > 6) return std::nullopt;
    exponent = std::stol(e) * (eneg ? -1 : 1);
    if (exponent > max_exponent || exponent < -max_exponent) return std::nullopt;
  }
  if (i != s.size()) return std::nullopt;
  const long power = exponent - fraction_digits;
  if (power > 4000 || power < -4000) return std::nullopt;
  mpz_class num(digits, 10), scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(power)));
  mpq_class q = power >= 0 ? mpq_class(num * scale) : mpq_class(num, scale);
  q.canonicalize();
  return negative ? mpq_class(-q) : q;
}

std::optional<double> parse_finite_double(const std::string& s) {
  if (!parse_exact_decimal(s)) return std::nullopt;  // the same syntax, no nan/inf/hex
  const double d = std::strtod(s.c_str(), nullptr);  // correctly rounded (glibc)
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

double nearest_double(const mpq_class& q) {
  mpfr_t x;
  mpfr_init2(x, 53);
  mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  const double d = mpfr_get_d(x, MPFR_RNDN);
  mpfr_clear(x);
  return d;
}

std::optional<DecimalValue> parse_decimal_value(const std::string& s) {
  std::optional<mpq_class> q = parse_exact_decimal(s);
  if (!q) return std::nullopt;
  const double d = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(d)) return std::nullopt;
  return DecimalValue{std::move(*q), d};
}

}  // namespace grassfire
