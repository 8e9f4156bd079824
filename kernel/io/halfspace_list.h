// halfspace_list.h -- the half-space text format (.hs): a convex polyhedron as a list of
// half-spaces, the input of medial3/convex/convex_polyhedron_axis.h.
//
// Format: one plane `a b c d` per line, meaning a x + b y + c z <= d; decimals as in
// complex_text.h, read exactly; `#` starts a comment; blank lines are ignored.
// Errors (ComplexFormatError) name the file and line: not four numbers, a field that is
// not a finite decimal, a zero normal, no half-space at all.
// Complexity: O(total characters).
#pragma once

#include <string>

#include "medial3/convex/convex_polyhedron_axis.h"

namespace grassfire {

ConvexPolyhedron parse_halfspaces(const std::string& text, const std::string& source);
ConvexPolyhedron read_halfspaces(const std::string& path);

}  // namespace grassfire
