// mesh_io.h -- triangle meshes (OFF, PLY, OBJ, STL) and ball lists, read and written.
//
// Accepted (reading; errors are ComplexFormatError "<file>:<line>: <problem>", or
// "<file>: <element> <index>: <problem>" inside binary PLY):
//  - OFF: a first line `OFF`, or `COFF`, `NOFF`, `CNOFF`, `STOFF`, ... of Geomview's OFF
//    family (optionally followed on the same line by the counts), then `nv nf ne`, nv
//    vertex lines `x y z` (further numbers -- colours, normals, texture coordinates -- are
//    ignored), nf face lines `k i_1 ... i_k` (further numbers ignored); `#` comments and
//    blank lines anywhere. 4OFF and nOFF (other dimensions) are rejected.
//  - PLY 1.0: `format ascii` or `format binary_little_endian` (big endian is rejected); a
//    `vertex` element with float/double/integer properties x, y, z, and a `face` element
//    with a list property `vertex_indices` or `vertex_index`; other properties and
//    elements are skipped (any PLY scalar type: char, uchar, short, ushort, int, uint,
//    float, double and their int8..float64 names).
//  - OBJ: `v x y z [w]` and `f a b c ...` with references of the forms i, i/t, i/t/n, i//n,
//    1-based, negative = relative to the end; other statements are ignored.
//  - STL: binary (80-byte header, uint32 count n, n facets of 50 bytes) when the file has
//    exactly 84 + 50 n bytes -- also when it begins with "solid", as some exporters write;
//    otherwise ASCII: `solid [name]`, then facets `facet normal nx ny nz`, `outer loop`,
//    three `vertex x y z`, `endloop`, `endfacet`, then `endsolid [name]` (keywords in any
//    case; several solids in one file are read as one mesh). Normals are ignored (the
//    vertex order gives the orientation, as the format says). Every facet repeats its
//    vertices: welding (below) makes a mesh of them.
//  - ball lists: one ball a line, `x y z w` with w > 0 the squared radius (CGAL weighted
//    points, /work/shared/data/balls); values are exact decimals within the range of
//    doubles (the builders triangulate their nearest doubles first).
// Every mesh reader rejects: NaN or infinite or non-numeric values, wrong counts (before
// allocating anything for them: a header announcing 10^12 vertices is refused by comparing
// with the file's size), indices out of range, a face listing fewer than 3 vertices or
// repeating a vertex other than consecutively, and meshes with no triangle left.
// A face with k > 3 vertices becomes the fan of k - 2 triangles from its first vertex
// (append_polygon_face), the triangulation of a convex face; non-convex faces are the
// caller's risk (the mesh builders check closedness, not face convexity).
// Then every reader repairs what is safe to repair, and counts it (geometry3/mesh_weld.h, through io/mesh_input.h): exactly
// repeated vertices are welded, faces left with fewer than 3 distinct vertices and
// repeated faces are dropped, unused vertices are dropped.
// Coordinates (io/decimal_text.h): text formats keep the decimals as written, exactly
// (TriangleMesh3::exact_vertices), beside their nearest doubles (TriangleMesh3::vertices).
// Writing: OFF, OBJ and ASCII PLY with the shortest round-tripping decimals, so a mesh
// written and read back has the same doubles.
#pragma once

#include <string>

#include "geometry3/ball_set.h"
#include "complex3/raw_complex.h"
#include "geometry3/triangle_mesh.h"

namespace grassfire {

TriangleMesh3 parse_off(const std::string& text, const std::string& source);
TriangleMesh3 parse_obj(const std::string& text, const std::string& source);
TriangleMesh3 parse_ply(const std::string& bytes, const std::string& source);
TriangleMesh3 parse_stl(const std::string& bytes, const std::string& source);
// By the extension of `source` (.off, .ply, .obj, .stl, case-insensitive); unknown
// extensions are an error.
TriangleMesh3 parse_triangle_mesh(const std::string& bytes, const std::string& source);
TriangleMesh3 read_triangle_mesh(const std::string& path);
// True for the extensions read_triangle_mesh reads ("off", "ply", "obj", "stl").
bool is_mesh_extension(const std::string& ext);

void write_off(const TriangleMesh3& mesh, const std::string& path);
void write_obj(const TriangleMesh3& mesh, const std::string& path);
void write_ply(const TriangleMesh3& mesh, const std::string& path);

BallSet parse_ball_list(const std::string& text, const std::string& source);
BallSet read_ball_list(const std::string& path);

// The mesh itself as a complex: vertex coordinates are the decimals the file wrote
// (exact_vertices, where their nearest doubles are still the mesh's), else the doubles,
// exactly; R = 0 and Linear ignition; for burning on a given surface or 2-complex.
RawComplex mesh_as_complex(const TriangleMesh3& mesh);

// Appends a polygonal face (v_0, ..., v_{k-1}) of the file as the fan of triangles
// (v_0, v_i, v_{i+1}), 0 < i < k - 1 (the triangulation of a convex face), each tagged with
// the face's file index (mesh.cleanup.file_faces, which counts the calls). Cyclically
// consecutive repeats (v, v) are merged first; a face left with fewer than 3 vertices is
// Degenerate (counted in mesh.cleanup, nothing appended); a face that still repeats a vertex
// is RepeatsVertex (nothing appended: the reader refuses it).
enum class PolygonFace { Added, Degenerate, RepeatsVertex };
PolygonFace append_polygon_face(TriangleMesh3& mesh, std::vector<std::uint32_t> face);

// Lower-case extension of a path without the dot ("" if none).
std::string file_extension(const std::string& path);

}  // namespace grassfire
