// Binary images as shapes: the PNG / GIF rasters (io/image_raster.h) and the polygon of the
// foreground (shapes/image_shape.h), checked against hand-built expectations and against
// the definition: a pixel centre is inside the shape iff the pixel is foreground.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io/image_raster.h"
#include "pipeline/edf2d.h"
#include "shapes/image_shape.h"
#include "io/load_shape.h"
#include "support.h"

using namespace grassfire;
using grassfire::testing::run_cli;
using grassfire::testing::temp_path;

namespace {

// A raster from rows of '#' (foreground: black) and '.' (white), row 0 at the top.
GrayAlphaImage raster(const std::vector<std::string>& rows) {
  GrayAlphaImage im;
  im.height = static_cast<std::uint32_t>(rows.size());
  im.width = static_cast<std::uint32_t>(rows[0].size());
  for (const std::string& r : rows)
    for (char c : r) im.gray.push_back(c == '#' ? 0 : 255), im.alpha.push_back(255);
  return im;
}

// Exact parity of crossings of the ray from (px, py) towards +x (doubled coordinates are
// integers: every vertex is a multiple of 1/2), with the half-open rule; p is never on
// the boundary here (pixel centres are (odd, odd) in doubled coordinates, no edge passes
// through one).
bool inside(const Shape2& s, double px, double py) {
  bool in = false;
  for (const Ring& r : s.rings)
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const Point2 a = r.points[i], b = r.points[(i + 1) % r.points.size()];
      if ((a.y > py) == (b.y > py)) continue;
      // x of the crossing > px  <=>  sign of the orientation, by the edge's direction.
      const long double o = (long double)(b.x - a.x) * (py - a.y) - (long double)(b.y - a.y) * (px - a.x);
      if ((o > 0) == (b.y > a.y)) in = !in;
    }
  return in;
}

// The reference: the component of the foreground (flood fill) with the most pixels,
// the first in row order among equals.
std::vector<bool> largest_component(const std::vector<bool>& fg, int w, int h, bool eight) {
  std::vector<int> label(fg.size(), -1);
  std::vector<int> sizes;
  for (int start = 0; start < w * h; ++start) {
    if (!fg[start] || label[start] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    std::vector<int> todo{start};
    label[start] = id;
    while (!todo.empty()) {
      const int p = todo.back();
      todo.pop_back();
      ++sizes[id];
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = p % w + dx, y = p / w + dy;
          if ((!eight && dx && dy) || x < 0 || y < 0 || x >= w || y >= h || !fg[y * w + x] || label[y * w + x] >= 0)
            continue;
          label[y * w + x] = id;
          todo.push_back(y * w + x);
        }
    }
  }
  int best = 0;
  for (int i = 1; i < static_cast<int>(sizes.size()); ++i)
    if (sizes[i] > sizes[best]) best = i;
  std::vector<bool> keep(fg.size());
  for (std::size_t i = 0; i < fg.size(); ++i) keep[i] = label[i] == best;
  return keep;
}

double area(const Shape2& s) {
  double a = 0;
  for (const Ring& r : s.rings)
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const Point2 p = r.points[i], q = r.points[(i + 1) % r.points.size()];
      a += p.x * q.y - p.y * q.x;
    }
  return a / 2;
}

// Dark ('#') is the foreground here whatever the border holds (the auto rule is tested apart).
ImageShapeOptions options(PixelConnectivity c, ImageContour k, bool largest = false) {
  ImageShapeOptions o;
  o.connectivity = c, o.contour = k, o.largest = largest;
  o.foreground = ImageForeground::Dark;
  return o;
}

// The ring's vertices from its least one (validation keeps the reader's first vertex).
std::vector<Point2> from_least(std::vector<Point2> ring) {
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), [](const Point2& a, const Point2& b) {
                return a.x != b.x ? a.x < b.x : a.y < b.y;
              }), ring.end());
  return ring;
}

}  // namespace

TEST_CASE("image shapes: a block is the rectangle of its pixels, y up", "[image]") {
  const Shape2 s = image_shape(raster({".....", ".###.", ".###.", "....."}), {}, "block");
  REQUIRE(s.rings.size() == 1);
  REQUIRE(from_least(s.rings[0].points) == std::vector<Point2>{{1, 1}, {4, 1}, {4, 3}, {1, 3}});
  const Shape2 ms = image_shape(raster({".....", ".###.", ".###.", "....."}),
                                options(PixelConnectivity::Eight, ImageContour::MarchingSquares), "block");
  // The polygon through the centres' midpoints: every corner of the rectangle cut.
  CHECK(area(ms) == 6 - 4 * 0.125);
  CHECK(ms.rings[0].points.size() == 8);
}

