// mesh_io.cpp -- OFF and OBJ meshes, ball lists, and the mesh writers (see mesh_io.h).
#include "io/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>

#include "io/complex_text.h"
#include "io/mesh_input.h"
#include "support/quoted.h"

namespace grassfire {
namespace {

// A vertex line's three coordinates from token `first`: the exact decimals and their
// nearest doubles (io/decimal_text.h).
void add_vertex(TriangleMesh3& m, const TextLine& l, std::size_t first, const std::string& source) {
  std::array<double, 3> p{};
  std::array<mpq_class, 3> q;
  for (std::size_t i = 0; i < 3; ++i) {
    if (first + i >= l.tokens.size()) format_error(source, l.number, "a vertex needs three coordinates");
    auto d = parse_decimal_value(l.tokens[first + i]);
    if (!d) format_error(source, l.number, quote_token(l.tokens[first + i]) + " is not a finite number");
    p[i] = d->nearest;
    q[i] = std::move(d->exact);
  }
  m.vertices.push_back(p);
  m.exact_vertices.push_back(std::move(q));
}

// Geomview's OFF family: [ST][C][N][4][n]OFF. The prefixes add per-vertex numbers (texture
// coordinates, colours, normals), which the reader skips; 4 and n change the dimension.
bool is_off_keyword(const std::string& w) {
  static const std::regex family("(ST)?C?N?OFF");
  return std::regex_match(w, family);
}

[[noreturn]] void unknown_mesh_extension(const std::string& source, const std::string& ext) {
  throw ComplexFormatError(source + ": unknown mesh extension '" + ext + "' (expected .off, .ply, .obj or .stl)");
}

std::ofstream open_for_writing(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw ComplexFormatError(path + ": cannot write file");
  return out;
}

void finish(std::ofstream& out, const std::string& path) {
  out.close();
  if (!out) throw ComplexFormatError(path + ": write error");
}

}  // namespace

PolygonFace append_polygon_face(TriangleMesh3& mesh, std::vector<std::uint32_t> face) {
  const auto file_face = static_cast<std::uint32_t>(mesh.cleanup.file_faces++);
  face.erase(std::unique(face.begin(), face.end()), face.end());
  while (face.size() > 1 && face.front() == face.back()) face.pop_back();
  if (face.size() < 3) {
    ++mesh.cleanup.degenerate_faces;
    return PolygonFace::Degenerate;
  }
  std::vector<std::uint32_t> sorted = face;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return PolygonFace::RepeatsVertex;
  for (std::size_t i = 1; i + 1 < face.size(); ++i) {
    mesh.triangles.push_back({face[0], face[i], face[i + 1]});
    mesh.triangle_origin.push_back(file_face);
  }
  return PolygonFace::Added;
}

bool is_mesh_extension(const std::string& ext) { return ext == "off" || ext == "ply" || ext == "obj" || ext == "stl"; }

std::string file_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

TriangleMesh3 parse_off(const std::string& text, const std::string& source) {
  const std::vector<TextLine> lines = tokenize_lines(text);
  TriangleMesh3 m;
  m.source = source;
  if (lines.empty() || !is_off_keyword(lines[0].tokens[0]))
    format_error(source, lines.empty() ? 0 : lines[0].number,
                 "not an OFF file (first word must be OFF, or COFF, NOFF, STOFF, ... of Geomview's OFF family)");
  std::vector<std::string> count_tokens(lines[0].tokens.begin() + 1, lines[0].tokens.end());
  std::size_t next = 1, count_line = lines[0].number;
  if (count_tokens.empty()) {
    if (lines.size() < 2) format_error(source, lines[0].number, "missing counts 'nv nf ne'");
    count_tokens = lines[1].tokens;
    count_line = lines[1].number;
    next = 2;
  }
  if (count_tokens.size() != 3) format_error(source, count_line, "counts must be 'nv nf ne'");
  std::uint64_t c[3];
  for (int i = 0; i < 3; ++i) {
    const auto v = parse_index(count_tokens[i]);
    if (!v) format_error(source, count_line, "count " + quote_token(count_tokens[i]) + " is not a non-negative integer");
    c[i] = *v;
  }
  const std::uint64_t nv = c[0], nf = c[1];
  if (lines.size() - next < nv + nf)
    format_error(source, lines.back().number, "file ends early: the counts announce " + std::to_string(nv) + " vertices and " +
                                                  std::to_string(nf) + " faces");
  if (lines.size() - next > nv + nf) format_error(source, lines[next + nv + nf].number, "content after the last face");
  for (std::uint64_t i = 0; i < nv; ++i) add_vertex(m, lines[next + i], 0, source);
  for (std::uint64_t i = 0; i < nf; ++i) {
    const TextLine& l = lines[next + nv + i];
    const auto n = parse_index(l.tokens[0]);
    if (!n) format_error(source, l.number, "face must start with its vertex count");
    if (*n < 3) format_error(source, l.number, "face with " + l.tokens[0] + " vertices; at least 3 are required");
    if (l.tokens.size() < 1 + *n) format_error(source, l.number, "face lists fewer than " + l.tokens[0] + " vertices");
    std::vector<std::uint32_t> face;
    for (std::uint64_t k = 0; k < *n; ++k) {  // numbers after the indices (colours) are ignored
      const auto idx = parse_index(l.tokens[1 + k]);
      if (!idx) format_error(source, l.number, quote_token(l.tokens[1 + k]) + " is not a vertex index");
      if (*idx >= nv)
        format_error(source, l.number, "vertex index '" + l.tokens[1 + k] + "' out of range (" + std::to_string(nv) + " vertices)");
      face.push_back(static_cast<std::uint32_t>(*idx));
    }
    if (append_polygon_face(m, face) == PolygonFace::RepeatsVertex)
      format_error(source, l.number, "face repeats a vertex (not next to itself)");
  }
  finish_mesh_reading(m);
  return m;
}

TriangleMesh3 parse_obj(const std::string& text, const std::string& source) {
  TriangleMesh3 m;
  m.source = source;
  struct Face {
    std::vector<long long> ref;
    std::size_t line;
  };
  std::vector<Face> faces;
  for (const TextLine& l : tokenize_lines(text)) {
    if (l.tokens[0] == "v") {
      if (l.tokens.size() < 4 || l.tokens.size() > 5) format_error(source, l.number, "vertex must be 'v x y z [w]'");
      add_vertex(m, l, 1, source);
    } else if (l.tokens[0] == "f") {
      if (l.tokens.size() < 4)
        format_error(source, l.number, "face with " + std::to_string(l.tokens.size() - 1) + " vertices; at least 3 are required");
      Face f{std::vector<long long>(l.tokens.size() - 1), l.number};
      for (std::size_t k = 0; k + 1 < l.tokens.size(); ++k) {
        const std::string idx = l.tokens[1 + k].substr(0, l.tokens[1 + k].find('/'));
        const bool negative = !idx.empty() && idx[0] == '-';
        const auto v = parse_index(negative ? idx.substr(1) : idx);
        if (!v || *v == 0) format_error(source, l.number, quote_token(l.tokens[1 + k]) + " is not a vertex reference");
        f.ref[k] = negative ? -static_cast<long long>(*v) : static_cast<long long>(*v);
        // A negative reference counts back from the vertices read so far.
        if (negative) f.ref[k] = static_cast<long long>(m.vertices.size()) + f.ref[k] + 1;
      }
      faces.push_back(f);
    }
  }
  for (const Face& f : faces) {
    std::vector<std::uint32_t> face;
    for (long long r : f.ref) {
      if (r < 1 || r > static_cast<long long>(m.vertices.size()))
        format_error(source, f.line, "vertex reference out of range (" + std::to_string(m.vertices.size()) + " vertices)");
      face.push_back(static_cast<std::uint32_t>(r - 1));
    }
    if (append_polygon_face(m, face) == PolygonFace::RepeatsVertex)
      format_error(source, f.line, "face repeats a vertex (not next to itself)");
  }
  finish_mesh_reading(m);
  return m;
}

TriangleMesh3 parse_triangle_mesh(const std::string& bytes, const std::string& source) {
  const std::string ext = file_extension(source);
  if (ext == "off") return parse_off(bytes, source);
  if (ext == "obj") return parse_obj(bytes, source);
  if (ext == "ply") return parse_ply(bytes, source);
  if (ext == "stl") return parse_stl(bytes, source);
  unknown_mesh_extension(source, ext);
}

TriangleMesh3 read_triangle_mesh(const std::string& path) {
  const std::string ext = file_extension(path);
  if (!is_mesh_extension(ext)) unknown_mesh_extension(path, ext);
  return parse_triangle_mesh(read_text_file(path), path);
}

void write_off(const TriangleMesh3& m, const std::string& path) {
  std::ofstream out = open_for_writing(path);
  out << "OFF\n" << m.vertices.size() << ' ' << m.triangles.size() << " 0\n";
  for (const auto& p : m.vertices) out << shortest_double(p[0]) << ' ' << shortest_double(p[1]) << ' ' << shortest_double(p[2]) << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  finish(out, path);
}

void write_obj(const TriangleMesh3& m, const std::string& path) {
  std::ofstream out = open_for_writing(path);
  for (const auto& p : m.vertices)
    out << "v " << shortest_double(p[0]) << ' ' << shortest_double(p[1]) << ' ' << shortest_double(p[2]) << '\n';
  for (const auto& t : m.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  finish(out, path);
}

void write_ply(const TriangleMesh3& m, const std::string& path) {
  std::ofstream out = open_for_writing(path);
  out << "ply\nformat ascii 1.0\nelement vertex " << m.vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << m.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.vertices) out << shortest_double(p[0]) << ' ' << shortest_double(p[1]) << ' ' << shortest_double(p[2]) << '\n';
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  finish(out, path);
}

BallSet parse_ball_list(const std::string& text, const std::string& source) {
  BallSet b;
  b.source = source;
  for (const TextLine& l : tokenize_lines(text)) {
    if (l.tokens.size() != 4) format_error(source, l.number, "a ball line must be 'x y z w' (w = squared radius)");
    mpq_class v[4];
    // The builders triangulate the approximate balls in doubles first (CGAL), so every value
    // must have a finite nearest double.
    static const mpq_class largest(std::numeric_limits<double>::max());
    for (int i = 0; i < 4; ++i) {
      const auto q = parse_exact_decimal(l.tokens[i]);
      if (!q) format_error(source, l.number, quote_token(l.tokens[i]) + " is not a finite decimal number");
      if (abs(*q) > largest) format_error(source, l.number, quote_token(l.tokens[i]) + " is beyond the range of doubles");
      v[i] = *q;
    }
    if (sgn(v[3]) <= 0) format_error(source, l.number, "squared radius " + shorten_token(l.tokens[3]) + " is not positive");
    b.centers.push_back({v[0], v[1], v[2]});
    b.squared_radii.push_back(v[3]);
    b.approx_centers.push_back({v[0].get_d(), v[1].get_d(), v[2].get_d()});
    b.approx_radii.push_back(std::sqrt(v[3].get_d()));
  }
  if (b.centers.empty()) format_error(source, 0, "no balls");
  return b;
}

BallSet read_ball_list(const std::string& path) { return parse_ball_list(read_text_file(path), path); }

RawComplex mesh_as_complex(const TriangleMesh3& mesh) {
  RawComplex r;
  r.source = mesh.source;
  // The coordinates as written (io/decimal_text.h), where the doubles are still theirs.
  const bool exact = mesh.exact_vertices.size() == mesh.vertices.size();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto& p = mesh.vertices[v];
    const auto* q = exact ? &mesh.exact_vertices[v] : nullptr;
    if (q && nearest_double((*q)[0]) == p[0] && nearest_double((*q)[1]) == p[1] && nearest_double((*q)[2]) == p[2])
      r.vertices.push_back({(*q)[0], (*q)[1], (*q)[2]});
    else
      r.vertices.push_back({mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])});
    r.radius_squared.push_back(0);
  }
  r.triangles = mesh.triangles;
  return r;
}

}  // namespace grassfire
