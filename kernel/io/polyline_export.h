// polyline_export.h -- polylines in 3D with per-point scalars, for ParaView and MeshLab:
// medial curve graphs (curves3d) and burning paths (paths3d).
//
// Writes ASCII PLY (element vertex with x y z and one float property per field, element
// edge with the segments of every polyline) and legacy VTK (POLYDATA with POINTS, LINES,
// one polyline per line, and POINT_DATA SCALARS). Infinite values are written "inf"
// (ParaView and MeshLab read them with strtod). Every file is written whole or not at all
// (support/atomic_file.h); malformed input (indices out of range, NaN, a field of the wrong
// size or with a bad name) throws ComplexFormatError naming the file, before writing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/complex_export.h"

namespace grassfire {

struct PolylineSet {
  std::vector<Vec3d> points;
  std::vector<std::vector<std::uint32_t>> lines;  // point indices, >= 2 per line
  std::vector<VertexField> fields;                // one value per point
};

void write_polylines_ply(const PolylineSet& set, const std::string& comment, const std::string& path);
void write_polylines_vtk(const PolylineSet& set, const std::string& title, const std::string& path);

}  // namespace grassfire