TEST_CASE("image shapes: holes are clockwise rings, the outer ring counter-clockwise", "[image]") {
  const Shape2 s = image_shape(raster({".......", ".#####.", ".#..##.", ".#####.", "......."}), {}, "frame");
  REQUIRE(s.rings.size() == 2);
  CHECK(from_least(s.rings[0].points) == std::vector<Point2>{{1, 1}, {6, 1}, {6, 4}, {1, 4}});
  CHECK(from_least(s.rings[1].points) == std::vector<Point2>{{2, 2}, {2, 3}, {4, 3}, {4, 2}});  // clockwise
  CHECK(area(s) == 15 - 2);
  // With the frame on the image border, the border's class is the background: the auto
  // rule takes the two light pixels inside (use --foreground dark for the frame).
  CHECK(area(image_shape(raster({"#####", "#..##", "#####"}), {}, "frame")) == 2);
}

TEST_CASE("image shapes: saddles follow the connectivity", "[image]") {
  const GrayAlphaImage diagonal = raster({"#.", ".#"});
  const Shape2 joined = image_shape(diagonal, options(PixelConnectivity::Eight, ImageContour::PixelBoundary), "d");
  REQUIRE(joined.rings.size() == 1);
  CHECK(area(joined) == 2 + 0.25);  // a bridge: the two background corners cut by half a pixel
  CHECK_THROWS_WITH(image_shape(diagonal, options(PixelConnectivity::Four, ImageContour::PixelBoundary), "d"),
                    "d: the foreground has 2 components (4-connected) of 1 and 1 pixels; a shape is one component: "
                    "--largest keeps the largest");
  const Shape2 first =
      image_shape(diagonal, options(PixelConnectivity::Four, ImageContour::PixelBoundary, true), "d");
  CHECK(from_least(first.rings[0].points) == std::vector<Point2>{{0, 1}, {1, 1}, {1, 2}, {0, 2}});
  // A ring of pixels touching at corners: with 8-connectivity one shape with a hole.
  const GrayAlphaImage diamond = raster({".#.", "#.#", ".#."});
  const Shape2 ring = image_shape(diamond, options(PixelConnectivity::Eight, ImageContour::PixelBoundary), "diamond");
  CHECK(ring.rings.size() == 2);
  // Four pixels, and at each of the four saddles a bridge of two 1/8 corners (one outside,
  // one cut from the hole, the centre pixel).
  CHECK(area(ring) == 4 + 4 * 0.25);
}

TEST_CASE("image shapes: a pixel centre is inside iff its pixel is kept, on random images", "[image]") {
  std::mt19937 rng(20240613);
  for (int trial = 0; trial < 150; ++trial) {
    const int w = 2 + static_cast<int>(rng() % 11), h = 2 + static_cast<int>(rng() % 11);
    const double density = 0.3 + 0.5 * (rng() % 100) / 100.0;
    std::vector<std::string> rows(h, std::string(w, '.'));
    std::vector<bool> fg(w * h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if ((rng() % 1000) < density * 1000) rows[y][x] = '#', fg[y * w + x] = true;
    if (std::find(fg.begin(), fg.end(), true) == fg.end()) continue;
    for (const PixelConnectivity c : {PixelConnectivity::Four, PixelConnectivity::Eight})
      for (const ImageContour k : {ImageContour::PixelBoundary, ImageContour::MarchingSquares}) {
        INFO("trial " << trial << " connectivity " << (c == PixelConnectivity::Four ? 4 : 8) << " contour "
                      << (k == ImageContour::PixelBoundary ? "pixel" : "marching-squares"));
        const Shape2 s = image_shape(raster(rows), options(c, k, true), "random");  // validated inside
        const std::vector<bool> keep = largest_component(fg, w, h, c == PixelConnectivity::Eight);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) REQUIRE(inside(s, x + 0.5, h - y - 0.5) == keep[y * w + x]);
      }
  }
}

