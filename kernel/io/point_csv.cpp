// point_csv.cpp -- see point_csv.h.
#include "io/point_csv.h"

#include "io/complex_text.h"

namespace grassfire {
namespace {

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = line.find(',', pos);
    out.push_back(trimmed(line.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos)));
    if (comma == std::string::npos) return out;
    pos = comma + 1;
  }
}

}  // namespace

std::vector<CsvPoint> parse_point_csv(const std::string& text, const std::string& source, bool with_t0) {
  const std::vector<std::string> header = with_t0 ? std::vector<std::string>{"x", "y", "z", "t0"}
                                                  : std::vector<std::string>{"x", "y", "z"};
  const std::string header_text = with_t0 ? "x,y,z,t0" : "x,y,z";
  std::vector<CsvPoint> points;
  bool seen_header = false;
  std::size_t number = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = trimmed(text.substr(pos, end - pos));
    pos = end + 1;
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = fields(line);
    if (!seen_header) {
      if (f != header) format_error(source, number, "the header must be '" + header_text + "', not '" + line + "'");
      seen_header = true;
      continue;
    }
    if (f.size() != header.size())
      format_error(source, number, std::to_string(f.size()) + " fields where '" + header_text + "' has " +
                                       std::to_string(header.size()));
    CsvPoint p;
    p.line = number;
    std::array<mpq_class, 4> value;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto q = parse_exact_decimal(f[i]);
      if (!q) format_error(source, number, header[i] + " is not a decimal number: '" + f[i] + "'");
      value[i] = *q;
    }
    p.text = {f[0], f[1], f[2]};
    p.point = {value[0], value[1], value[2]};
    if (with_t0) p.t0 = value[3];
    points.push_back(std::move(p));
  }
  if (!seen_header) format_error(source, 0, "no header line '" + header_text + "' (an empty file?)");
  return points;
}

std::vector<CsvPoint> read_point_csv(const std::string& path, bool with_t0) {
  return parse_point_csv(read_text_file(path), path, with_t0);
}

}  // namespace grassfire
