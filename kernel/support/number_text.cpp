// number_text.cpp -- see number_text.h.
#include "support/number_text.h"

#include <charconv>

namespace grassfire {

std::string shortest_double(double x) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace grassfire
