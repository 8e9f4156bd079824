// load_shape.cpp -- see load_shape.h.
#include "io/load_shape.h"

#include <stdexcept>
#include <sys/stat.h>

#include "io/shape_json.h"
#include "io/shape_wkt.h"
#include "shapes/builtin_shapes.h"

namespace grassfire {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool file_exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

Shape2 read_shape_file(const std::string& path, const ImageShapeOptions& image) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw ShapeFormatError(path + ": is a directory");
  if (ends_with(path, ".json")) return read_shape_json(path);
  if (ends_with(path, ".wkt") || ends_with(path, ".txt")) return read_shape_wkt(path);
  if (is_image_path(path)) return image_shape(read_image(path), image, path);
  throw std::invalid_argument(path + ": unknown shape file type; use .json (the shapes2d format), .wkt / .txt "
                              "(Well-Known Text POLYGON) or .png / .gif (a binary image)");
}

std::string not_found(const std::string& arg) {
  return "'" + arg + "' is neither a shape file (.json, .wkt, .txt, .png, .gif) nor a built-in shape; the built-in shapes are: " +
         builtin_shape_names() + " (grassfire shapes describes them)";
}

}  // namespace

Shape2 load_shape(const std::string& arg, ShapeValidation* report) { return load_shape(arg, {}, report); }

Shape2 load_shape(const std::string& arg, const ImageShapeOptions& image, ShapeValidation* report) {
  const std::string prefix = "builtin:";
  Shape2 shape;
  if (arg.compare(0, prefix.size(), prefix) == 0) {
    const std::string name = arg.substr(prefix.size());
    if (!is_builtin_shape(name)) throw std::invalid_argument(not_found(name));
    shape = builtin_shape(name);
  } else if (file_exists(arg)) {
    shape = read_shape_file(arg, image);
  } else if (is_builtin_shape(arg)) {
    shape = builtin_shape(arg);
  } else if (ends_with(arg, ".json") || ends_with(arg, ".wkt") || ends_with(arg, ".txt") || is_image_path(arg)) {
    throw ShapeFormatError(arg + ": no such file");
  } else {
    throw std::invalid_argument(not_found(arg));
  }
  // Built-ins are already validated; validating again is cheap and fills the report.
  const ShapeValidation v = validate_shape(shape, shape.name);
  if (report) *report = v;
  return shape;
}

}  // namespace grassfire
