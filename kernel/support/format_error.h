// format_error.h -- the one contract of every input error: a file or text that cannot be
// read as what it claims to be.
//
// what() starts with the file path (or the source name a parse_* function was given) and
// names the first problem and where it is: "<source>:<line>[:<column>]: <problem>", or
// "<source>: <problem>" when no line applies (an element index, an unreadable file). It
// never carries internal text. The readers' own classes (ShapeFormatError,
// ComplexFormatError, JsonSyntaxError, ImageFormatError, DiskListError) derive from it, so a
// caller can catch every format error at once, or one reader's. Nothing to compute.
#pragma once

#include <stdexcept>

namespace grassfire {

class FormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace grassfire
