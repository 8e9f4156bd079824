// complex_json.cpp -- see complex_json.h.
#include "io/complex_json.h"

#include <cctype>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "support/atomic_file.h"
#include "io/complex_text.h"
#include "io/json_text.h"
#include "support/quoted.h"

namespace grassfire {
namespace {

using Json = nlohmann::json;

const char* kFormat = "grassfire-complex";

class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw ComplexFormatError(source_ + ": " + where + ": " + problem);
  }

  static std::string shown(const Json& v) {
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
  }

  const Json& array(const Json& v, const std::string& where, std::size_t length = 0) const {
    if (!v.is_array()) fail(where, "is not an array (" + shown(v) + ")");
    if (length > 0 && v.size() != length)
      fail(where, "has " + std::to_string(v.size()) + " entries, not " + std::to_string(length));
    return v;
  }

  mpq_class number(const Json& v, const std::string& where) const {
    if (v.is_number_integer()) {
      // number_integer / number_unsigned: nlohmann's exact 64-bit integers.
      return v.is_number_unsigned() ? mpq_class(mpz_class(std::to_string(v.get<std::uint64_t>())))
                                    : mpq_class(mpz_class(std::to_string(v.get<std::int64_t>())));
    }
    if (!v.is_string()) fail(where, "is not a number (" + shown(v) + ")");
    const auto q = parse_rational_text(v.get<std::string>(), true);
    if (!q) fail(where, "is not an exact number: " + shown(v) + " (a decimal, or \"p/q\" with integers p, q > 0)");
    return *q;
  }

  ExactPoint3 point(const Json& v, const std::string& where) const {
    array(v, where, 3);
    return {number(v[0], where + "[0]"), number(v[1], where + "[1]"), number(v[2], where + "[2]")};
  }

  std::uint32_t index(const Json& v, const std::string& where, std::size_t vertex_count) const {
    if (!v.is_number_integer()) fail(where, "is not a vertex index (" + shown(v) + ")");
    if (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() < 0)
      fail(where, "is a negative vertex index (" + shown(v) + ")");
    const std::uint64_t i = v.get<std::uint64_t>();
    if (i >= vertex_count)
      fail(where, "vertex index " + std::to_string(i) + " is out of range (" + std::to_string(vertex_count) +
                      " vertices)");
    return static_cast<std::uint32_t>(i);
  }

  template <std::size_t N>
  std::vector<std::array<std::uint32_t, N>> cells(const Json& doc, const char* name, std::size_t vertex_count) const {
    std::vector<std::array<std::uint32_t, N>> out;
    const auto it = doc.find(name);
    if (it == doc.end()) return out;
    array(*it, name);
    for (std::size_t c = 0; c < it->size(); ++c) {
      const std::string where = std::string(name) + "[" + std::to_string(c) + "]";
      array((*it)[c], where, N);
      std::array<std::uint32_t, N> cell{};
      for (std::size_t k = 0; k < N; ++k)
        cell[k] = index((*it)[c][k], where + "[" + std::to_string(k) + "]", vertex_count);
      out.push_back(cell);
    }
    return out;
  }

