// python_inputs.cpp -- see python_inputs.h.
#include "python_inputs.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "io/complex_text.h"
#include "io/decimal_text.h"
#include "io/image_raster.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"

namespace py = pybind11;

namespace grassfire::python {

namespace {

using Floats = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

Floats float_rows(const py::handle& x, py::ssize_t columns, const std::string& what) {
  const Floats a = Floats::ensure(x);
  if (!a || a.ndim() != 2 || a.shape(1) != columns)
    throw std::invalid_argument(what + " is not an (n, " + std::to_string(columns) + ") array of numbers");
  const auto m = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    for (py::ssize_t k = 0; k < columns; ++k)
      if (!std::isfinite(m(i, k)))
        throw std::invalid_argument(what + ": row " + std::to_string(i) + " has a value that is not a finite number");
  return a;
}

std::string off_text(const py::handle& vertices, const py::handle& faces, const std::string& name) {
  const Floats v = float_rows(vertices, 3, name + ": vertices");
  const Indices f = Indices::ensure(faces);
  if (!f || f.ndim() != 2 || f.shape(1) != 3) throw std::invalid_argument(name + ": faces is not an (m, 3) array of indices");
  std::ostringstream os;
  os << "OFF\n" << v.shape(0) << " " << f.shape(0) << " 0\n";
  const auto vm = v.unchecked<2>();
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    os << shortest_double(vm(i, 0)) << " " << shortest_double(vm(i, 1)) << " " << shortest_double(vm(i, 2)) << "\n";
  const auto fm = f.unchecked<2>();
  for (py::ssize_t i = 0; i < f.shape(0); ++i) os << "3 " << fm(i, 0) << " " << fm(i, 1) << " " << fm(i, 2) << "\n";
  return os.str();
}

std::string balls_text(const py::handle& balls, const std::string& name) {
  const Floats b = float_rows(balls, 4, name);
  std::ostringstream os;
  const auto m = b.unchecked<2>();
  for (py::ssize_t i = 0; i < b.shape(0); ++i) {
    if (m(i, 3) < 0) throw std::invalid_argument(name + ": row " + std::to_string(i) + " has a negative radius");
    const mpq_class r(m(i, 3));
    os << shortest_double(m(i, 0)) << " " << shortest_double(m(i, 1)) << " " << shortest_double(m(i, 2)) << " "
       << *exact_decimal_string(r * r) << "\n";
  }
  return os.str();
}

bool is_mesh_pair(const py::object& x) {
  return (py::isinstance<py::tuple>(x) || py::isinstance<py::list>(x)) && py::len(x) == 2;
}

}  // namespace

bool is_path(const py::object& x) { return py::isinstance<py::str>(x) || py::hasattr(x, "__fspath__"); }

std::string path_text(const py::object& x) { return py::module_::import("os").attr("fspath")(x).cast<std::string>(); }

// Points as burn3d takes them: None (no points), a CSV file read as the program reads it
// (io/point_csv.h: exact decimals), or an (n, columns) array of floats, each taken at its
// exact binary value; rows are named "<name>:<row from 1>" in messages.
BurnPoints points_of(const py::object& x, const std::string& name, py::ssize_t columns) {
  BurnPoints points;
  points.name = name;
  if (x.is_none()) return points;
  if (is_path(x)) {
    points.file = path_text(x);
    return points;
  }
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!a || a.ndim() != 2 || a.shape(1) != columns)
    throw std::invalid_argument(name + ": not a CSV path or an (n, " + std::to_string(columns) + ") array of " +
                                (columns == 4 ? "x, y, z, t0" : "x, y, z"));
  const auto m = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    CsvPoint row;
    row.line = static_cast<std::size_t>(i) + 1;
    for (py::ssize_t k = 0; k < columns; ++k)
      if (!std::isfinite(m(i, k)))
        throw std::invalid_argument(name + ":" + std::to_string(i + 1) + ": a value is not a finite number");
    for (int k = 0; k < 3; ++k) row.text[k] = shortest_double(m(i, k));
    row.point = {mpq_class(m(i, 0)), mpq_class(m(i, 1)), mpq_class(m(i, 2))};
    if (columns == 4) row.t0 = mpq_class(m(i, 3));
    points.rows.push_back(std::move(row));
  }
  return points;
}


