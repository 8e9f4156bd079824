// mesh_stl.cpp -- STL triangle soups, binary and ASCII (see mesh_io.h).
//
// Binary or ASCII is decided by size, not by the first word: many binary exporters write
// "solid ..." into the 80-byte header, so a file of exactly 84 + 50 n bytes, n the count at
// byte 80, is binary. The count is checked against the size before anything is allocated.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "io/complex_text.h"
#include "io/mesh_io.h"
#include "io/mesh_input.h"
#include "support/quoted.h"

namespace grassfire {
namespace {

constexpr std::size_t kHeaderBytes = 84, kFacetBytes = 50;

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  const auto b = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])); };
  return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}

float little_endian_f32(const std::string& bytes, std::size_t at) {
  const std::uint32_t u = little_endian_u32(bytes, at);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

void add_facet(TriangleMesh3& m, const std::array<std::array<double, 3>, 3>& corners) {
  const auto first = static_cast<std::uint32_t>(m.vertices.size());
  for (const auto& p : corners) m.vertices.push_back(p);
  // Corners equal by index cannot happen here; equal points are welded afterwards.
  append_polygon_face(m, {first, first + 1, first + 2});
}

TriangleMesh3 parse_binary_stl(const std::string& bytes, const std::string& source, std::uint32_t n) {
  TriangleMesh3 m;
  m.source = source;
  m.vertices.reserve(3 * static_cast<std::size_t>(n));  // n is bounded by the file size here
  for (std::uint32_t f = 0; f < n; ++f) {
    const std::size_t at = kHeaderBytes + kFacetBytes * f + 12;  // after the facet normal
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 9; ++k) {
      const double x = little_endian_f32(bytes, at + 4 * k);
      if (!std::isfinite(x))
        throw ComplexFormatError(source + ": facet " + std::to_string(f) + ": vertex coordinate is NaN or infinite");
      corners[k / 3][k % 3] = x;
    }
    add_facet(m, corners);
  }
  finish_mesh_reading(m);
  return m;
}

std::string lower(std::string w) {
  std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return std::tolower(c); });
  return w;
}

// ASCII STL as a stream of words with their line numbers.
class AsciiStl {
 public:
  AsciiStl(const std::string& text, const std::string& source) : source_(source), lines_(tokenize_lines(text, 0)) {}

  TriangleMesh3 read() {
    TriangleMesh3 m;
    m.source = source_;
    expect("solid");
    skip_rest_of_line();
    for (;;) {
      if (at_end()) fail("file ends before 'endsolid'");
      const std::string w = lower(word());
      if (w == "endsolid") {
        skip_rest_of_line();
        if (at_end()) break;
        expect("solid");  // several solids in one file: one mesh
        skip_rest_of_line();
      } else if (w == "facet") {
        facet(m);
      } else {
        fail("expected 'facet' or 'endsolid', found " + quote_token(w), true);
      }
    }
    finish_mesh_reading(m);
    return m;
  }

 private:
  void facet(TriangleMesh3& m) {
    expect("normal");
    for (int k = 0; k < 3; ++k) word("a normal component");  // ignored: the vertex order orients
    expect("outer");
    expect("loop");
    std::array<std::array<double, 3>, 3> corners;
    for (auto& p : corners) {
      expect("vertex");
      std::array<mpq_class, 3> exact;
      for (int k = 0; k < 3; ++k) {
        const std::string w = word("a coordinate");
        auto d = parse_decimal_value(w);
        if (!d) fail(quote_token(w) + " is not a finite number", true);
        p[k] = d->nearest;
        exact[k] = std::move(d->exact);
      }
      m.exact_vertices.push_back(std::move(exact));
    }
    expect("endloop");
    expect("endfacet");
    add_facet(m, corners);
  }

  bool at_end() const { return line_ >= lines_.size(); }
  std::size_t line_number() const { return at_end() ? (lines_.empty() ? 0 : lines_.back().number) : lines_[line_].number; }
  std::string word(const std::string& what = "a keyword") {
    if (at_end()) fail("file ends early: expected " + what);
    const std::string w = lines_[line_].tokens[token_];
    last_line_ = lines_[line_].number;
    if (++token_ == lines_[line_].tokens.size()) ++line_, token_ = 0;
    return w;
  }
  void expect(const std::string& keyword) {
    const std::string w = lower(word("'" + keyword + "'"));
    if (w != keyword) fail("expected '" + keyword + "', found " + quote_token(w), true);
  }
  void skip_rest_of_line() {
    if (token_ > 0) ++line_, token_ = 0;
  }
  [[noreturn]] void fail(const std::string& problem, bool at_last_word = false) const {
    format_error(source_, at_last_word ? last_line_ : line_number(), "ASCII STL: " + problem);
  }

  const std::string& source_;
  std::vector<TextLine> lines_;
  std::size_t line_ = 0, token_ = 0, last_line_ = 0;
};

bool begins_with_solid(const std::string& bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i]))) ++i;
  if (bytes.size() - i < 5) return false;
  return lower(bytes.substr(i, 5)) == "solid";
}

bool looks_binary(const std::string& bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 512);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c == 0 || (c < 32 && !std::isspace(c)) || c > 126) return true;
  }
  return false;
}

}  // namespace

TriangleMesh3 parse_stl(const std::string& bytes, const std::string& source) {
  std::uint64_t announced = 0, needed = 0;
  if (bytes.size() >= kHeaderBytes) {
    announced = little_endian_u32(bytes, 80);
    needed = kHeaderBytes + kFacetBytes * announced;
    if (needed == bytes.size()) return parse_binary_stl(bytes, source, static_cast<std::uint32_t>(announced));
  }
  const std::string size_text = "the file has " + std::to_string(bytes.size()) + " bytes";
  if (begins_with_solid(bytes) && !looks_binary(bytes)) return AsciiStl(bytes, source).read();
  if (bytes.size() < kHeaderBytes)
    throw ComplexFormatError(source + ": not an STL file: it does not begin with 'solid' (ASCII) and is shorter than "
                                      "the 84-byte header of a binary STL (" + size_text + ")");
  throw ComplexFormatError(source + ": binary STL: the header announces " + std::to_string(announced) +
                           " facets, which take 84 + 50 * " + std::to_string(announced) + " = " +
                           std::to_string(needed) + " bytes, but " + size_text);
}

}  // namespace grassfire
