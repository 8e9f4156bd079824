// complex_ma.cpp -- reading and writing .ma medial-axis files (see header).
#include "io/complex_ma.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <set>

#include "support/atomic_file.h"
#include "io/complex_text.h"
#include "support/quoted.h"

namespace grassfire {
namespace {

std::uint32_t index_field(const TextLine& l, std::size_t i, std::uint64_t nv, const std::string& source) {
  const auto v = parse_index(l.tokens[i]);
  if (!v) format_error(source, l.number, quote_token(l.tokens[i]) + " is not a vertex index");
  if (*v >= nv) format_error(source, l.number, "vertex index " + l.tokens[i] + " out of range (" + std::to_string(nv) + " vertices)");
  return static_cast<std::uint32_t>(*v);
}

mpq_class number_field(const TextLine& l, std::size_t i, const std::string& source) {
  const auto q = parse_exact_decimal(l.tokens[i]);
  if (!q) format_error(source, l.number, quote_token(l.tokens[i]) + " is not a finite decimal number");
  return *q;
}

void expect_fields(const TextLine& l, std::size_t n, const std::string& what, const std::string& source) {
  if (l.tokens.size() != n)
    format_error(source, l.number,
                 what + " needs " + std::to_string(n - 1) + " values, found " + std::to_string(l.tokens.size() - 1));
}

// sqrt(q) exactly when q is the square of a rational.
std::optional<mpq_class> exact_sqrt(const mpq_class& q) {
  if (sgn(q) < 0 || !mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t())) return std::nullopt;
  return mpq_class(sqrt(mpz_class(q.get_num())), sqrt(mpz_class(q.get_den())));
}

}  // namespace

RawComplex parse_ma(const std::string& text, const std::string& source) {
  const std::vector<TextLine> lines = tokenize_lines(text);
  if (lines.empty()) format_error(source, 0, "empty file (no header 'nv ne nf')");
  const TextLine& head = lines.front();
  if (head.tokens.size() != 3) format_error(source, head.number, "header must be 'nv ne nf'");
  std::uint64_t counts[3];
  for (int i = 0; i < 3; ++i) {
    const auto c = parse_index(head.tokens[i]);
    if (!c) format_error(source, head.number, "header count " + quote_token(head.tokens[i]) + " is not a non-negative integer");
    counts[i] = *c;
  }
  if (counts[0] == 0) format_error(source, head.number, "no vertices (nv = 0)");
  RawComplex raw;
  raw.source = source;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::uint64_t seen[3] = {0, 0, 0};
  for (std::size_t n = 1; n < lines.size(); ++n) {
    const TextLine& l = lines[n];
    const std::string& tag = l.tokens[0];
    if (tag == "v") {
      expect_fields(l, 5, "vertex line 'v x y z r'", source);
      raw.vertices.push_back({number_field(l, 1, source), number_field(l, 2, source), number_field(l, 3, source)});
      const mpq_class r = number_field(l, 4, source);
      if (sgn(r) < 0) format_error(source, l.number, "negative radius " + shorten_token(l.tokens[4]));
      raw.radius_squared.push_back(r * r);
      ++seen[0];
    } else if (tag == "e") {
      expect_fields(l, 3, "edge line 'e i j'", source);
      const std::uint32_t a = index_field(l, 1, counts[0], source), b = index_field(l, 2, counts[0], source);
      if (a == b) format_error(source, l.number, "edge from vertex " + l.tokens[1] + " to itself");
      edges.push_back({std::min(a, b), std::max(a, b)});
      ++seen[1];
    } else if (tag == "f") {
      if (l.tokens.size() != 4)
        format_error(source, l.number, "face with " + std::to_string(l.tokens.size() - 1) + " vertices; .ma faces must be triangles");
      raw.triangles.push_back({index_field(l, 1, counts[0], source), index_field(l, 2, counts[0], source),
                               index_field(l, 3, counts[0], source)});
      ++seen[2];
    } else {
      format_error(source, l.number, "unknown line tag " + quote_token(tag) + " (expected v, e or f)");
    }
  }
  const char* names[3] = {"vertices", "edges", "faces"};
  for (int i = 0; i < 3; ++i)
    if (seen[i] != counts[i])
      format_error(source, head.number, "header says " + std::to_string(counts[i]) + " " + names[i] + ", the file has " +
                                            std::to_string(seen[i]));
  std::set<std::array<std::uint32_t, 2>> face_edges;
  for (const auto& t : raw.triangles)
    for (int i = 0; i < 3; ++i) face_edges.insert({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& e : edges)
    if (!face_edges.count(e)) raw.segments.push_back(e);
  return raw;
}

RawComplex read_ma(const std::string& path) { return parse_ma(read_text_file(path), path); }

bool write_ma(const RawComplex& c, std::ostream& out) {
  std::set<std::array<std::uint32_t, 2>> edges;
  for (const auto& t : c.triangles)
    for (int i = 0; i < 3; ++i) edges.insert({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  for (const auto& s : c.segments) edges.insert({std::min(s[0], s[1]), std::max(s[0], s[1])});
  bool exact = true;
  auto number = [&](const mpq_class& q) {
    auto s = exact_decimal_string(q);
    exact = exact && s.has_value();
    return s ? *s : shortest_double(q.get_d());
  };
  out << c.vertices.size() << ' ' << edges.size() << ' ' << c.triangles.size() << '\n';
  for (std::size_t v = 0; v < c.vertices.size(); ++v) {
    const auto r = exact_sqrt(c.radius_squared[v]);
    std::string rs;
    if (r) {
      rs = number(*r);
    } else {
      exact = false;
      rs = shortest_double(std::sqrt(c.radius_squared[v].get_d()));
    }
    out << "v " << number(c.vertices[v].x) << ' ' << number(c.vertices[v].y) << ' ' << number(c.vertices[v].z) << ' '
        << rs << '\n';
  }
  for (const auto& e : edges) out << "e " << e[0] << ' ' << e[1] << '\n';
  for (const auto& t : c.triangles) out << "f " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return exact;
}

bool write_ma_file(const RawComplex& c, const std::string& path) {
  std::ostringstream out;
  const bool exact = write_ma(c, out);
  try {
    write_file_atomically(path, out.str());  // never a partial file
  } catch (const std::runtime_error& e) {
    throw ComplexFormatError(e.what());
  }
  return exact;
}

}  // namespace grassfire
