// python_values.h -- from the kernel's JSON documents and arrays to Python values.
//
// Computes: the Python value of a JSON document, with arrays made numpy arrays where that
// is what a numpy user expects:
//   - an array of numbers (and the strings "inf" / "-inf" the 2D format writes for
//     infinite values, and null) -> a 1-D numpy array: int64 when every element is an
//     integer, else float64 with inf for "inf" and nan for null;
//   - an array of equally long arrays of numbers -> a 2-D numpy array (rows);
//   - an array of objects that all have the same members -> a dict of columns, each
//     column converted by these rules (e.g. "nodes": {"x": array, "y": array, ...});
//   - anything else -> the list, dict, str, int, float, bool or None it is.
// Contract: called with the GIL held.
// Complexity: O(size of the document).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace grassfire {
class MedialComplex;
}

namespace grassfire::python {

pybind11::object to_python(const nlohmann::json& j);

pybind11::array_t<double> float_array(const std::vector<double>& values);

// A complex as numpy arrays: "vertices" (n, 3) nearest doubles, "triangles" (m, 3),
// "segments" (k, 2) (dangling edges), "R" (n,).
void add_complex(pybind11::dict& out, const MedialComplex& mc);
// Every member of a report (but `skip`) as out[key] = to_python(value).
void add_report(pybind11::dict& out, const nlohmann::json& report, const char* skip = nullptr);
// Rows of equal length: an (n, K) array.
template <class T, std::size_t K>
pybind11::array_t<T> row_array(const std::vector<std::array<T, K>>& rows) {
  pybind11::array_t<T> a({static_cast<pybind11::ssize_t>(rows.size()), static_cast<pybind11::ssize_t>(K)});
  auto m = a.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t k = 0; k < K; ++k) m(i, k) = rows[i][k];
  return a;
}

}  // namespace grassfire::python
