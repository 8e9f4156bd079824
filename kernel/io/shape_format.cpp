// shape_format.cpp -- see shape_format.h.
#include "io/shape_format.h"

#include <charconv>
#include <fstream>
#include <sstream>

namespace grassfire {

std::string read_shape_file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ShapeFormatError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ShapeFormatError(path + ": read error");
  return text.str();
}

}  // namespace grassfire
