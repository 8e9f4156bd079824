// mesh_input.h -- what every mesh reader does last, and the report of what it read.
//
// finish_mesh_reading: records the file's vertex count, welds and drops
// (geometry3/mesh_weld.h), and rejects a mesh with no triangle left with a
// ComplexFormatError naming the file and what was dropped. mesh_input_json: the counts of
// that cleanup for the JSON reports (medial3d's "mesh_input").
// Complexity: O(n log n) for n vertices and triangles (the weld).
#pragma once

#include <nlohmann/json.hpp>

#include "geometry3/mesh_weld.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

// What every mesh reader does last: records file_vertices, weld_and_drop, and rejects a
// mesh with no triangle left (ComplexFormatError naming the file and what was dropped).
void finish_mesh_reading(TriangleMesh3& mesh);

// {"file_vertices", "file_faces", "welded_vertices", "unused_vertices", "degenerate_faces",
//  "repeated_faces", "vertices", "triangles", "repairs": describe_cleanup}: what was read,
// for the JSON reports (medial3d's "mesh_input").
nlohmann::json mesh_input_json(const TriangleMesh3& mesh);

}  // namespace grassfire
