// complex_input.cpp -- see complex_input.h.
#include "pipeline/complex_input.h"

#include <stdexcept>

#include "pipeline/medial_axis_input.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"
#include "io/mesh_input.h"
#include "support/progress.h"

namespace grassfire {
namespace {

bool is_synthetic(const std::string& input) {
  for (const std::string& n : synthetic_complex_names())
    if (input == n || (n == "book:K" && input.rfind("book:", 0) == 0) || (n == "box:A:B:C" && input.rfind("box:", 0) == 0))
      return true;
  return false;
}

}  // namespace

std::string complex_input_help() {
  return "a complex (.json in the grassfire-complex format, .ma medial axis); a shape whose medial axis is built as "
         "by `grassfire medial3d`: a closed mesh (.off/.ply/.obj/.stl: exact for convex meshes, else from its inner polar "
         "balls), a half-space list (.hs) or a ball list (.cin/.balls, exact); or a synthetic complex: board-fin, "
         "board-cylinder, book:K, y-junction, tetrahedron, octahedron, double-cone, tetrahedron-flap, box:A:B:C";
}

RawComplex load_complex(const std::string& input, bool mesh_is_complex, const std::string& command,
                        const MeshRepairOptions& repair) {
  if (is_synthetic(input)) return synthetic_complex(input);
  const std::string ext = file_extension(input);
  if (ext == "json") return read_complex_json(input);
  if (ext == "ma") return read_ma(input);
  if (mesh_is_complex) {
    if (repair.enabled) throw std::runtime_error(input + ": --repair builds a medial axis; --mesh-is-complex burns the mesh as it is");
    if (!is_mesh_extension(ext))
      throw std::runtime_error(input + ": --mesh-is-complex needs a mesh (.off, .ply, .obj or .stl)");
    const TriangleMesh3 mesh = read_triangle_mesh(input);
    if (mesh.cleanup.any()) note(command + ": " + input + ": " + describe_cleanup(mesh.cleanup));
    return mesh_as_complex(mesh);
  }
  if (is_mesh_extension(ext) || ext == "hs" || ext == "halfspaces" || ext == "cin" || ext == "balls") {
    MedialAxisBuild axis = build_medial_axis(input, MedialInputKind::Auto, {}, repair);
    note(command + ": " + input + ": medial axis by the " + axis.kind + " builder");
    if (const std::string r = axis.report.value("/mesh_input/repairs"_json_pointer, ""); !r.empty())
      note(command + ": " + input + ": " + r);
    if (axis.report.contains("repair")) note(command + ": " + input + ": " + axis.report["repair"]["summary"].get<std::string>());
    return std::move(axis.complex);
  }
  std::string names;
  for (const std::string& n : synthetic_complex_names()) names += " " + n;
  throw std::runtime_error("'" + input + "' is neither a synthetic complex (" + names.substr(1) +
                           ") nor a file with extension .json, .ma, .off, .ply, .obj, .stl, .hs, .halfspaces, .cin or "
                           ".balls");
}

}  // namespace grassfire