  BorderIgnition border_rule(const Json& v, const std::string& where, std::size_t vertex_count) const {
    if (!v.is_object()) fail(where, "is not an object {\"edge\": [i, j], \"rule\": ...} (" + shown(v) + ")");
    for (const auto& [key, value] : v.items())
      if (key != "edge" && key != "rule" && key != "point") fail(where, "unknown member \"" + shorten_token(key) + "\"");
    BorderIgnition b;
    const auto edge = v.find("edge");
    if (edge == v.end()) fail(where, "has no \"edge\"");
    array(*edge, where + ".edge", 2);
    b.edge = {index((*edge)[0], where + ".edge[0]", vertex_count), index((*edge)[1], where + ".edge[1]", vertex_count)};
    if (b.edge[0] == b.edge[1]) fail(where + ".edge", "repeats vertex " + std::to_string(b.edge[0]));
    const auto rule = v.find("rule");
    if (rule == v.end()) fail(where, "has no \"rule\"");
    const std::string name = rule->is_string() ? rule->get<std::string>() : std::string();
    if (name == "linear") b.rule = IgnitionRule::Linear;
    else if (name == "never") b.rule = IgnitionRule::Never;
    else if (name == "point") b.rule = IgnitionRule::DistanceToPoint;
    else fail(where + ".rule", "is " + shown(*rule) + ", not \"linear\", \"never\" or \"point\"");
    const auto p = v.find("point");
    if (b.rule == IgnitionRule::DistanceToPoint) {
      if (p == v.end()) fail(where, "has rule \"point\" but no \"point\"");
      b.point = point(*p, where + ".point");
    } else if (p != v.end()) {
      fail(where, "has a \"point\" but rule \"" + name + "\" (only rule \"point\" takes one)");
    }
    return b;
  }

  RawComplex complex(const Json& doc) const {
    if (!doc.is_object()) fail("document", "is not a JSON object");
    for (const auto& [key, value] : doc.items())
      if (key != "format" && key != "version" && key != "vertices" && key != "radius_squared" &&
          key != "triangles" && key != "segments" && key != "border" && key != "source" && key != "comment")
        fail(shorten_token(key), "unknown member (a typo? the members are format, version, vertices, radius_squared, "
                  "triangles, segments, border, source, comment)");
    const auto format = doc.find("format");
    if (format == doc.end() || *format != kFormat)
      fail("format", format == doc.end() ? "missing (expected \"grassfire-complex\")"
                                          : "is " + shown(*format) + ", not \"grassfire-complex\"");
    const auto version = doc.find("version");
    if (version == doc.end() || *version != 1)
      fail("version", version == doc.end() ? "missing (expected 1)" : "is " + shown(*version) + "; this reader knows 1");
    RawComplex raw;
    raw.source = source_;
    const auto vertices = doc.find("vertices");
    if (vertices == doc.end()) fail("vertices", "missing");
    array(*vertices, "vertices");
    if (vertices->empty()) fail("vertices", "is empty: a complex needs at least one vertex");
    for (std::size_t v = 0; v < vertices->size(); ++v)
      raw.vertices.push_back(point((*vertices)[v], "vertices[" + std::to_string(v) + "]"));
    const std::size_t nv = raw.vertices.size();
    raw.radius_squared.assign(nv, mpq_class(0));
    if (const auto r2 = doc.find("radius_squared"); r2 != doc.end()) {
      array(*r2, "radius_squared", nv);
      for (std::size_t v = 0; v < nv; ++v) {
        const std::string where = "radius_squared[" + std::to_string(v) + "]";
        raw.radius_squared[v] = number((*r2)[v], where);
        if (sgn(raw.radius_squared[v]) < 0) fail(where, "is negative (" + shown((*r2)[v]) + ")");
      }
    }
    raw.triangles = cells<3>(doc, "triangles", nv);
    raw.segments = cells<2>(doc, "segments", nv);
    if (const auto border = doc.find("border"); border != doc.end()) {
      array(*border, "border");
      for (std::size_t i = 0; i < border->size(); ++i)
        raw.border_rules.push_back(border_rule((*border)[i], "border[" + std::to_string(i) + "]", nv));
    }
    return raw;
  }

 private:
  const std::string& source_;
};

std::string point_json(const ExactPoint3& p) {
  return "[" + rational_json(p.x) + ", " + rational_json(p.y) + ", " + rational_json(p.z) + "]";
}

