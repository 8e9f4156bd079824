// complex_input.h -- the complex a 3D command works on, from its INPUT argument.
//
// INPUT is a synthetic complex name (synthetic_complexes.h), a grassfire-complex JSON file
// (.json, io/complex_json.h), a .ma medial axis, a mesh burned as itself
// (mesh_is_complex, .off/.ply/.obj), or a shape whose medial axis is built as
// `grassfire medial3d` builds it (pipeline/medial_axis_input.h: convex meshes and
// half-spaces exactly, ball lists exactly, other closed meshes through their inner polar
// balls). Errors name the input; nothing is written. `grassfire burn3d`, `grassfire complex`
// and the Python module's grassfire.burn3d read their INPUT through it.
// Complexity: that of the reader or builder the input selects.
// Section: docs/design.md 5 (the complexes of ch. 4).
#pragma once

#include <string>

#include "medial3/mesh/mesh_repair.h"
#include "complex3/raw_complex.h"

namespace grassfire {

// `command` prefixes the line that says which builder made a medial axis (stderr), and the
// line that says how a defective mesh was repaired (`repair`, medial3/mesh/mesh_repair.h;
// not with mesh_is_complex, which burns the mesh as it is).
RawComplex load_complex(const std::string& input, bool mesh_is_complex, const std::string& command,
                        const MeshRepairOptions& repair = {});
// The help text of INPUT for the commands that take one.
std::string complex_input_help();

}  // namespace grassfire
