// mesh_ply.cpp -- PLY 1.0 triangle meshes, ASCII and binary little endian (see mesh_io.h).
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "io/mesh_input.h"
#include "support/quoted.h"

namespace grassfire {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
  std::string name;
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;
  PlyType type = PlyType::Float32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool binary = false;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // bytes
  std::size_t body_line = 0;    // line number of the first body line (ASCII)
};

std::optional<PlyType> ply_type(const std::string& s) {
  if (s == "char" || s == "int8") return PlyType::Int8;
  if (s == "uchar" || s == "uint8") return PlyType::UInt8;
  if (s == "short" || s == "int16") return PlyType::Int16;
  if (s == "ushort" || s == "uint16") return PlyType::UInt16;
  if (s == "int" || s == "int32") return PlyType::Int32;
  if (s == "uint" || s == "uint32") return PlyType::UInt32;
  if (s == "float" || s == "float32") return PlyType::Float32;
  if (s == "double" || s == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

PlyHeader parse_header(const std::string& bytes, const std::string& source) {
  PlyHeader h;
  std::size_t pos = 0, line = 0;
  bool format_seen = false;
  for (;;) {
    const std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) format_error(source, line + 1, "header has no end_header line");
    ++line;
    std::string text = bytes.substr(pos, end - pos);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    pos = end + 1;
    std::istringstream ls(text);
    std::vector<std::string> t;
    for (std::string w; ls >> w;) t.push_back(w);
    if (line == 1) {
      if (t.size() != 1 || t[0] != "ply") format_error(source, 1, "not a PLY file (first line must be 'ply')");
      continue;
    }
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() != 3 || t[2] != "1.0") format_error(source, line, "format line must be 'format <kind> 1.0'");
      if (t[1] == "ascii") h.binary = false;
      else if (t[1] == "binary_little_endian") h.binary = true;
      else format_error(source, line, "unsupported PLY format " + quote_token(t[1]) + " (ascii or binary_little_endian)");
      format_seen = true;
    } else if (t[0] == "element") {
      const auto n = t.size() == 3 ? parse_index(t[2]) : std::nullopt;
      if (!n) format_error(source, line, "element line must be 'element <name> <count>'");
      h.elements.push_back({t[1], *n, {}});
    } else if (t[0] == "property") {
      if (h.elements.empty()) format_error(source, line, "property before any element");
      PlyProperty p;
      if (t.size() == 5 && t[1] == "list") {
        const auto ct = ply_type(t[2]), vt = ply_type(t[3]);
        if (!ct || !vt) format_error(source, line, "unknown PLY type in list property");
        p = {t[4], true, *ct, *vt};
      } else if (t.size() == 3) {
        const auto vt = ply_type(t[1]);
        if (!vt) format_error(source, line, "unknown PLY type " + quote_token(t[1]));
        p = {t[2], false, PlyType::UInt8, *vt};
      } else {
        format_error(source, line, "malformed property line");
      }
      h.elements.back().properties.push_back(p);
    } else {
      format_error(source, line, "unknown header keyword " + quote_token(t[0]));
    }
  }
  if (!format_seen) format_error(source, line, "header has no format line");
  h.body_offset = pos;
  h.body_line = line + 1;
  return h;
}

// Reads the values of one element instance, in property order (lists: count, then items).
class PlyReader {
 public:
  PlyReader(const std::string& bytes, const PlyHeader& h, const std::string& source)
      : bytes_(bytes), h_(h), source_(source), pos_(h.body_offset), line_(h.body_line - 1) {}

