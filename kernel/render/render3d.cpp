// render3d.cpp -- painter's-algorithm SVG renderer and SVG canvas (see header).
#include "render/render3d.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "support/xml_escape.h"

namespace grassfire {
namespace {

Point3d sub(const Point3d& a, const Point3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot3(const Point3d& a, const Point3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3d cross3(const Point3d& a, const Point3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point3d normalized(const Point3d& a) {
  const double n = std::sqrt(dot3(a, a));
  return n > 0 ? Point3d{a[0] / n, a[1] / n, a[2] / n} : a;
}
Point3d lerp3(const Point3d& a, const Point3d& b, double t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string points_attr(const std::vector<Point2d>& pts) {
  std::string s;
  for (const Point2d& p : pts) s += fmt(p[0]) + "," + fmt(p[1]) + " ";
  if (!s.empty()) s.pop_back();
  return s;
}

}  // namespace

std::string to_svg_color(const Rgb& c) {
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

Rgb hue_color(double t) {
  t = std::clamp(t, 0.0, 1.0);
  const double h = t * 5.0 / 6.0 * 6.0;  // hue 0 (red) .. 300 degrees (purple), in sixths
  const int i = static_cast<int>(std::floor(h));
  const double f = h - i;
  switch (std::min(i, 5)) {
    case 0: return {1, f, 0};
    case 1: return {1 - f, 1, 0};
    case 2: return {0, 1, f};
    case 3: return {0, 1 - f, 1};
    case 4: return {f, 0, 1};
    default: return {1, 0, 1};
  }
}

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
}

Rgb shade(const Rgb& c, double f) { return {c.r * f, c.g * f, c.b * f}; }

SvgCanvas::SvgCanvas(double width, double height) : width_(width), height_(height) {}

void SvgCanvas::polygon(const std::vector<Point2d>& pts, const Rgb& fill, double opacity) {
  const std::string col = to_svg_color(fill);
  body_ += "<polygon points=\"" + points_attr(pts) + "\" fill=\"" + col + "\" stroke=\"" + col +
           "\" stroke-width=\"0.6\" stroke-linejoin=\"round\"";
  if (opacity < 1) body_ += " fill-opacity=\"" + fmt(opacity) + "\" stroke-opacity=\"" + fmt(opacity) + "\"";
  body_ += "/>\n";
}

void SvgCanvas::polygon_outline(const std::vector<Point2d>& pts, const Rgb& fill, const Rgb& stroke, double sw) {
  body_ += "<polygon points=\"" + points_attr(pts) + "\" fill=\"" + to_svg_color(fill) + "\" stroke=\"" +
           to_svg_color(stroke) + "\" stroke-width=\"" + fmt(sw) + "\"/>\n";
}

void SvgCanvas::polyline(const std::vector<Point2d>& pts, const Rgb& stroke, double w, const std::string& dash) {
  body_ += "<polyline points=\"" + points_attr(pts) + "\" fill=\"none\" stroke=\"" + to_svg_color(stroke) +
           "\" stroke-width=\"" + fmt(w) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
  if (!dash.empty()) body_ += " stroke-dasharray=\"" + dash + "\"";
  body_ += "/>\n";
}

void SvgCanvas::circle(const Point2d& c, double r, const Rgb& fill, const Rgb& stroke, double sw) {
  body_ += "<circle cx=\"" + fmt(c[0]) + "\" cy=\"" + fmt(c[1]) + "\" r=\"" + fmt(r) + "\" fill=\"" +
           to_svg_color(fill) + "\" stroke=\"" + to_svg_color(stroke) + "\" stroke-width=\"" + fmt(sw) + "\"/>\n";
}

void SvgCanvas::text(const Point2d& p, const std::string& s, double size, const std::string& anchor, const Rgb& color) {
  body_ += "<text x=\"" + fmt(p[0]) + "\" y=\"" + fmt(p[1]) + "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"" +
           fmt(size) + "\" text-anchor=\"" + anchor + "\" fill=\"" + to_svg_color(color) + "\">" + xml_escape(s) + "</text>\n";
}

void SvgCanvas::rect(double x, double y, double w, double h, const Rgb& fill) {
  body_ += "<rect x=\"" + fmt(x) + "\" y=\"" + fmt(y) + "\" width=\"" + fmt(w) + "\" height=\"" + fmt(h) +
           "\" fill=\"" + to_svg_color(fill) + "\"/>\n";
}

std::string SvgCanvas::str() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fmt(width_) +
         "\" height=\"" + fmt(height_) + "\" viewBox=\"0 0 " + fmt(width_) + " " + fmt(height_) +
         "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body_ + "</svg>\n";
}

void SvgCanvas::save(const std::string& path) const {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write SVG");
  out << str();
  out.close();
  if (!out) throw std::runtime_error(path + ": write error");
}

Renderer3d::Renderer3d(const Camera& camera) : cam_(camera) {
  forward_ = normalized(sub(cam_.target, cam_.eye));
  right_ = normalized(cross3(forward_, cam_.up));
  up_ = cross3(right_, forward_);
}

Point3d Renderer3d::to_camera(const Point3d& p) const {
  const Point3d d = sub(p, cam_.eye);
  return {dot3(d, right_), dot3(d, up_), dot3(d, forward_)};
}

void Renderer3d::triangle(const Point3d& a, const Point3d& b, const Point3d& c, const Rgb& color) {
  const Point3d n = normalized(cross3(sub(b, a), sub(c, a)));
  const Point3d light = normalized({-forward_[0] + 0.5 * up_[0] + 0.3 * right_[0], -forward_[1] + 0.5 * up_[1] + 0.3 * right_[1],
                                    -forward_[2] + 0.5 * up_[2] + 0.3 * right_[2]});
  const double intensity = 0.45 + 0.55 * std::abs(dot3(n, light));
  prims_.push_back({0, {a, b, c}, shade(color, intensity), 0, "", "", {0, 0}});
}

void Renderer3d::scalar_triangle(const std::array<Point3d, 3>& p, const std::array<double, 3>& v, double lo, double hi,
                                 int n) {
  n = std::max(1, n);
  auto at = [&](int i, int j) {  // barycentric grid point (i, j) with i + j <= n
    const double a = static_cast<double>(i) / n, b = static_cast<double>(j) / n;
    return Point3d{p[0][0] + a * (p[1][0] - p[0][0]) + b * (p[2][0] - p[0][0]),
                   p[0][1] + a * (p[1][1] - p[0][1]) + b * (p[2][1] - p[0][1]),
                   p[0][2] + a * (p[1][2] - p[0][2]) + b * (p[2][2] - p[0][2])};
  };
  auto color_at = [&](double a, double b) {
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return Rgb{0.55, 0.55, 0.55};
    const double val = v[0] + a * (v[1] - v[0]) + b * (v[2] - v[0]);
    return hue_color(hi > lo ? (val - lo) / (hi - lo) : 0.0);
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      triangle(at(i, j), at(i + 1, j), at(i, j + 1), color_at((i + 1.0 / 3) / n, (j + 1.0 / 3) / n));
      if (i + j + 2 <= n)
        triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), color_at((i + 2.0 / 3) / n, (j + 2.0 / 3) / n));
    }
}

void Renderer3d::iso_lines(const std::array<Point3d, 3>& p, const std::array<double, 3>& v,
                           const std::vector<double>& levels, const Rgb& color, double width) {
  for (double level : levels) {
    std::vector<Point3d> cut;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const double a = v[i] - level, b = v[j] - level;
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      if ((a < 0 && b >= 0) || (a >= 0 && b < 0)) cut.push_back(lerp3(p[i], p[j], a / (a - b)));
    }
    if (cut.size() == 2) line(cut[0], cut[1], color, width);
  }
}

void Renderer3d::line(const Point3d& a, const Point3d& b, const Rgb& color, double width, const std::string& dash) {
  prims_.push_back({1, {a, b}, color, width, "", dash, {0, 0}});
}

void Renderer3d::point(const Point3d& p, double radius, const Rgb& fill) {
  prims_.push_back({2, {p}, fill, radius, "", "", {0, 0}});
}

void Renderer3d::label(const Point3d& p, const std::string& text, double size, const Point2d& offset) {
  prims_.push_back({3, {p}, {0, 0, 0}, size, text, "", offset});
}

void Renderer3d::render(SvgCanvas& canvas, double x0, double y0, double w, double h) const {
  struct Item {
    double depth;
    std::size_t index;
  };
  std::vector<Item> items;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
  std::vector<std::vector<Point3d>> cam(prims_.size());
  for (std::size_t i = 0; i < prims_.size(); ++i) {
    for (const Point3d& p : prims_[i].pts) {
      Point3d c = to_camera(p);
      if (c[2] <= 1e-9) c[2] = 1e-9;  // behind the camera: clamp (scenes are in front)
      cam[i].push_back(c);
      const double px = c[0] / c[2], py = c[1] / c[2];
      lo[0] = std::min(lo[0], px), hi[0] = std::max(hi[0], px);
      lo[1] = std::min(lo[1], py), hi[1] = std::max(hi[1], py);
      zmin = std::min(zmin, c[2]), zmax = std::max(zmax, c[2]);
    }
  }
  if (prims_.empty()) return;
  // Triangles sort by their centroid; lines and points by their nearest point, moved a
  // further 1% of the depth range towards the viewer, so that curves drawn on a surface
  // come after the small triangles they lie on.
  const double bias = 1e-2 * (zmax - zmin) + 1e-9;
  for (std::size_t i = 0; i < prims_.size(); ++i) {
    double z = 0, znear = std::numeric_limits<double>::infinity();
    for (const Point3d& c : cam[i]) z += c[2], znear = std::min(znear, c[2]);
    z /= static_cast<double>(cam[i].size());
    const int kind = prims_[i].kind;
    const double key = kind == 0 ? z : kind == 3 ? -std::numeric_limits<double>::infinity() : znear - bias * kind;
    items.push_back({key, i});
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.depth > b.depth; });
  const double margin = 0.04;
  const double sx = (hi[0] - lo[0]) > 0 ? w * (1 - 2 * margin) / (hi[0] - lo[0]) : 1;
  const double sy = (hi[1] - lo[1]) > 0 ? h * (1 - 2 * margin) / (hi[1] - lo[1]) : 1;
  const double s = std::min(sx, sy);
  const double ox = x0 + 0.5 * (w - s * (hi[0] - lo[0])), oy = y0 + 0.5 * (h + s * (hi[1] - lo[1]));
  auto screen = [&](const Point3d& c) { return Point2d{ox + s * (c[0] / c[2] - lo[0]), oy - s * (c[1] / c[2] - lo[1])}; };
  for (const Item& it : items) {
    const Prim& p = prims_[it.index];
    std::vector<Point2d> pts;
    for (const Point3d& c : cam[it.index]) pts.push_back(screen(c));
    if (p.kind == 0) canvas.polygon(pts, p.color);
    if (p.kind == 1) canvas.polyline(pts, p.color, p.width, p.dash);
    if (p.kind == 2) canvas.circle(pts[0], p.width, p.color, {0, 0, 0}, 0.8);
    if (p.kind == 3) canvas.text({pts[0][0] + p.offset[0], pts[0][1] + p.offset[1]}, p.text, p.width, "middle");
  }
}

}  // namespace grassfire
