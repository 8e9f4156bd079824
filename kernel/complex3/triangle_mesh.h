// triangle_mesh.h -- a triangle mesh in R^3 with double coordinates, as read from OFF, PLY
// or OBJ files (kernel/io/mesh_io.h) and handed to the mesh -> approximate medial axis
// builder. No connectivity is derived here; readers guarantee finite coordinates, indices
// in range and three distinct vertices per triangle.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace grassfire {

struct TriangleMesh3 {
  std::string source;  // file name or generator, for messages
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace grassfire
