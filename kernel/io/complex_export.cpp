// complex_export.cpp -- PLY and legacy VTK output of a complex with scalars (see header).
#include "io/complex_export.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "support/atomic_file.h"
#include "io/complex_text.h"

namespace grassfire {
namespace {

void check_fields(const MedialComplex& mc, const std::vector<VertexField>& fields, const std::string& path) {
  for (const VertexField& f : fields) {
    if (f.name.empty()) throw ComplexFormatError(path + ": a scalar field has no name");
    for (char c : f.name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw ComplexFormatError(path + ": scalar field name '" + f.name + "' must be letters, digits or _");
    if (f.values.size() != mc.vertex_count())
      throw ComplexFormatError(path + ": field " + f.name + " has " + std::to_string(f.values.size()) + " values for " +
                               std::to_string(mc.vertex_count()) + " vertices");
    for (double v : f.values)
      if (std::isnan(v)) throw ComplexFormatError(path + ": field " + f.name + " contains NaN");
  }
}

std::string number(double x) { return std::isinf(x) ? (x > 0 ? "inf" : "-inf") : shortest_double(x); }

// Through a temporary file renamed when complete: never a partial output.
void write_all(const std::string& path, const std::string& text) {
  try {
    write_file_atomically(path, text);
  } catch (const std::runtime_error& e) {
    throw ComplexFormatError(e.what());
  }
}

}  // namespace

void write_complex_ply(const MedialComplex& mc, const std::vector<VertexField>& fields, const std::string& path) {
  check_fields(mc, fields, path);
  std::ostringstream os;
  os << "ply\nformat ascii 1.0\ncomment grassfire medial complex " << mc.source() << "\nelement vertex "
     << mc.vertex_count() << "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const VertexField& f : fields) os << "property float " << f.name << '\n';
  os << "element face " << mc.triangle_count() << "\nproperty list uchar int vertex_indices\n";
  os << "element edge " << mc.count(EdgeStratum::Dangling) << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    const Vec3d& p = mc.vertex(v).approx;
    os << number(p[0]) << ' ' << number(p[1]) << ' ' << number(p[2]);
    for (const VertexField& f : fields) os << ' ' << number(f.values[v]);
    os << '\n';
  }
  for (const ComplexTriangle& t : mc.triangles()) os << "3 " << t.v[0] << ' ' << t.v[1] << ' ' << t.v[2] << '\n';
  for (const ComplexEdge& e : mc.edges())
    if (e.stratum == EdgeStratum::Dangling) os << e.v[0] << ' ' << e.v[1] << '\n';
  write_all(path, os.str());
}

void write_complex_vtk(const MedialComplex& mc, const std::vector<VertexField>& fields, const std::string& path) {
  check_fields(mc, fields, path);
  std::ostringstream os;
  os << "# vtk DataFile Version 3.0\ngrassfire medial complex\nASCII\nDATASET POLYDATA\nPOINTS " << mc.vertex_count()
     << " double\n";
  for (const ComplexVertex& v : mc.vertices()) os << number(v.approx[0]) << ' ' << number(v.approx[1]) << ' ' << number(v.approx[2]) << '\n';
  os << "POLYGONS " << mc.triangle_count() << ' ' << 4 * mc.triangle_count() << '\n';
  for (const ComplexTriangle& t : mc.triangles()) os << "3 " << t.v[0] << ' ' << t.v[1] << ' ' << t.v[2] << '\n';
  const std::size_t segments = mc.count(EdgeStratum::Dangling);
  if (segments > 0) {
    os << "LINES " << segments << ' ' << 3 * segments << '\n';
    for (const ComplexEdge& e : mc.edges())
      if (e.stratum == EdgeStratum::Dangling) os << "2 " << e.v[0] << ' ' << e.v[1] << '\n';
  }
  if (!fields.empty()) os << "POINT_DATA " << mc.vertex_count() << '\n';
  for (const VertexField& f : fields) {
    os << "SCALARS " << f.name << " double 1\nLOOKUP_TABLE default\n";
    for (double x : f.values) os << number(x) << '\n';
  }
  write_all(path, os.str());
}

}  // namespace grassfire
