// disk_list.cpp -- see disk_list.h.
#include "io/disk_list.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/quoted.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {

constexpr long kMaxExponent = 300;
constexpr std::size_t kMaxDigits = 1000;  // as the 3D readers (io/complex_text.h): exact arithmetic stays fast

bool all_digits(const std::string& s) {
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Splits a line (comment removed) into fields separated by blanks or commas.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::string current;
  for (char c : line) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
      if (!current.empty()) fields.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) fields.push_back(current);
  return fields;
}

}  // namespace

bool parse_exact_decimal(const std::string& token, mpq_class& value) {
  std::size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) negative = token[i++] == '-';
  const std::size_t e = token.find_first_of("eE", i);
  const std::string mantissa = token.substr(i, e == std::string::npos ? std::string::npos : e - i);
  const std::size_t dot = mantissa.find('.');
  const std::string whole = mantissa.substr(0, dot);
  const std::string fraction = dot == std::string::npos ? "" : mantissa.substr(dot + 1);
  if (whole.empty() && fraction.empty()) return false;
  if (whole.size() + fraction.size() > kMaxDigits) return false;
  if (!all_digits(whole) || !all_digits(fraction)) return false;
  long exponent = 0;
  if (e != std::string::npos) {
    std::string digits = token.substr(e + 1);
    bool exp_negative = false;
    if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) {
      exp_negative = digits[0] == '-';
      digits.erase(0, 1);
    }
    if (digits.empty() || !all_digits(digits) || digits.size() > 6) return false;
    exponent = std::stol(digits) * (exp_negative ? -1 : 1);
    if (exponent > kMaxExponent || exponent < -kMaxExponent) return false;
  }
  exponent -= static_cast<long>(fraction.size());
  mpz_class n(whole + fraction, 10);
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(exponent < 0 ? -exponent : exponent));
  value = exponent < 0 ? make_rational(n, scale) : mpq_class(n * scale);
  if (negative) value = -value;
  return true;
}

DiskList parse_disk_list(const std::string& text, const std::string& source) {
  DiskList list;
  list.name = source;
  std::istringstream in(text);
  std::string line;
  std::size_t number = 0;
  auto fail = [&](const std::string& what) {
    throw DiskListError(source + ":" + std::to_string(number) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++number;
    const std::vector<std::string> f = fields_of(line.substr(0, line.find('#')));
    if (f.empty()) continue;
    if (f.size() != 3)
      fail("expected three numbers 'x y r', found " + std::to_string(f.size()) + " field" +
           (f.size() == 1 ? "" : "s"));
    Disk d;
    d.line = number;
    const char* names[3] = {"x", "y", "r"};
    mpq_class* targets[3] = {&d.x, &d.y, &d.r};
    for (int k = 0; k < 3; ++k)
      if (!parse_exact_decimal(f[k], *targets[k]))
        fail(std::string(names[k]) + " = " + quote_token(f[k]) +
             " is not a decimal number (at most 1000 digits, an optional point and an exponent of at most 300)");
    if (sgn(d.r) <= 0) fail("radius r = " + shorten_token(f[2]) + " must be positive");
    list.disks.push_back(std::move(d));
  }
  if (list.disks.empty()) throw DiskListError(source + ": no disks (one 'x y r' line per disk)");
  return list;
}

DiskList read_disk_list(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw DiskListError(path + ": is a directory, not a disk list");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DiskListError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw DiskListError(path + ": read error");
  return parse_disk_list(text.str(), path);
}

}  // namespace grassfire
