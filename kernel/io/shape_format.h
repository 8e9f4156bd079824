// shape_format.h -- what the planar shape readers and writers share: their error type,
// reading a whole file, and printing coordinates so that they read back exactly.
#pragma once

#include <stdexcept>
#include <string>

#include "support/format_error.h"
#include "support/number_text.h"  // shortest_double: coordinates that read back exactly

namespace grassfire {

// A file that cannot be read or parsed as a shape. what() starts with the file path (or
// the source name given to a parse_* function) and says where: line and column, or the
// element index.
class ShapeFormatError : public FormatError {  // support/format_error.h: the contract of what()
 public:
  using FormatError::FormatError;
};

// The whole content of a file; throws ShapeFormatError naming the path when it cannot be read.
std::string read_shape_file_text(const std::string& path);

}  // namespace grassfire
