// polyline_export.cpp -- PLY and legacy VTK polylines (see header).
#include "io/polyline_export.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "support/atomic_file.h"
#include "io/complex_text.h"

namespace grassfire {
namespace {

void check(const PolylineSet& set, const std::string& path) {
  for (const Vec3d& p : set.points)
    for (double x : p)
      if (!std::isfinite(x)) throw ComplexFormatError(path + ": a point coordinate is not finite");
  for (const auto& line : set.lines) {
    if (line.size() < 2) throw ComplexFormatError(path + ": a polyline has fewer than 2 points");
    for (std::uint32_t i : line)
      if (i >= set.points.size()) throw ComplexFormatError(path + ": a polyline point index is out of range");
  }
  for (const VertexField& f : set.fields) {
    if (f.name.empty()) throw ComplexFormatError(path + ": a scalar field has no name");
    for (char c : f.name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
        throw ComplexFormatError(path + ": scalar field name '" + f.name + "' must be letters, digits or _");
    if (f.values.size() != set.points.size())
      throw ComplexFormatError(path + ": field " + f.name + " has " + std::to_string(f.values.size()) + " values for " +
                               std::to_string(set.points.size()) + " points");
    for (double v : f.values)
      if (std::isnan(v)) throw ComplexFormatError(path + ": field " + f.name + " contains NaN");
  }
}

std::string number(double x) { return std::isinf(x) ? (x > 0 ? "inf" : "-inf") : shortest_double(x); }

void write(const std::string& path, const std::string& text) {
  try {
    write_file_atomically(path, text);
  } catch (const std::exception& e) {
    throw ComplexFormatError(e.what());
  }
}

}  // namespace

void write_polylines_ply(const PolylineSet& set, const std::string& comment, const std::string& path) {
  check(set, path);
  std::size_t segments = 0;
  for (const auto& line : set.lines) segments += line.size() - 1;
  std::ostringstream os;
  os << "ply\nformat ascii 1.0\ncomment " << comment << "\nelement vertex " << set.points.size()
     << "\nproperty double x\nproperty double y\nproperty double z\n";
  for (const VertexField& f : set.fields) os << "property float " << f.name << '\n';
  os << "element edge " << segments << "\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    os << number(set.points[i][0]) << ' ' << number(set.points[i][1]) << ' ' << number(set.points[i][2]);
    for (const VertexField& f : set.fields) os << ' ' << number(f.values[i]);
    os << '\n';
  }
  for (const auto& line : set.lines)
    for (std::size_t j = 1; j < line.size(); ++j) os << line[j - 1] << ' ' << line[j] << '\n';
  write(path, os.str());
}

void write_polylines_vtk(const PolylineSet& set, const std::string& title, const std::string& path) {
  check(set, path);
  std::size_t entries = 0;
  for (const auto& line : set.lines) entries += line.size() + 1;
  std::ostringstream os;
  os << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET POLYDATA\nPOINTS " << set.points.size() << " double\n";
  for (const Vec3d& p : set.points) os << number(p[0]) << ' ' << number(p[1]) << ' ' << number(p[2]) << '\n';
  os << "LINES " << set.lines.size() << ' ' << entries << '\n';
  for (const auto& line : set.lines) {
    os << line.size();
    for (std::uint32_t i : line) os << ' ' << i;
    os << '\n';
  }
  if (!set.fields.empty()) os << "POINT_DATA " << set.points.size() << '\n';
  for (const VertexField& f : set.fields) {
    os << "SCALARS " << f.name << " double 1\nLOOKUP_TABLE default\n";
    for (double x : f.values) os << number(x) << '\n';
  }
  write(path, os.str());
}

}  // namespace grassfire
