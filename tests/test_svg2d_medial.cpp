// Pictures of 2D results (render/svg_medial2.h): well-formed SVG, one element per drawn edge
// piece, the EMA marker, the colour-bar range against the EDF computed from the fire entry
// times, and `grassfire edf2d --svg`.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "render/svg_medial2.h"
#include "pipeline/edf2d.h"
#include "shapes/builtin_shapes.h"
#include "support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

// A minimal XML well-formedness check: balanced, properly nested tags, quoted attribute
// values, nothing but entity references after '&'. Returns "" or what is wrong.
std::string xml_problem(const std::string& s) {
  std::vector<std::string> open;
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == '&') {
      const std::size_t semi = s.find(';', i);
      if (semi == std::string::npos || semi - i > 8) return "bare & at " + std::to_string(i);
      i = semi + 1;
      continue;
    }
    if (s[i] != '<') {
      if (s[i] == '>') return "stray > at " + std::to_string(i);
      ++i;
      continue;
    }
    if (s.compare(i, 2, "<?") == 0) {
      const std::size_t end = s.find("?>", i);
      if (end == std::string::npos) return "unterminated <?";
      i = end + 2;
      continue;
    }
    std::size_t j = i + 1;
    bool quoted = false;
    char quote = 0;
    while (j < s.size() && (quoted || s[j] != '>')) {
      if (s[j] == '"' || s[j] == '\'') {
        if (!quoted)
          quoted = true, quote = s[j];
        else if (s[j] == quote)
          quoted = false;
      } else if (!quoted && s[j] == '<') {
        return "< inside a tag at " + std::to_string(j);
      }
      ++j;
    }
    if (j >= s.size()) return "unterminated tag at " + std::to_string(i);
    const std::string tag = s.substr(i + 1, j - i - 1);
    if (tag.empty()) return "empty tag";
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return "mismatched </" + tag.substr(1) + ">";
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
    }
    i = j + 1;
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
  return n;
}