TEST_CASE("image shapes: the foreground rule", "[image]") {
  GrayAlphaImage dark = raster({"....", ".##.", "....", "...."});
  GrayAlphaImage light = dark;
  for (auto& g : light.gray) g = 255 - g;  // white on black, as MPEG-7 CE-Shape-1
  const Shape2 a = image_shape(dark, {}, "dark"), b = image_shape(light, {}, "light");
  CHECK(a.rings[0].points == b.rings[0].points);
  // Asked for the dark pixels of the white-on-black image: the black frame with a hole.
  ImageShapeOptions o;
  o.foreground = ImageForeground::Dark;
  const Shape2 frame = image_shape(light, o, "light");
  CHECK(frame.rings.size() == 2);
  CHECK(area(frame) == 16 - 2);
  o.foreground = ImageForeground::Light;
  CHECK(image_shape(light, o, "light").rings[0].points == a.rings[0].points);
}

TEST_CASE("image shapes: transparency decides when the image has it", "[image]") {
  GrayAlphaImage im = raster({"....", ".##.", "...."});
  for (std::size_t i = 0; i < im.alpha.size(); ++i) im.alpha[i] = im.gray[i] == 0 ? 255 : 0;
  for (auto& g : im.gray) g = 255;  // all white: only alpha tells the shape
  const Shape2 s = image_shape(im, {}, "alpha");
  CHECK(from_least(s.rings[0].points) == std::vector<Point2>{{1, 1}, {3, 1}, {3, 2}, {1, 2}});
  for (auto& a : im.alpha) a = 0;
  CHECK_THROWS_WITH(image_shape(im, {}, "clear"), "clear: the image has no foreground pixel (see --foreground)");
}

TEST_CASE("image files: PNG and GIF round trips and load_shape", "[image]") {
  GrayAlphaImage im = raster({"......", ".####.", ".#..#.", ".####.", "......"});
  im.gray[0] = 201, im.gray[1] = 130, im.gray[8] = 17;  // not only 0 and 255; same classes
  for (const char* ext : {".png", ".gif"}) {
    const std::string path = temp_path(std::string("frame") + ext);
    if (std::string(ext) == ".png")
      write_png(im, path);
    else
      write_gif(im, path);
    const GrayAlphaImage back = read_image(path);
    CHECK(back.width == im.width);
    CHECK(back.height == im.height);
    CHECK(back.gray == im.gray);
    CHECK(back.alpha == im.alpha);
    const Shape2 s = load_shape(path);
    CHECK(s.name == path);
    CHECK(s.rings.size() == 2);
    CHECK(area(s) == 12 - 2);
    std::remove(path.c_str());
  }
  GrayAlphaImage transparent = im;
  transparent.alpha[3] = 0;
  const std::string gif = temp_path("transparent.gif");
  write_gif(transparent, gif);
  CHECK(read_gif(gif).alpha == transparent.alpha);
  std::remove(gif.c_str());
}

TEST_CASE("image files: bad files name the file and the problem", "[image]") {
  const std::string png = temp_path("garbage.png"), gif = temp_path("garbage.gif");
  std::ofstream(png) << "not a png";
  std::ofstream(gif) << "GIF89a";
  CHECK_THROWS_WITH(read_image(png), Catch::StartsWith(png + ": cannot read as PNG"));
  CHECK_THROWS_WITH(read_image(gif), Catch::StartsWith(gif + ": "));
  CHECK_THROWS_AS(load_shape(png), ImageFormatError);
  CHECK_THROWS_WITH(load_shape(temp_path("missing.png")), Catch::Contains("no such file"));
  std::remove(png.c_str());
  std::remove(gif.c_str());
}

TEST_CASE("image shapes: the exact axis of a pixel bar, through the program", "[image][cli]") {
  const std::string path = temp_path("bar.png");
  write_png(raster({"..........", ".########.", ".########.", ".########.", ".########.", ".........."}), path);
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(load_shape(path), o);
  CHECK(r.polygon_report.construction == AxisConstruction::BoostPolygon);
  const Point2 ema = position_of(*r.graph, r.burning->ema.at(0).point);
  // The centre of the 8 x 4 bar [1, 9] x [1, 5] (x, y inside an edge are interpolated doubles).
  CHECK(ema.x == Approx(5).margin(1e-12));
  CHECK(ema.y == Approx(3).margin(1e-12));
  const auto valid = run_cli("validate " + path);
  CHECK(valid.code == 0);
  CHECK_THAT(valid.output, Catch::Contains("valid, 1 ring"));
  const auto ms = run_cli("edf2d " + path + " --exact --contour marching-squares --quiet");
  CHECK(ms.code == 0);
  CHECK(ms.output.empty());
  const auto bad = run_cli("edf2d " + path + " --connectivity 6");
  CHECK(bad.code == 1);
  CHECK_THAT(bad.output, Catch::Contains("option --connectivity must be 4 or 8, got '6'"));
  std::remove(path.c_str());
}
