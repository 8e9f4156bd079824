// python_inputs.h -- the inputs Python users hold, turned into what the kernel's pipelines read.
//
// 3D (complex_input): a path (str or os.PathLike) or a synthetic complex name, used as is; a
// mesh as a (V, F) pair of arrays (V (n, 3) floats, F (m, 3) integer indices) or any object
// with `.vertices` and `.faces` (trimesh, meshio-like); balls as an (n, 4) array of x, y, z,
// r. Arrays are written, each float at its exact binary value (shortest round-trip decimals;
// a ball's r^2 as the exact decimal of the square), to a temporary .off or .balls file that
// the pipeline reads as the program would read it, so the semantics and the checks are the
// program's; the file is removed afterwards and messages name the array (`name`) instead.
// 2D (shape_of): paths and built-in names; (n, 2) arrays and lists of them (outer ring, then
// holes); shapely-like polygons (`.exterior.coords`, `.interiors`; a multi-polygon of one
// polygon); 2D boolean arrays (True = foreground, row 0 at the top, as an image file's
// pixels, shapes/image_shape.h).
// Contract: called with the GIL held; errors are std::invalid_argument naming `name`.
// Complexity: linear in the input.
#pragma once

#include <gmpxx.h>
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>

#include "pipeline/burn3d.h"
#include "support/progress.h"
#include "shapes/image_shape.h"
#include "shapes/validate_shape.h"
#include "geometry2/shape2.h"

namespace grassfire::python {

// A 3D input as a path for the pipelines; owns the temporary file it may have written.
class InputFile {
 public:
  InputFile(const pybind11::object& input, const std::string& name);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  const std::string& path() const { return path_; }
  // `message` with the temporary path replaced by the array's name.
  std::string message(const std::string& message) const;
  // A report with the temporary path replaced by the array's name in every string.
  nlohmann::json named(nlohmann::json report) const;
  // Runs f (without the GIL), its notes and progress lines naming the array
  // (support/progress.h NoteAlias), and rethrows its errors with messages naming the array.
  template <class F>
  auto run(F f) const -> decltype(f()) {
    try {
      const NoteAlias alias(dir_.empty() ? std::string() : path_, name_);
      pybind11::gil_scoped_release release;
      return f();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(message(e.what()));
    } catch (const std::exception& e) {
      throw std::runtime_error(message(e.what()));
    }
  }

 private:
  std::string path_, dir_, name_;
};

// A threshold as the program reads it (a decimal string, exactly) or a float at its exact
// binary value; `name` names the argument in the error.
mpq_class exact_threshold(const pybind11::object& x, const char* name);

bool is_path(const pybind11::object& x);
std::string path_text(const pybind11::object& x);

// Points as burn3d and paths3d take them: None (no points), a CSV file read as the program
// reads it (io/point_csv.h: exact decimals), or an (n, columns) array of floats (columns 3:
// x, y, z; 4: x, y, z, t0), each taken at its exact binary value; rows are named
// "<name>:<row from 1>" in messages.
BurnPoints points_of(const pybind11::object& x, const std::string& name, pybind11::ssize_t columns);

// With `report`, the validation's description (shapes/validate_shape.h) as load_shape gives it.
Shape2 shape_of(const pybind11::object& shape, const std::string& name, const ImageShapeOptions& image,
                bool image_options_given, ShapeValidation* report = nullptr);

}  // namespace grassfire::python
