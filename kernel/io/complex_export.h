// complex_export.h -- a medial complex with per-vertex scalars, for ParaView and MeshLab.
//
// Writes the complex's vertices, triangles and dangling segments with named per-vertex
// scalar fields (typically R, BT, ET): ASCII PLY (element vertex with x y z and one float
// property per field, element face, element edge for the segments) and legacy VTK
// (POLYDATA with POLYGONS, LINES and POINT_DATA SCALARS). An infinite value (BT where
// nothing burns) is written as "inf", which ParaView and MeshLab parse with strtod; NaN is
// rejected. Throws ComplexFormatError naming the file on write errors or bad fields, and
// writes nothing when the fields are malformed.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "complex3/medial_complex.h"

namespace grassfire {

struct VertexField {
  std::string name;            // letters, digits, '_'
  std::vector<double> values;  // one per vertex
};

void write_complex_ply(const MedialComplex& mc, const std::vector<VertexField>& fields, const std::string& path);
void write_complex_vtk(const MedialComplex& mc, const std::vector<VertexField>& fields, const std::string& path);

}  // namespace grassfire