InputFile::InputFile(const py::object& input, const std::string& name) : name_(name) {
  if (is_path(input)) {
    path_ = path_text(input);
    return;
  }
  std::string text, ext;
  if (py::hasattr(input, "vertices") && py::hasattr(input, "faces")) {
    text = off_text(input.attr("vertices"), input.attr("faces"), name), ext = ".off";
  } else if (is_mesh_pair(input)) {
    text = off_text(input[py::int_(0)], input[py::int_(1)], name), ext = ".off";
  } else if (py::isinstance<py::array>(input) && input.cast<py::array>().ndim() == 2) {
    text = balls_text(input, name), ext = ".balls";
  } else {
    throw std::invalid_argument(name + ": an input is a path, a synthetic complex name, a (V, F) pair of arrays, an "
                                       "object with .vertices and .faces, or an (n, 4) array of balls x, y, z, r");
  }
  std::string pattern = (std::filesystem::temp_directory_path() / "grassfire_py_XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error(name + ": cannot create a temporary folder");
  dir_ = pattern;
  path_ = dir_ + "/" + name + ext;
  std::ofstream out(path_);
  out << text;
  if (!out) throw std::runtime_error(name + ": cannot write the temporary file " + path_);
}

InputFile::~InputFile() {
  if (dir_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

std::string InputFile::message(const std::string& m) const {
  if (dir_.empty()) return m;
  const NoteAlias alias(path_, name_);
  return NoteAlias::shown(m);
}

nlohmann::json InputFile::named(nlohmann::json report) const {
  if (dir_.empty()) return report;
  if (report.is_string()) return message(report.get<std::string>());
  if (report.is_structured())
    for (auto& value : report) value = named(std::move(value));
  return report;
}

namespace {

Ring ring_of(const py::handle& points, const std::string& name, std::size_t index) {
  const Floats a = Floats::ensure(points);
  if (!a || a.ndim() != 2 || a.shape(1) != 2)
    throw std::invalid_argument(name + ": ring " + std::to_string(index) + " is not an (n, 2) array of coordinates");
  Ring r;
  const auto m = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) r.points.push_back({m(i, 0), m(i, 1)});
  // A closed ring (first point repeated last, as shapely gives it) is the same ring.
  if (r.points.size() > 1 && r.points.front().x == r.points.back().x && r.points.front().y == r.points.back().y)
    r.points.pop_back();
  return r;
}

// A shapely-like polygon: exterior.coords, then interiors[k].coords (closed rings: the
// repeated first point is dropped by validation like a closed WKT ring).
void add_polygon_rings(const py::object& polygon, const std::string& name, Shape2& s) {
  const py::module_ np = py::module_::import("numpy");
  auto coords = [&](const py::object& ring) {
    return np.attr("asarray")(ring.attr("coords"), "float64").attr("__getitem__")(
        py::make_tuple(py::slice(py::none(), py::none(), py::none()), py::slice(0, 2, 1)));
  };
  s.rings.push_back(ring_of(coords(polygon.attr("exterior")), name, 0));
  std::size_t i = 1;
  for (const py::handle ring : polygon.attr("interiors")) s.rings.push_back(ring_of(coords(py::reinterpret_borrow<py::object>(ring)), name, i++));
}

GrayAlphaImage mask_image(const py::array& mask) {
  const auto a = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(mask);
  GrayAlphaImage img;
  img.height = static_cast<std::uint32_t>(a.shape(0));
  img.width = static_cast<std::uint32_t>(a.shape(1));
  const auto m = a.unchecked<2>();
  for (py::ssize_t y = 0; y < a.shape(0); ++y)
    for (py::ssize_t x = 0; x < a.shape(1); ++x) img.gray.push_back(m(y, x) ? 0 : 255), img.alpha.push_back(255);
  return img;
}

}  // namespace

Shape2 shape_of(const py::object& shape, const std::string& name, const ImageShapeOptions& image,
                bool image_options_given, ShapeValidation* report) {
  if (is_path(shape)) return load_shape(path_text(shape), image, report);
  Shape2 s;
  s.name = name;
  if (py::isinstance<py::array>(shape) && shape.cast<py::array>().dtype().kind() == 'b' &&
      shape.cast<py::array>().ndim() == 2) {
    ImageShapeOptions o = image;
    if (!image_options_given || o.foreground == ImageForeground::Auto) o.foreground = ImageForeground::Dark;
    Shape2 traced = image_shape(mask_image(shape.cast<py::array>()), o, name);
    // As load_shape does for an image file: validating the traced rings fills the report.
    if (report) *report = validate_shape(traced, name);
    return traced;
  }
  if (py::hasattr(shape, "geoms")) {  // a multi-polygon: one polygon only, as WKT's MULTIPOLYGON
    const py::list geoms(shape.attr("geoms"));
    if (geoms.size() != 1) throw std::invalid_argument(name + ": a multi-polygon must hold exactly one polygon");
    add_polygon_rings(geoms[0], name, s);
  } else if (py::hasattr(shape, "exterior") && py::hasattr(shape, "interiors")) {
    add_polygon_rings(shape, name, s);
  } else if (py::isinstance<py::array>(shape) && shape.cast<py::array>().ndim() == 2) {
    s.rings.push_back(ring_of(shape, name, 0));
  } else if (py::isinstance<py::list>(shape) || py::isinstance<py::tuple>(shape)) {
    std::size_t i = 0;
    for (const py::handle ring : shape) s.rings.push_back(ring_of(ring, name, i++));
  } else {
    throw std::invalid_argument(name + ": a shape is a file path, a built-in name, an (n, 2) array or a list of them, "
                                       "a shapely polygon, or a 2D boolean array (an image)");
  }
  const ShapeValidation v = validate_shape(s, name);
  if (report) *report = v;
  return s;
}

mpq_class exact_threshold(const pybind11::object& x, const char* name) {
  if (pybind11::isinstance<pybind11::str>(x)) {
    const std::optional<mpq_class> q = parse_exact_decimal(x.cast<std::string>());
    if (!q)
      throw std::invalid_argument(std::string(name) + " must be a non-negative decimal number, got '" +
                                  x.cast<std::string>() + "'");
    return *q;
  }
  const double d = x.cast<double>();
  if (!std::isfinite(d)) throw std::invalid_argument(std::string(name) + " must be a finite number");
  return mpq_class(d);
}

}  // namespace grassfire::python
