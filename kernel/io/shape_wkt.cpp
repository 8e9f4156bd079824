// shape_wkt.cpp -- see shape_wkt.h.
#include "io/shape_wkt.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "support/quoted.h"

namespace grassfire {

namespace {

// A recursive-descent reader over the text. Tokens are '(', ')', ',', ';' and words: runs
// of any other non-space characters (keywords and numbers alike).
class WktReader {
 public:
  WktReader(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  Shape2 read() {
    Shape2 shape;
    shape.name = source_;
    skip_space();
    const Position start = position();
    const std::string type = upper(expect_word("a geometry type (POLYGON)"));
    if (type == "POLYGON") {
      expect_2d("POLYGON");
      shape.rings = polygon_text();
    } else if (type == "MULTIPOLYGON") {
      expect_2d("MULTIPOLYGON");
      expect('(');
      shape.rings = polygon_text();
      skip_space();
      if (peek() == ',')
        fail("MULTIPOLYGON with more than one polygon: a shape is one polygon with holes; "
             "give each polygon its own file");
      expect(')');
    } else {
      fail_at(start, "expected POLYGON or MULTIPOLYGON, found " + quote_token(type));
    }
    skip_space();
    if (peek() == ';') advance();
    skip_space();
    if (pos_ < text_.size()) fail("unexpected text after the end of the polygon: '" + token_preview() + "'");
    return shape;
  }

 private:
  std::vector<Ring> polygon_text() {
    std::vector<Ring> rings;
    expect('(');
    do {
      rings.push_back(ring_text(rings.size()));
    } while (accept(','));
    expect(')');
    return rings;
  }

  Ring ring_text(std::size_t ring) {
    Ring r;
    expect('(');
    do {
      const std::string where = "point " + std::to_string(r.points.size()) + " of ring " + std::to_string(ring);
      const double x = number("x of " + where);
      const double y = number("y of " + where);
      r.points.push_back({x, y});
      skip_space();
      if (pos_ < text_.size() && !is_delimiter(peek()))
        fail("expected ',' or ')' after " + where + "; only 2D coordinates (x y) are supported");
    } while (accept(','));
    expect(')');
    return r;
  }

  void expect_2d(const std::string& type) {
    skip_space();
    if (peek() == '(') return;
    const Position start = position();
    const std::string word = upper(expect_word("'('"));
    if (word == "EMPTY") fail_at(start, type + " EMPTY: the shape has no rings (empty input)");
    if (word == "Z" || word == "M" || word == "ZM")
      fail_at(start, type + " " + word + ": only 2D coordinates are supported");
    fail_at(start, "expected '(' after " + quote_token(type) + ", found " + quote_token(word));
  }

  double number(const std::string& what) {
    skip_space();
    const Position start = position();
    const std::string word = expect_word("a number (" + what + ")");
    const char* first = word.data() + (word[0] == '+' ? 1 : 0);
    const char* last = word.data() + word.size();
    double value = 0.0;
    const std::from_chars_result r = std::from_chars(first, last, value);
    if (r.ec == std::errc::result_out_of_range) fail_at(start, what + " " + quote_token(word) + " is out of the range of doubles");
    if (r.ec != std::errc() || r.ptr != last) fail_at(start, "expected a number (" + what + "), found " + quote_token(word));
    if (!std::isfinite(value)) fail_at(start, what + " is not a finite number (" + quote_token(word) + ")");
    return value;
  }

  static bool is_delimiter(char c) { return c == '(' || c == ')' || c == ',' || c == ';'; }
  char peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) advance();
  }
  bool accept(char c) {
    skip_space();
    if (peek() != c || pos_ >= text_.size()) return false;
    advance();
    return true;
  }
  void expect(char c) {
    if (!accept(c)) fail(std::string("expected '") + c + "', found " + describe_next());
  }
  std::string expect_word(const std::string& what) {
    skip_space();
    if (pos_ >= text_.size() || is_delimiter(peek())) fail("expected " + what + ", found " + describe_next());
    std::string word;
    while (pos_ < text_.size() && !is_delimiter(peek()) && !std::isspace(static_cast<unsigned char>(peek()))) {
      word += peek();
      advance();
    }
    return word;
  }
  std::string token_preview() const { return text_.substr(pos_, 20); }
  std::string describe_next() const {
    if (pos_ >= text_.size()) return "the end of the text";
    return "'" + token_preview() + "'";
  }
  static std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  }
  struct Position {
    std::size_t line, column;
  };
  Position position() const { return {line_, column_}; }
  [[noreturn]] void fail_at(const Position& at, const std::string& problem) const {
    throw ShapeFormatError(source_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + problem);
  }
  [[noreturn]] void fail(const std::string& problem) const { fail_at(position(), problem); }

  const std::string& text_;
  const std::string& source_;
  std::size_t pos_ = 0, line_ = 1, column_ = 1;
};

}  // namespace

Shape2 parse_shape_wkt(const std::string& text, const std::string& source) { return WktReader(text, source).read(); }

Shape2 read_shape_wkt(const std::string& path) { return parse_shape_wkt(read_shape_file_text(path), path); }

void write_shape_wkt(const Shape2& shape, std::ostream& out) {
  if (shape.rings.empty()) {
    out << "POLYGON EMPTY\n";
    return;
  }
  out << "POLYGON (";
  for (std::size_t r = 0; r < shape.rings.size(); ++r) {
    const std::vector<Point2>& p = shape.rings[r].points;
    out << (r ? ",\n  (" : "\n  (");
    for (std::size_t i = 0; i <= p.size() && !p.empty(); ++i) {
      const Point2& q = p[i % p.size()];  // closed: the first point again at the end
      out << (i ? ", " : "") << shortest_double(q.x) << " " << shortest_double(q.y);
    }
    out << ")";
  }
  out << "\n)\n";
}

std::string to_wkt(const Shape2& shape) {
  std::ostringstream out;
  write_shape_wkt(shape, out);
  return out.str();
}

}  // namespace grassfire
