// match_svg.h -- pictures of boundary signatures and of a boundary correspondence (3.5.3,
// Fig. 3.9): each shape's outer boundary drawn as a thick curve coloured by a signature,
// and lines joining marked samples of the first shape to the samples of the second that
// the matching assigns them.
//
// Computes: SVG through render/svg_medial2.h's frame and heat colours (blue = low, red = high),
// each signature normalised by its own range. Display only, no decision.
// Contract: each signature was sampled on the outer ring of its shape; `match` pairs
// samples of a with samples of b (apps2d/boundary_matching.h). Complexity: O(samples).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "apps2d/boundary_matching.h"
#include "render/svg_medial2.h"

namespace grassfire {

// The signature along the boundary as coloured segments between consecutive samples,
// coloured by the value at the segment's start, mapped from [lo, hi].
void draw_signature(SvgCanvas& c, const Medial2Frame& f, const BoundarySignature& s, double lo, double hi,
                    double width);

// Two panels side by side, shape a left and b right (the shapes filled light grey), their
// signatures, and for every index i in `marked` (samples of a) a dot on both boundaries
// and a line from a's sample i to the sample of b matched to it, in a distinct hue.
std::string match_svg(const Shape2& a, const BoundarySignature& sa, const Shape2& b, const BoundarySignature& sb,
                      const BoundaryMatch& match, const std::vector<std::uint32_t>& marked, const std::string& title,
                      double width = 1000);

}  // namespace grassfire
