// shape_json.cpp -- see shape_json.h. The only file that includes nlohmann::json for shapes.
#include "io/shape_json.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/json_text.h"
#include "support/quoted.h"

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

}  // namespace

Shape2 parse_shape_json(const std::string& text, const std::string& source) {
  nlohmann::json doc;
  try {
    doc = parse_json_text(text, source);
  } catch (const JsonSyntaxError& e) {
    throw ShapeFormatError(e.what());
  }
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
    out << (i ? ",\n" : "\n") << "  {\"x\":" << shortest_double(p[i].x) << ",\"y\":" << shortest_double(p[i].y)
        << "}";
  out << "\n]}\n";
}

}  // namespace grassfire
