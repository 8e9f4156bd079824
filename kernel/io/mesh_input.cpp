// mesh_input.cpp -- see mesh_input.h.
#include "io/mesh_input.h"

#include "io/complex_text.h"

namespace grassfire {

void finish_mesh_reading(TriangleMesh3& mesh) {
  mesh.cleanup.file_vertices = mesh.vertices.size();
  weld_and_drop(mesh);
  if (mesh.triangles.empty()) {
    const std::string repaired = describe_cleanup(mesh.cleanup);
    throw ComplexFormatError(mesh.source + ": empty mesh (no vertices or no triangles" +
                             (repaired.empty() ? "" : " left after the repairs: " + repaired) + ")");
  }
}

nlohmann::json mesh_input_json(const TriangleMesh3& mesh) {
  const MeshCleanup& c = mesh.cleanup;
  return {{"file_vertices", c.file_vertices},       {"file_faces", c.file_faces},
          {"welded_vertices", c.welded_vertices},   {"unused_vertices", c.unused_vertices},
          {"degenerate_faces", c.degenerate_faces}, {"repeated_faces", c.repeated_faces},
          {"vertices", mesh.vertices.size()},       {"triangles", mesh.triangles.size()},
          {"repairs", describe_cleanup(c)}};
}

}  // namespace grassfire
