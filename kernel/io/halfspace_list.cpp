// halfspace_list.cpp -- see halfspace_list.h.
#include "io/halfspace_list.h"

#include <array>

#include "io/complex_text.h"
#include "support/quoted.h"

namespace grassfire {

ConvexPolyhedron parse_halfspaces(const std::string& text, const std::string& source) {
  ConvexPolyhedron p;
  p.source = source;
  for (const TextLine& line : tokenize_lines(text)) {
    if (line.tokens.size() != 4) format_error(source, line.number, "expected four numbers `a b c d` (a x + b y + c z <= d)");
    std::array<mpq_class, 4> v;
    for (int k = 0; k < 4; ++k) {
      const auto q = parse_exact_decimal(line.tokens[k]);
      if (!q) format_error(source, line.number, "not a finite decimal number: " + quote_token(line.tokens[k]));
      v[k] = *q;
    }
    if (sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0)
      format_error(source, line.number, "the normal (a, b, c) is zero");
    p.planes.push_back({v[0], v[1], v[2], v[3]});
  }
  if (p.planes.empty()) format_error(source, 0, "no half-spaces");
  return p;
}

ConvexPolyhedron read_halfspaces(const std::string& path) { return parse_halfspaces(read_text_file(path), path); }

}  // namespace grassfire
