// complex_text.cpp -- shared tokenising and exact decimals for the 3D formats.
#include "io/complex_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace grassfire {

void format_error(const std::string& source, std::size_t line, const std::string& problem) {
  throw ComplexFormatError(source + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ComplexFormatError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ComplexFormatError(path + ": read error");
  return ss.str();
}

std::vector<TextLine> tokenize_lines(const std::string& text, char comment) {
  std::vector<TextLine> lines;
  std::size_t number = 0, pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    ++number;
    std::string line = text.substr(pos, end - pos);
    if (comment != 0) {
      const std::size_t c = line.find(comment);
      if (c != std::string::npos) line.resize(c);
    }
    std::istringstream ls(line);
    TextLine tl;
    tl.number = number;
    for (std::string tok; ls >> tok;) tl.tokens.push_back(tok);
    if (!tl.tokens.empty()) lines.push_back(std::move(tl));
    pos = end + 1;
  }
  return lines;
}

std::optional<std::uint64_t> parse_index(const std::string& s) {
  if (s.empty() || s.size() > 18) return std::nullopt;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  return std::stoull(s);
}

std::optional<std::string> exact_decimal_string(const mpq_class& q) {
  mpz_class den = q.get_den();
  long twos = 0, fives = 0;
  while (mpz_divisible_ui_p(den.get_mpz_t(), 2)) den /= 2, ++twos;
  while (mpz_divisible_ui_p(den.get_mpz_t(), 5)) den /= 5, ++fives;
  if (den != 1) return std::nullopt;
  const long digits = std::max(twos, fives);
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(digits));
  const mpz_class scaled = q.get_num() * (scale / q.get_den());
  std::string s = mpz_class(abs(scaled)).get_str();
  if (digits > 0) {
    if (s.size() <= static_cast<std::size_t>(digits)) s.insert(0, static_cast<std::size_t>(digits) - s.size() + 1, '0');
    s.insert(s.size() - static_cast<std::size_t>(digits), ".");
  }
  return (sgn(scaled) < 0 ? "-" : "") + s;
}

std::string decimal_or_nearest(const mpq_class& q) {
  if (auto s = exact_decimal_string(q)) return *s;
  return shortest_double(q.get_d());
}

}  // namespace grassfire
