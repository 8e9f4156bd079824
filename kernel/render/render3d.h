// render3d.h -- a small software renderer to SVG for the figures of chapter 4.
//
// Computes: SVG pictures of triangles, lines, points and labels in R^3 seen through a
// perspective camera: painter's algorithm (triangles sorted far to near by the depth of
// their centroid, lines and points by their nearest point biased towards the viewer by 1%
// of the depth range, so that curves lying on a surface stay visible), flat Lambert shading of triangles lit from the camera
// side (two-sided), and a hue colour map for scalar fields (red = low to purple = high,
// as the dissertation's figures). SvgCanvas is the 2D layer underneath, also used for
// plots. Painter's sorting is not exact visibility: intersecting or long thin triangles
// can be mis-ordered, so scenes are built from small triangles (callers subdivide).
// Complexity: O(p log p) for p primitives.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace grassfire {

using Point2d = std::array<double, 2>;
using Point3d = std::array<double, 3>;

struct Rgb {
  double r = 0, g = 0, b = 0;  // in [0, 1]
};
std::string to_svg_color(const Rgb& c);
// Hue from red (t = 0) through yellow, green, cyan, blue to purple (t = 1); t is clamped.
Rgb hue_color(double t);
Rgb mix(const Rgb& a, const Rgb& b, double t);
Rgb shade(const Rgb& c, double factor);  // factor in [0, 1]: towards black

class SvgCanvas {
 public:
  SvgCanvas(double width, double height);
  double width() const { return width_; }
  double height() const { return height_; }
  void polygon(const std::vector<Point2d>& points, const Rgb& fill, double opacity = 1.0);
  void polygon_outline(const std::vector<Point2d>& points, const Rgb& fill, const Rgb& stroke, double stroke_width);
  void polyline(const std::vector<Point2d>& points, const Rgb& stroke, double width, const std::string& dash = "");
  void circle(const Point2d& c, double r, const Rgb& fill, const Rgb& stroke, double stroke_width);
  // anchor: "start", "middle" or "end".
  void text(const Point2d& p, const std::string& s, double size, const std::string& anchor = "start",
            const Rgb& color = {0, 0, 0});
  void rect(double x, double y, double w, double h, const Rgb& fill);
  std::string str() const;
  void save(const std::string& path) const;  // throws std::runtime_error naming the file

 private:
  double width_, height_;
  std::string body_;
};

struct Camera {
  Point3d eye{10, -10, 10};
  Point3d target{0, 0, 0};
  Point3d up{0, 0, 1};
  double fov_degrees = 30;
};

class Renderer3d {
 public:
  explicit Renderer3d(const Camera& camera);

  void triangle(const Point3d& a, const Point3d& b, const Point3d& c, const Rgb& color);
  // A triangle coloured by a scalar per vertex, subdivided `n` times per edge so that the
  // colour follows the field (values mapped by hue_color((v - lo) / (hi - lo))).
  void scalar_triangle(const std::array<Point3d, 3>& p, const std::array<double, 3>& v, double lo, double hi,
                       int subdivisions);
  // Iso-curves of the linear interpolation of v over the triangle, at the given levels.
  void iso_lines(const std::array<Point3d, 3>& p, const std::array<double, 3>& v, const std::vector<double>& levels,
                 const Rgb& color, double width);
  void line(const Point3d& a, const Point3d& b, const Rgb& color, double width, const std::string& dash = "");
  void point(const Point3d& p, double radius, const Rgb& fill);
  void label(const Point3d& p, const std::string& text, double size, const Point2d& offset = {0, 0});

  // Draws everything into the rectangle (x, y, w, h) of the canvas, scaled to fit.
  void render(SvgCanvas& canvas, double x, double y, double w, double h) const;

 private:
  struct Prim {
    int kind;  // 0 triangle, 1 line, 2 point, 3 label
    std::vector<Point3d> pts;
    Rgb color;
    double width = 0;
    std::string text, dash;
    Point2d offset{0, 0};
  };
  Point3d to_camera(const Point3d& p) const;
  Camera cam_;
  Point3d right_, up_, forward_;
  std::vector<Prim> prims_;
};

}  // namespace grassfire
