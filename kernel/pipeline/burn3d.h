// burn3d.h -- the 3D burning pipeline: input -> medial complex -> burning time BT, ET = BT - R.
//
// Computes: the complex an input names (load_burn_complex), its burning time by the
// discrete baseline (burn3/discrete_burning.h) at a spacing chosen as `grassfire burn3d`
// chooses it, and the JSON report the program writes with --json (format below). This is
// what `grassfire burn3d` and the Python module's grassfire.burn3d run, so the two agree.
// Report (the members `grassfire burn3d --json` writes for the discrete method without
// sources or queries): {"input", "method", "spacing", "complex": {counts}, "sources": 0,
// "queries": 0, "stats": {spacing, steiner_points, arrivals_pushed, arrivals_popped,
// seconds}, "summary": {burned_vertices,
// unburned_vertices, max_bt, max_et}, "vertex_values": {"x", "y", "z", "R", "BT", "ET"}}
// with null for BT and ET where nothing burns.
// Contract: errors are exceptions whose message names the input and the problem.
// Complexity: that of the builder (for shapes) plus that of burn_discrete.
// Section: ch. 4 (Definitions 9-10), DESIGN.md 5.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "burn3/discrete_burning.h"
#include "complex3/medial_complex.h"
#include "complex3/raw_complex.h"

namespace grassfire {

// The complex to burn: a synthetic complex name (complex3/synthetic_complexes.h), a .ma
// medial axis, a mesh burned as itself (mesh_is_complex), or the medial axis of a shape
// built as `grassfire medial3d` builds it (complex3/builders/medial_axis_input.h).
RawComplex load_burn_complex(const std::string& input, bool mesh_is_complex);

// 1/100 of the diagonal of the complex's bounding box (1 for a single point).
double default_burn_spacing(const MedialComplex& mc);

struct Burn3dOptions {
  std::optional<double> spacing;  // Steiner spacing h; none: default_burn_spacing
  std::uint64_t max_points = 50'000'000;
};

// The discrete baseline with the options' spacing; std::invalid_argument for a spacing
// that is not a positive finite number.
DiscreteBurning burn3d_discrete(const MedialComplex& mc, const Burn3dOptions& options);

nlohmann::json burn3d_report(const std::string& input, const MedialComplex& mc, const DiscreteBurning& d);

}  // namespace grassfire
