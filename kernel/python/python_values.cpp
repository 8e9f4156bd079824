// python_values.cpp -- see python_values.h.
#include "python_values.h"

#include "complex3/medial_complex.h"

#include <cmath>
#include <limits>
#include <string>

namespace py = pybind11;

namespace grassfire::python {

namespace {

enum class NumberKind { None, Integer, Real };

// Whether every element is a number (or "inf", "-inf", null); integers only if no element
// needs a double. None when an element is anything else.
NumberKind number_kind(const nlohmann::json& a) {
  NumberKind kind = NumberKind::Integer;
  for (const nlohmann::json& e : a) {
    if (e.is_number_integer()) {
      continue;
    } else if (e.is_number_float()) {
      kind = NumberKind::Real;
    } else if (e.is_null() || (e.is_string() && (e == "inf" || e == "-inf"))) {
      kind = NumberKind::Real;
    } else {
      return NumberKind::None;
    }
  }
  return kind;
}

double real_of(const nlohmann::json& e) {
  if (e.is_number()) return e.get<double>();
  if (e.is_null()) return std::numeric_limits<double>::quiet_NaN();
  return e == "inf" ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
}

py::object number_array(const nlohmann::json& a, NumberKind kind) {
  if (kind == NumberKind::Integer) {
    py::array_t<std::int64_t> out(static_cast<py::ssize_t>(a.size()));
    auto m = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < a.size(); ++i) m(i) = a[i].get<std::int64_t>();
    return std::move(out);
  }
  py::array_t<double> out(static_cast<py::ssize_t>(a.size()));
  auto m = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < a.size(); ++i) m(i) = real_of(a[i]);
  return std::move(out);
}

// Rows of numbers of one length: an (n, k) array; None when the array is not such rows.
py::object matrix(const nlohmann::json& a) {
  if (a.empty() || !a[0].is_array() || a[0].empty()) return py::none();
  const std::size_t k = a[0].size();
  NumberKind kind = NumberKind::Integer;
  for (const nlohmann::json& row : a) {
    if (!row.is_array() || row.size() != k) return py::none();
    const NumberKind r = number_kind(row);
    if (r == NumberKind::None) return py::none();
    if (r == NumberKind::Real) kind = NumberKind::Real;
  }
  nlohmann::json flat = nlohmann::json::array();
  for (const nlohmann::json& row : a)
    for (const nlohmann::json& e : row) flat.push_back(e);
  return number_array(flat, kind).attr("reshape")(a.size(), k);
}

// Objects that all have the same members: a dict of columns; None otherwise.
py::object columns(const nlohmann::json& a) {
  if (a.empty() || !a[0].is_object()) return py::none();
  for (const nlohmann::json& e : a) {
    if (!e.is_object() || e.size() != a[0].size()) return py::none();
    for (const auto& item : a[0].items())
      if (!e.contains(item.key())) return py::none();
  }
  py::dict out;
  for (const auto& item : a[0].items()) {
    nlohmann::json column = nlohmann::json::array();
    for (const nlohmann::json& e : a) column.push_back(e[item.key()]);
    out[py::str(item.key())] = to_python(column);
  }
  return std::move(out);
}

}  // namespace

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& item : j.items()) d[py::str(item.key())] = to_python(item.value());
      return std::move(d);
    }
    case nlohmann::json::value_t::array: {
      if (j.empty()) return py::array_t<double>(0);
      const NumberKind kind = number_kind(j);
      if (kind != NumberKind::None) return number_array(j, kind);
      py::object m = matrix(j);
      if (!m.is_none()) return m;
      py::object c = columns(j);
      if (!c.is_none()) return c;
      py::list l;
      for (const nlohmann::json& e : j) l.append(to_python(e));
      return std::move(l);
    }
    default:
      return py::none();  // binary and discarded values never occur in the kernel's documents
  }
}

py::array_t<double> float_array(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  auto m = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < values.size(); ++i) m(i) = values[i];
  return a;
}

void add_complex(py::dict& out, const MedialComplex& mc) {
  std::vector<std::array<double, 3>> vertices;
  std::vector<double> radius;
  for (const ComplexVertex& v : mc.vertices()) vertices.push_back(v.approx), radius.push_back(v.radius);
  std::vector<std::array<std::int64_t, 3>> triangles;
  for (const ComplexTriangle& t : mc.triangles()) triangles.push_back({t.v[0], t.v[1], t.v[2]});
  std::vector<std::array<std::int64_t, 2>> segments;
  for (const ComplexEdge& e : mc.edges())
    if (e.stratum == EdgeStratum::Dangling) segments.push_back({e.v[0], e.v[1]});
  out["vertices"] = row_array(vertices);
  out["triangles"] = row_array(triangles);
  out["segments"] = row_array(segments);
  out["R"] = float_array(radius);
}

void add_report(py::dict& out, const nlohmann::json& report, const char* skip) {
  for (const auto& item : report.items())
    if (!skip || item.key() != skip) out[py::str(item.key())] = to_python(item.value());
}


}  // namespace grassfire::python