// The texts of all <text> elements.
std::vector<std::string> texts(const std::string& svg) {
  std::vector<std::string> out;
  const std::regex re("<text[^>]*>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

bool has_text(const std::string& svg, const std::string& t) {
  const auto all = texts(svg);
  return std::find(all.begin(), all.end(), t) != all.end();
}

// One piece per linear part of every edge, and an axis width no other element has.
Medial2SvgOptions whole_pieces() {
  Medial2SvgOptions o;
  o.max_piece = 1e9;
  o.axis_width = 3.3;
  return o;
}

Shape2 box_shape() {
  return {"box", {Ring{{{-1, -1}, {4, -1}, {4, 1}, {-1, 1}}}}};
}

// The finite EDF range from the fire entry times alone: node values, and along each edge
// the value at its far end (one side sent fire) or at the quench point (both sent).
std::pair<double, double> reference_edf_range(const MedialGraph& g, const GrassfireResult& r) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto add = [&](double v) { lo = std::min(lo, v), hi = std::max(hi, v); };
  for (std::uint32_t v = 0; v < g.node_count(); ++v)
    if (!r.is_infinite(v)) add(r.edf(v).mid());
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const EdgeFire& f = r.fire[e];
    const double w = g.edge(e).length.mid();
    const double tu = f.from_u == kNoTime ? 0 : r.times.approx(f.from_u).mid();
    const double tv = f.from_v == kNoTime ? 0 : r.times.approx(f.from_v).mid();
    if (f.from_u != kNoTime && f.from_v != kNoTime)
      add(0.5 * (tu + tv + w));
    else if (f.from_u != kNoTime)
      add(tu + w);
    else if (f.from_v != kNoTime)
      add(tv + w);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("svg of a star: one polyline per edge piece, the EMA point, the colour-bar range", "[svg2d]") {
  // Leaves 1, 2, 3 send fire; the fronts on edge 0 quench inside it (EDF 13/2 there), so
  // edge 0 is drawn in two pieces and edges 1, 2 in one each.
  const MedialGraph g = integer_graph({1, 0, 1, 2}, {{0, 1, 10}, {0, 2, 1}, {0, 3, 1}});
  const GrassfireResult r = extended_grassfire(g);
  const NodeMeasures m = node_measures(g, r);
  Medial2SvgOptions o = whole_pieces();
  const std::string svg = medial2_svg(box_shape(), g, r, m, o);
  CHECK(xml_problem(svg).empty());
  CHECK(count(svg, "<polyline") - count(svg, "stroke-width=\"1.00\"") - count(svg, "stroke-width=\"1.98\"") == 4);
  CHECK(count(svg, "stroke-width=\"3.30\"") == 4);
  // The EMA point: a black ring and a grey dot with a white ring; nothing else is a circle.
  CHECK(count(svg, "<circle") == 2);
  CHECK(count(svg, "fill=\"#737373\" stroke=\"#ffffff\"") == 1);

  const Medial2FieldRange range = medial2_field_range(g, r, m, Medial2Field::Edf);
  CHECK(range.lo == Approx(0.0).margin(1e-12));
  CHECK(range.hi == Approx(6.5).epsilon(1e-12));
  CHECK_FALSE(range.has_infinite);
  CHECK(has_text(svg, "EDF"));
  CHECK(has_text(svg, "0"));
  CHECK(has_text(svg, "6.5"));
  CHECK_FALSE(has_text(svg, "\xe2\x88\x9e"));

  SvgCanvas c(800, 400);
  o.max_piece = 1;  // edge lengths 10, 1, 1 in a frame of about 150 px per unit
  const std::size_t pieces = draw_medial2(c, 0, 0, 800, 400, box_shape(), g, r, m, o);
  CHECK(pieces > 100);
  CHECK(count(c.str(), "stroke-width=\"3.30\"") == pieces);
}

TEST_CASE("svg with a cycle: the EMA loop in grey, infinite values, the finite range", "[svg2d]") {
  const MedialGraph g = integer_graph({2, 2, 2, 1, 0}, {{0, 1, 1}, {1, 2, 1}, {2, 0, 1}, {2, 3, 1}, {3, 4, 1}});
  const GrassfireResult r = extended_grassfire(g);
  const NodeMeasures m = node_measures(g, r);
  Medial2SvgOptions o = whole_pieces();
  const std::string svg = medial2_svg(box_shape(), g, r, m, o);
  CHECK(xml_problem(svg).empty());
  // The finite EDF reaches 2 where the pendant path meets the cycle (the edge-side limit).
  const Medial2FieldRange range = medial2_field_range(g, r, m, Medial2Field::Edf);
  CHECK(range.lo == Approx(0.0).margin(1e-12));
  CHECK(range.hi == Approx(2.0).epsilon(1e-12));
  CHECK(range.has_infinite);
  CHECK(has_text(svg, "\xe2\x88\x9e"));
  CHECK(count(svg, "stroke=\"#999999\" stroke-width=\"11.22\"") == 3);  // the 2-core's three edges
  CHECK(count(svg, "stroke=\"" + to_svg_color(kInfiniteColour) + "\" stroke-width=\"3.30\"") == 3);
  CHECK(count(svg, "<circle") == 0);
  // ST is 1 on the cycle (finite), ET infinite there.
  CHECK_FALSE(medial2_field_range(g, r, m, Medial2Field::St).has_infinite);
  CHECK(medial2_field_range(g, r, m, Medial2Field::Et).has_infinite);
}

TEST_CASE("svg of the hole shape: well-formed, colour bar = finite EDF range, R background", "[svg2d]") {
  const Shape2 shape = builtin_shape("hole");
  Edf2dOptions eo;
  eo.samples = 600;
  const Edf2dResult res = compute_edf2d(shape, eo);
  const MedialGraph& g = *res.graph;
  const GrassfireResult& r = *res.burning;
  const auto [lo, hi] = reference_edf_range(g, r);
  const Medial2FieldRange range = medial2_field_range(g, r, res.measures, Medial2Field::Edf);
  CHECK(range.lo == Approx(lo).margin(1e-12));
  CHECK(range.hi == Approx(hi).epsilon(1e-12));
  CHECK(range.has_infinite);
  Medial2SvgOptions o;
  o.distance_background = true;
  o.samples = &res.samples;
  o.title = "hole";
  const std::string svg = medial2_svg(shape, g, r, res.measures, o);
  CHECK(xml_problem(svg).empty());
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", hi);
  CHECK(has_text(svg, buf));
  CHECK(has_text(svg, "R"));
  CHECK(count(svg, "<circle") == 600);  // the samples; the EMA is a loop
  CHECK(count(svg, "<rect") > 100);     // the background raster
}

TEST_CASE("field names parse: bad ones are rejected", "[svg2d]") {
  CHECK(parse_medial2_field("EDF") == Medial2Field::Edf);
  CHECK(parse_medial2_field("et") == Medial2Field::Et);
  CHECK(parse_medial2_field("St") == Medial2Field::St);
  CHECK(parse_medial2_field("r") == Medial2Field::R);
  CHECK_THROWS_AS(parse_medial2_field("edf2"), std::invalid_argument);
  CHECK(heat_color(0).b == 1.0);
  CHECK(heat_color(1).r == 1.0);
}

TEST_CASE("grassfire edf2d --svg writes a picture: a bad --field writes nothing", "[svg2d]") {
  const std::string out = grassfire::testing::temp_path("test_svg2d_cli.svg");
  const std::string json = grassfire::testing::temp_path("test_svg2d_cli.json");
  std::remove(out.c_str());
  std::remove(json.c_str());
  const std::string cli = std::string(GF_CLI) + " edf2d rectangle --exact --quiet --svg " + out;
  REQUIRE(std::system((cli + " --field et").c_str()) == 0);
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(xml_problem(ss.str()).empty());
  CHECK(has_text(ss.str(), "ET"));
  std::remove(out.c_str());
  CHECK(std::system((cli + " --json " + json + " --field depth > /dev/null 2>&1").c_str()) != 0);
  CHECK_FALSE(std::ifstream(out).good());
  CHECK_FALSE(std::ifstream(json).good());
}
