// triangle_mesh.h -- a triangle mesh in R^3 with double coordinates, as read from OFF, PLY,
// OBJ or STL files (kernel/io/mesh_io.h) and handed to the mesh -> medial axis builders.
// No connectivity is derived here. Readers guarantee finite coordinates, indices in range,
// three distinct vertices per triangle, no two vertices at the same point, every vertex
// used, no two triangles on the same three vertices; what they repaired on the way
// (exactly repeated vertices welded, degenerate and repeated faces dropped) is counted in
// `cleanup`, and `vertex_origin` / `triangle_origin` map back to the file's own numbering
// so that messages name the elements a user can find in the file.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace grassfire {

// What a reader repaired (mesh_io.h, weld_and_drop). All zero for a mesh built in code.
struct MeshCleanup {
  std::size_t file_vertices = 0;     // vertices listed in the file (STL: 3 per facet)
  std::size_t file_faces = 0;        // faces listed in the file (a polygon counts once)
  std::size_t welded_vertices = 0;   // merged into an earlier vertex at exactly the same point
  std::size_t unused_vertices = 0;   // distinct points on no kept triangle, dropped
  std::size_t degenerate_faces = 0;  // faces (or fan triangles) with < 3 distinct vertices, dropped
  std::size_t repeated_faces = 0;    // triangles on the same three vertices as an earlier one, dropped
  bool any() const { return welded_vertices + unused_vertices + degenerate_faces + repeated_faces > 0; }
};

struct TriangleMesh3 {
  std::string source;  // file name or generator, for messages
  std::vector<std::array<double, 3>> vertices;
  // The coordinates the file wrote, exactly (io/decimal_text.h: a decimal is the rational it
  // writes; `vertices` holds their nearest doubles), one per vertex; empty when the doubles
  // are the exact coordinates (binary files, meshes built in code).
  std::vector<std::array<mpq_class, 3>> exact_vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // The file's 0-based index of each vertex (the first of its welded copies; STL numbers the
  // corners of facet f as 3 f, 3 f + 1, 3 f + 2) and of the face each triangle comes from.
  // Empty: the identity (meshes built in code).
  std::vector<std::uint32_t> vertex_origin;
  std::vector<std::uint32_t> triangle_origin;
  MeshCleanup cleanup;
};

inline std::uint32_t file_vertex_index(const TriangleMesh3& m, std::uint32_t v) {
  return v < m.vertex_origin.size() ? m.vertex_origin[v] : v;
}
inline std::uint32_t file_face_index(const TriangleMesh3& m, std::uint32_t t) {
  return t < m.triangle_origin.size() ? m.triangle_origin[t] : t;
}

}  // namespace grassfire