  std::vector<std::vector<double>> next(const PlyElement& e, std::uint64_t index) {
    where_ = shorten_token(e.name) + " " + std::to_string(index);
    if (!h_.binary) start_line();
    std::vector<std::vector<double>> values;
    text_.assign(e.properties.size(), std::string());
    for (const PlyProperty& p : e.properties) {
      std::vector<double> v;
      if (p.is_list) {
        const double n = scalar(p.count_type);
        if (n < 0 || n != std::floor(n) || n > 1e6) fail("bad list length");
        for (std::uint64_t i = 0; i < static_cast<std::uint64_t>(n); ++i) v.push_back(scalar(p.type));
      } else {
        v.push_back(scalar(p.type));
        if (!h_.binary) text_[values.size()] = tokens_[token_ - 1];
      }
      values.push_back(std::move(v));
    }
    if (!h_.binary && token_ < tokens_.size()) fail("more values than the element's properties");
    return values;
  }
  // ASCII: the text of scalar property k of the element last read ("" when binary).
  const std::string& text(int k) const { return text_[static_cast<std::size_t>(k)]; }
  void finish() {
    if (h_.binary) return;
    while (pos_ < bytes_.size()) {
      start_line_raw();
      if (!tokens_.empty()) format_error(source_, line_, "content after the last element");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    if (h_.binary) throw ComplexFormatError(source_ + ": " + where_ + ": " + what);
    format_error(source_, line_, where_ + ": " + what);
  }
  void start_line_raw() {
    const std::size_t end = std::min(bytes_.find('\n', pos_), bytes_.size());
    std::istringstream ls(bytes_.substr(pos_, end - pos_));
    tokens_.clear();
    for (std::string w; ls >> w;) tokens_.push_back(w);
    token_ = 0;
    ++line_;
    pos_ = end + 1;
  }
  void start_line() {
    do {
      if (pos_ >= bytes_.size()) fail("file ends early");
      start_line_raw();
    } while (tokens_.empty());
  }
  double scalar(PlyType t) {
    if (!h_.binary) {
      if (token_ >= tokens_.size()) fail("fewer values than the element's properties");
      // Non-finite values are legal in properties we skip (e.g. an exported BT = inf);
      // parse_ply checks that coordinates are finite.
      const std::string& tok = tokens_[token_++];
      if (const auto d = parse_finite_double(tok)) return *d;
      if (tok == "inf" || tok == "+inf") return std::numeric_limits<double>::infinity();
      if (tok == "-inf") return -std::numeric_limits<double>::infinity();
      if (tok == "nan") return std::numeric_limits<double>::quiet_NaN();
      fail(quote_token(tok) + " is not a number");
    }
    const std::size_t n = type_size(t);
    if (pos_ + n > bytes_.size()) fail("file ends early");
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    pos_ += n;
    double value = 0;
    switch (t) {  // little endian: the host's order on the platforms we build for
      case PlyType::Int8: value = static_cast<std::int8_t>(b[0]); break;
      case PlyType::UInt8: value = b[0]; break;
      case PlyType::Int16: { std::int16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case PlyType::UInt16: { std::uint16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case PlyType::Int32: { std::int32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case PlyType::UInt32: { std::uint32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case PlyType::Float32: { float x; std::memcpy(&x, b, 4); value = x; break; }
      case PlyType::Float64: { std::memcpy(&value, b, 8); break; }
    }
    return value;
  }

  const std::string& bytes_;
  const PlyHeader& h_;
  const std::string& source_;
  std::size_t pos_, line_;
  std::vector<std::string> tokens_;
  std::vector<std::string> text_;
  std::size_t token_ = 0;
  std::string where_;
};

int property_index(const PlyElement& e, const std::string& name) {
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

TriangleMesh3 parse_ply(const std::string& bytes, const std::string& source) {
  static_assert(sizeof(float) == 4 && sizeof(double) == 8, "IEEE float sizes");
  const PlyHeader h = parse_header(bytes, source);
  TriangleMesh3 m;
  m.source = source;
  PlyReader reader(bytes, h, source);
  bool have_vertices = false, have_faces = false;
  double vertex_count = 0;
  for (const PlyElement& e : h.elements)
    if (e.name == "vertex") vertex_count = static_cast<double>(e.count);
  for (const PlyElement& e : h.elements) {
    const int ix = property_index(e, "x"), iy = property_index(e, "y"), iz = property_index(e, "z");
    int list = property_index(e, "vertex_indices");
    if (list < 0) list = property_index(e, "vertex_index");
    if (e.name == "vertex" && (ix < 0 || iy < 0 || iz < 0)) format_error(source, 0, "vertex element lacks x, y or z");
    if (e.name == "face" && (list < 0 || !e.properties[list].is_list))
      format_error(source, 0, "face element lacks the list property vertex_indices");
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const auto values = reader.next(e, i);
      if (e.name == "vertex") {
        m.vertices.push_back({values[ix][0], values[iy][0], values[iz][0]});
        for (double c : m.vertices.back())
          if (!std::isfinite(c))
            throw ComplexFormatError(source + ": vertex " + std::to_string(i) + ": coordinate is NaN or infinite");
        if (!h.binary)  // the decimals as written (io/decimal_text.h); finite, so they parse
          m.exact_vertices.push_back({*parse_exact_decimal(reader.text(ix)), *parse_exact_decimal(reader.text(iy)),
                                      *parse_exact_decimal(reader.text(iz))});
      } else if (e.name == "face") {
        const auto& idx = values[list];
        const std::string where = source + ": face " + std::to_string(i) + ": ";
        if (idx.size() < 3)
          throw ComplexFormatError(where + "face with " + std::to_string(idx.size()) + " vertices; at least 3 are required");
        std::vector<std::uint32_t> face;
        for (double k : idx) {
          if (k < 0 || k != std::floor(k) || k >= vertex_count)
            throw ComplexFormatError(where + "vertex index " + shortest_double(k) + " out of range (" +
                                     shortest_double(vertex_count) + " vertices)");
          face.push_back(static_cast<std::uint32_t>(k));
        }
        if (append_polygon_face(m, face) == PolygonFace::RepeatsVertex)
          throw ComplexFormatError(where + "face repeats a vertex (not next to itself)");
      }
    }
    have_vertices = have_vertices || e.name == "vertex";
    have_faces = have_faces || e.name == "face";
  }
  reader.finish();
  if (!have_vertices || !have_faces) throw ComplexFormatError(source + ": empty mesh (no vertices or no triangles)");
  finish_mesh_reading(m);
  return m;
}

}  // namespace grassfire