template <std::size_t N>
void write_cells(std::ostringstream& os, const char* name, const std::vector<std::array<std::uint32_t, N>>& cells) {
  os << ",\n \"" << name << "\": [";
  for (std::size_t c = 0; c < cells.size(); ++c) {
    os << (c ? ",\n  [" : "\n  [");
    for (std::size_t k = 0; k < N; ++k) os << (k ? ", " : "") << cells[c][k];
    os << "]";
  }
  os << (cells.empty() ? "]" : "\n ]");
}

const char* rule_name(IgnitionRule r) {
  return r == IgnitionRule::Linear ? "linear" : r == IgnitionRule::Never ? "never" : "point";
}

}  // namespace

std::optional<mpq_class> parse_rational_text(const std::string& text, bool allow_fraction) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return parse_exact_decimal(text);
  if (!allow_fraction) return std::nullopt;
  const std::string p = text.substr(0, slash), q = text.substr(slash + 1);
  auto digits = [](const std::string& s, std::size_t from) {
    if (s.size() <= from) return false;
    for (std::size_t i = from; i < s.size(); ++i)
      if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    return true;
  };
  const bool signed_p = !p.empty() && (p[0] == '-' || p[0] == '+');
  if (!digits(p, signed_p ? 1 : 0) || !digits(q, 0)) return std::nullopt;
  const mpz_class den(q, 10);
  if (den == 0) return std::nullopt;
  mpq_class r(mpz_class(p.substr(p[0] == '+' ? 1 : 0), 10), den);
  r.canonicalize();
  return r;
}

std::string rational_json(const mpq_class& q) {
  // JSON parsers refuse number tokens beyond the double range: quote those.
  static const mpq_class kHuge(mpz_class("1" + std::string(300, '0')));
  if (auto s = exact_decimal_string(q)) return abs(q) < kHuge ? *s : "\"" + *s + "\"";
  return "\"" + q.get_str() + "\"";
}

RawComplex parse_complex_json(const std::string& text, const std::string& source) {
  Json doc;
  try {
    doc = parse_json_text(text, source, {true, true});
  } catch (const JsonSyntaxError& e) {
    throw ComplexFormatError(e.what());
  }
  return Reader(source).complex(doc);
}

RawComplex read_complex_json(const std::string& path) { return parse_complex_json(read_text_file(path), path); }

std::string complex_json_text(const RawComplex& raw) {
  if (raw.radius_squared.size() != raw.vertices.size())
    throw std::invalid_argument(raw.source + ": radius_squared has " + std::to_string(raw.radius_squared.size()) +
                                " values for " + std::to_string(raw.vertices.size()) + " vertices");
  std::ostringstream os;
  os << "{\"format\": \"" << kFormat << "\", \"version\": 1,\n \"source\": " << Json(raw.source).dump() << ",\n"
     << " \"vertices\": [";
  for (std::size_t v = 0; v < raw.vertices.size(); ++v) os << (v ? ",\n  " : "\n  ") << point_json(raw.vertices[v]);
  os << "\n ],\n \"radius_squared\": [";
  for (std::size_t v = 0; v < raw.radius_squared.size(); ++v) os << (v ? ", " : "") << rational_json(raw.radius_squared[v]);
  os << "]";
  write_cells(os, "triangles", raw.triangles);
  write_cells(os, "segments", raw.segments);
  os << ",\n \"border\": [";
  for (std::size_t i = 0; i < raw.border_rules.size(); ++i) {
    const BorderIgnition& b = raw.border_rules[i];
    os << (i ? ",\n  " : "\n  ") << "{\"edge\": [" << b.edge[0] << ", " << b.edge[1] << "], \"rule\": \""
       << rule_name(b.rule) << "\"";
    if (b.rule == IgnitionRule::DistanceToPoint) os << ", \"point\": " << point_json(b.point);
    os << "}";
  }
  os << (raw.border_rules.empty() ? "]" : "\n ]") << "}\n";
  return os.str();
}

void write_complex_json(const RawComplex& raw, const std::string& path) {
  write_file_atomically(path, complex_json_text(raw));
}

}  // namespace grassfire
