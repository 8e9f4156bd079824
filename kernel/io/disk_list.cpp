// disk_list.cpp -- see disk_list.h.
#include "io/disk_list.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/decimal_text.h"
#include "support/quoted.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {

constexpr long kMaxExponent = 300;  // a written exponent beyond: refused (every disk has a double)

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
    for (int k = 0; k < 3; ++k) {
      const std::optional<mpq_class> q = parse_exact_decimal(f[k], kMaxExponent);
      if (!q)
        fail(std::string(names[k]) + " = " + quote_token(f[k]) +
             " is not a decimal number (at most 1000 digits, an optional point and an exponent of at most 300)");
      *targets[k] = *q;
    }
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
