// shape_json.cpp -- see shape_json.h. The only file that includes nlohmann::json for shapes.
#include "io/shape_json.h"

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/quoted.h"

namespace grassfire {

namespace {

double coordinate(const nlohmann::json& point, const char* axis, std::size_t index, const std::string& source) {
  const std::string where = source + ": points[" + std::to_string(index) + "]";
  const auto it = point.find(axis);
  if (it == point.end()) throw ShapeFormatError(where + " has no \"" + axis + "\" member");
  if (!it->is_number()) throw ShapeFormatError(where + "." + axis + " is not a number (" + shorten_token(it->dump()) + ")");
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw ShapeFormatError(where + "." + axis + " is not a finite number");
  return v;
}

// nlohmann quotes the input it stopped at ("last read: '<token>'", "number overflow parsing
// '<token>'", maybe followed by "; expected ..."); a long token is shown shortened.
std::string shorten_quoted_input(const std::string& reason) {
  for (const char* opener : {"last read: '", "parsing '"}) {
    const std::size_t at = reason.find(opener);
    if (at == std::string::npos) continue;
    const std::size_t from = at + std::strlen(opener) - 1;
    std::size_t to = reason.rfind("'; expected");
    if (to == std::string::npos || to < from) to = reason.back() == '\'' ? reason.size() - 1 : std::string::npos;
    if (to == std::string::npos || to <= from) continue;
    return reason.substr(0, from) + quote_token(reason.substr(from + 1, to - from - 1)) + reason.substr(to + 1);
  }
  return reason;
}

// Builds the document like nlohmann's own DOM parser, but reports every parse error (syntax,
// or a number that overflows to infinity) with the line and column of its byte offset.
class PositionedDomParser {
 public:
  PositionedDomParser(nlohmann::json& doc, const std::string& text, const std::string& source)
      : dom_(doc), text_(text), source_(source) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(nlohmann::json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(nlohmann::json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(nlohmann::json::number_float_t v, const std::string& s) { return dom_.number_float(v, s); }
  bool string(std::string& v) { return dom_.string(v); }
  bool binary(nlohmann::json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) { return dom_.start_object(n); }
  bool key(std::string& k) { return dom_.key(k); }
  bool end_object() { return dom_.end_object(); }
  bool start_array(std::size_t n) { return dom_.start_array(n); }
  bool end_array() { return dom_.end_array(); }

  bool parse_error(std::size_t offset, const std::string& /*token*/, const nlohmann::detail::exception& e) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < offset && i < text_.size(); ++i) {
      column = text_[i] == '\n' ? 1 : column + 1;
      line += text_[i] == '\n';
    }
    // e.what() is "[json.exception.<kind>.<id>] [parse error at line L, column C: ]<reason>".
    std::string reason = e.what();
    reason = reason.substr(reason.find("] ") + 2);
    if (reason.rfind("parse error", 0) == 0) reason = reason.substr(reason.find(": ") + 2);
    reason = shorten_quoted_input(reason);
    throw ShapeFormatError(source_ + ":" + std::to_string(line) + ":" + std::to_string(column) +
                           ": invalid JSON: " + reason);
  }

 private:
  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
  const std::string& text_;
  const std::string& source_;
};

}  // namespace

Shape2 parse_shape_json(const std::string& text, const std::string& source) {
  nlohmann::json doc;
  PositionedDomParser parser(doc, text, source);
  nlohmann::json::sax_parse(text, &parser);
  if (!doc.is_object()) throw ShapeFormatError(source + ": the JSON value is not an object with a \"points\" member");
  const auto points = doc.find("points");
  if (points == doc.end()) throw ShapeFormatError(source + ": no \"points\" member");
  if (!points->is_array()) throw ShapeFormatError(source + ": \"points\" is not an array");
  Shape2 shape;
  shape.name = source;
  Ring ring;
  for (std::size_t i = 0; i < points->size(); ++i) {
    const nlohmann::json& p = (*points)[i];
    if (!p.is_object())
      throw ShapeFormatError(source + ": points[" + std::to_string(i) + "] is not an object {\"x\":..,\"y\":..}");
    ring.points.push_back({coordinate(p, "x", i, source), coordinate(p, "y", i, source)});
  }
  shape.rings.push_back(std::move(ring));
  return shape;
}

Shape2 read_shape_json(const std::string& path) { return parse_shape_json(read_shape_file_text(path), path); }

void write_shape_json(const Shape2& shape, std::ostream& out) {
  if (shape.rings.size() != 1)
    throw std::invalid_argument(shape.name + ": the JSON shape format holds exactly one ring; this shape has " +
                                std::to_string(shape.rings.size()) + " (write it as WKT)");
  out << "{\"points\":[";
  const std::vector<Point2>& p = shape.rings[0].points;
  for (std::size_t i = 0; i < p.size(); ++i)
    out << (i ? ",\n" : "\n") << "  {\"x\":" << format_coordinate(p[i].x) << ",\"y\":" << format_coordinate(p[i].y)
        << "}";
  out << "\n]}\n";
}

}  // namespace grassfire
