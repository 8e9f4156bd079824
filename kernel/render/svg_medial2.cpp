// svg_medial2.cpp -- see svg_medial2.h.
#include "render/svg_medial2.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace grassfire {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMargin = 12;      // px around the shape
constexpr double kTitleStrip = 30;  // px
constexpr double kBarStrip = 72;    // px
const Rgb kFill{0.92, 0.92, 0.92}, kBoundary{0.15, 0.15, 0.15}, kWhite{1, 1, 1}, kBlack{0, 0, 0};
const Rgb kEmaGrey{0.6, 0.6, 0.6};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

double font_size(double width) {
  return std::clamp(width / 45, 12.0, 18.0);
}

struct Box {
  double minx = kInf, miny = kInf, maxx = -kInf, maxy = -kInf;
};
Box bounding_box(const Shape2& shape) {
  Box b;
  for (const Ring& r : shape.rings)
    for (const Point2& p : r.points) {
      b.minx = std::min(b.minx, p.x), b.maxx = std::max(b.maxx, p.x);
      b.miny = std::min(b.miny, p.y), b.maxy = std::max(b.maxy, p.y);
    }
  if (!(b.maxx > b.minx && b.maxy > b.miny)) throw std::invalid_argument("svg: the shape " + shape.name + " is empty");
  return b;
}

// Grey level of R in the background: dark at the boundary, white at the largest R.
Rgb distance_grey(double r, double r_max) {
  const double t = r_max > 0 ? std::clamp(r / r_max, 0.0, 1.0) : 0.0;
  const double g = 0.3 + 0.7 * t;
  return {g, g, g};
}

double node_value(const MedialGraph& g, const GrassfireResult& r, const NodeMeasures& m, Medial2Field field,
                  std::uint32_t v) {
  switch (field) {
    case Medial2Field::Edf:
      return r.edf(v).mid();
    case Medial2Field::Et:
      return m.erosion_thickness[v].mid();
    case Medial2Field::St:
      return m.tubularity[v].mid();
    case Medial2Field::R:
      break;
  }
  return g.node(v).radius.mid();
}

double max_radius(const MedialGraph& g) {
  double r = 0;
  for (const MedialNode& n : g.nodes()) r = std::max(r, n.radius.mid());
  return r;
}

void draw_distance_background(SvgCanvas& c, const Medial2Frame& f, const Shape2& shape, const MedialGraph& g,
                              double cell, double x, double y, double w, double h) {
  const Box b = bounding_box(shape);
  const Point2d lo = f({b.minx, b.maxy}), hi = f({b.maxx, b.miny});
  const double r_max = max_radius(g);
  constexpr int kLevels = 48;
  for (double cy = lo[1]; cy < hi[1]; cy += cell) {
    int run_level = -1;
    double run_start = lo[0];
    for (double cx = lo[0]; cx <= hi[0] + cell; cx += cell) {
      int level = -1;
      if (cx < hi[0]) {
        const double d = boundary_distance(shape, f.world({cx + cell / 2, cy + cell / 2}));
        level = static_cast<int>(std::lround(std::clamp(d / r_max, 0.0, 1.0) * (kLevels - 1)));
      }
      if (level == run_level) continue;
      if (run_level >= 0)
        c.rect(run_start, cy, cx - run_start + 0.6, cell + 0.6,
               distance_grey(run_level * r_max / (kLevels - 1), r_max));
      run_level = level, run_start = cx;
    }
  }
  // White over the outside (the panel box with the outer ring cut out) and the holes.
  std::vector<Point2d> mask{{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}, {x, y}};
  for (const Point2& p : shape.rings[0].points) mask.push_back(f(p));
  mask.push_back(f(shape.rings[0].points[0]));
  c.polygon_outline(mask, kWhite, kWhite, 0);
  for (std::size_t i = 1; i < shape.rings.size(); ++i) {
    std::vector<Point2d> hole;
    for (const Point2& p : shape.rings[i].points) hole.push_back(f(p));
    c.polygon_outline(hole, kWhite, kWhite, 0);
  }
}

void draw_ema(SvgCanvas& c, const Medial2Frame& f, const MedialGraph& g, const GrassfireResult& r, double axis_width,
              bool cycles) {
  for (const ExtendedMedialAxis& ema : r.ema) {
    if (ema.kind == ExtendedMedialAxis::Kind::Cycles && cycles) {
      for (std::uint32_t e : ema.edges) {
        std::vector<Point2d> pts;
        for (const Point2& p : g.geometry().polyline(g, e)) pts.push_back(f(p));
        c.polyline(pts, kEmaGrey, 3.4 * axis_width);
      }
    }
    if (ema.kind == ExtendedMedialAxis::Kind::Point && !cycles) {
      const Point2d p = f(position_of(g, ema.point));
      const double radius = 3.4 * axis_width;
      c.circle(p, radius + 0.8 * axis_width, kBlack, kBlack, 0);
      c.circle(p, radius, {0.45, 0.45, 0.45}, kWhite, 0.7 * axis_width);
    }
  }
}

// A horizontal bar from lo to hi with `ticks` + 1 labelled ticks; `colour` maps t in [0, 1].
template <class Colour>
void bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& name, double fs,
         int ticks, Colour&& colour) {
  c.text({x, y + 12}, name, fs, "start");
  const double bx = x + 4.2 * fs, bw = w - 4.2 * fs - fs;
  constexpr int kSteps = 96;
  for (int i = 0; i < kSteps; ++i) c.rect(bx + bw * i / kSteps, y, bw / kSteps + 0.5, 14, colour((i + 0.5) / kSteps));
  const double unit = std::max(std::fabs(lo), std::fabs(hi));
  for (int k = 0; k <= ticks; ++k) {
    const double tx = bx + bw * k / ticks, v = lo + (hi - lo) * k / ticks;
    c.polyline({{tx, y + 14}, {tx, y + 19}}, kBlack, 1);
    // Rounding residue such as ET = -3e-18 at a leaf is printed as the 0 it stands for.
    c.text({tx, y + 20 + fs}, number(std::fabs(v) < 1e-9 * unit ? 0.0 : v), 0.85 * fs, "middle");
  }
}

void draw_colour_bars(SvgCanvas& c, double x, double y, double w, const std::string& name,
                      const Medial2FieldRange& range, const Medial2SvgOptions& o, double r_max) {
  const double fs = font_size(w);
  const double heat_w = o.distance_background ? 0.56 * w : 0.8 * w;
  bar(c, x, y, heat_w, range.lo, range.hi, name, fs, 4, heat_color);
  if (range.has_infinite) {
    const double sx = x + heat_w + 0.6 * fs;
    c.rect(sx, y, 1.6 * fs, 14, kInfiniteColour);
    c.text({sx + 0.8 * fs, y + 20 + fs}, "\xe2\x88\x9e", fs, "middle");  // infinity sign
  }
  if (o.distance_background)
    bar(c, x + 0.64 * w, y, 0.36 * w, 0, r_max, "R", fs, 2, [&](double t) { return distance_grey(t * r_max, r_max); });
}

}  // namespace

const char* to_string(Medial2Field f) {
  switch (f) {
    case Medial2Field::Edf:
      return "EDF";
    case Medial2Field::Et:
      return "ET";
    case Medial2Field::St:
      return "ST";
    case Medial2Field::R:
      return "R";
  }
  return "?";
}

Medial2Field parse_medial2_field(const std::string& name) {
  std::string s;
  for (char ch : name) s += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (s == "edf") return Medial2Field::Edf;
  if (s == "et") return Medial2Field::Et;
  if (s == "st") return Medial2Field::St;
  if (s == "r") return Medial2Field::R;
  throw std::invalid_argument("field must be edf, et, st or r, got '" + name + "'");
}

// The quench point lies at (w + Tv - Tu) / 2 from u (docs/design.md 4).
std::vector<double> field_breakpoints(const MedialGraph& g, const GrassfireResult& r, std::uint32_t e) {
  const double w = g.edge(e).length.mid();
  std::vector<double> s{0.0};
  const EdgeFire& f = r.fire[e];
  if (f.from_u != kNoTime && f.from_v != kNoTime) {
    const double q = 0.5 * (w + r.times.approx(f.from_v).mid() - r.times.approx(f.from_u).mid());
    if (q > 0 && q < w) s.push_back(q);
  }
  s.push_back(w);
  return s;
}

Rgb heat_color(double t) {
  return hue_color(0.8 * (1.0 - std::clamp(t, 0.0, 1.0)));
}

double medial2_field_along(const MedialGraph& g, const GrassfireResult& r, Medial2Field field, std::uint32_t edge,
                           std::uint32_t from, double s) {
  const double w = g.edge(edge).length.mid();
  const double ra = g.node(from).radius.mid(), rb = g.node(g.other_end(edge, from)).radius.mid();
  const double radius = w > 0 ? ra + (rb - ra) * std::clamp(s / w, 0.0, 1.0) : ra;
  const double edf = r.edf_along(edge, from, s).mid();
  switch (field) {
    case Medial2Field::Edf:
      return edf;
    case Medial2Field::Et:
      return edf - radius;  // infinite with the EDF
    case Medial2Field::St:
      // ST = 0 at an R = 0 leaf (3.5.1), where the display EDF may be rounding noise above 0.
      return std::isinf(edf) ? 1.0 : edf > 0 && radius > 0 ? 1.0 - radius / edf : 0.0;
    case Medial2Field::R:
      break;
  }
  return radius;
}

Medial2FieldRange medial2_field_range(const MedialGraph& g, const GrassfireResult& r, const NodeMeasures& m,
                                      Medial2Field field) {
  Medial2FieldRange range;
  double lo = kInf, hi = -kInf;
  auto add = [&](double v) {
    if (std::isinf(v)) {
      range.has_infinite = true;
      return;
    }
    lo = std::min(lo, v), hi = std::max(hi, v);
  };
  for (std::uint32_t v = 0; v < g.node_count(); ++v) add(node_value(g, r, m, field, v));
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    for (double s : field_breakpoints(g, r, e)) add(medial2_field_along(g, r, field, e, g.edge(e).u, s));
  if (lo <= hi) range.lo = lo, range.hi = hi;
  return range;
}

Medial2Frame::Medial2Frame(const Shape2& shape, double x, double y, double w, double h) {
  const Box b = bounding_box(shape);
  scale_ = std::min(w / (b.maxx - b.minx), h / (b.maxy - b.miny));
  ox_ = x + 0.5 * (w - scale_ * (b.maxx - b.minx)) - scale_ * b.minx;
  oy_ = y + 0.5 * (h + scale_ * (b.maxy - b.miny)) + scale_ * b.miny;
}

std::vector<Point2d> shape_polygon(const Medial2Frame& f, const Shape2& shape) {
  std::vector<Point2d> pts;
  const Point2d anchor = f(shape.rings.at(0).points.at(0));
  for (const Point2& p : shape.rings[0].points) pts.push_back(f(p));
  pts.push_back(anchor);
  for (std::size_t i = 1; i < shape.rings.size(); ++i) {
    for (const Point2& p : shape.rings[i].points) pts.push_back(f(p));
    pts.push_back(f(shape.rings[i].points[0]));
    pts.push_back(anchor);
  }
  return pts;
}

double boundary_distance(const Shape2& shape, const Point2& p) {
  double best = kInf;
  for (const Ring& ring : shape.rings) {
    const std::size_t n = ring.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& a = ring.points[i];
      const Point2& b = ring.points[(i + 1) % n];
      const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy));
    }
  }
  return best;
}

void draw_boundary(SvgCanvas& c, const Medial2Frame& f, const Shape2& shape, const Rgb& colour, double width) {
  for (const Ring& ring : shape.rings) {
    std::vector<Point2d> pts;
    for (const Point2& p : ring.points) pts.push_back(f(p));
    pts.push_back(f(ring.points[0]));
    c.polyline(pts, colour, width);
  }
}

std::vector<Point2d> edge_points(const Medial2Frame& f, const MedialGraph& g, std::uint32_t edge,
                                 const std::vector<double>& s) {
  std::vector<Point2d> pts;
  for (double si : s) pts.push_back(f(g.geometry().point_along(g, edge, g.edge(edge).u, si)));
  return pts;
}

double medial2_panel_height(const Shape2& shape, const Medial2SvgOptions& o, double width) {
  const Box b = bounding_box(shape);
  const double plot = std::min((width - 2 * kMargin) * (b.maxy - b.miny) / (b.maxx - b.minx), 1.2 * width);
  return plot + 2 * kMargin + (o.title.empty() ? 0 : kTitleStrip) + (o.colour_bar ? kBarStrip : 0);
}

namespace {

// A panel coloured by the scalar on the given colour range (the body of draw_medial2 and
// draw_medial2_scalar).
std::size_t draw_panel(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape, const MedialGraph& g,
                       const GrassfireResult& r, const Medial2Scalar& scalar, Medial2FieldRange range,
                       const Medial2SvgOptions& o) {
  const Medial2Frame f = medial2_panel_frame(shape, o, x, y, w, h);
  const double axis_width = o.axis_width > 0 ? o.axis_width : w / 320;
  if (o.range_lo < o.range_hi) range.lo = o.range_lo, range.hi = o.range_hi;

  if (o.distance_background)
    draw_distance_background(c, f, shape, g, o.raster_cell, x, y, w, h);
  else
    c.polygon_outline(shape_polygon(f, shape), kFill, kFill, 0);
  draw_boundary(c, f, shape, kBoundary, 0.6 * axis_width);
  if (o.samples)
    for (const auto& ring : *o.samples)
      for (const Point2& p : ring) c.circle(f(p), 0.5 * axis_width, kBoundary, kBoundary, 0);
  if (o.show_ema) draw_ema(c, f, g, r, axis_width, true);

  std::size_t pieces = 0;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::vector<double> cuts = scalar.breakpoints(e);
    const int min_pieces = g.edge(e).kind == EdgeKind::ParabolicArc ? 4 : 1;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double a = cuts[k], b = cuts[k + 1];
      const int n = std::max(min_pieces, static_cast<int>(std::ceil((b - a) * f.scale() / o.max_piece)));
      for (int i = 0; i < n; ++i) {
        const double s0 = a + (b - a) * i / n, s1 = a + (b - a) * (i + 1) / n;
        const double v = scalar.along(e, 0.5 * (s0 + s1));
        const Rgb col = std::isinf(v) ? kInfiniteColour
                                      : heat_color(range.hi > range.lo ? (v - range.lo) / (range.hi - range.lo) : 0.5);
        c.polyline(edge_points(f, g, e, {s0, s1}), col, axis_width);
        ++pieces;
      }
    }
  }
  if (o.show_ema) draw_ema(c, f, g, r, axis_width, false);
  const double bottom = o.colour_bar ? kBarStrip : 0;
  if (o.colour_bar)
    draw_colour_bars(c, x + kMargin, y + h - bottom + 14, w - 2 * kMargin, scalar.name, range, o, max_radius(g));
  if (!o.title.empty()) c.text({x + w / 2, y + 21}, o.title, 1.1 * font_size(w), "middle");
  return pieces;
}

}  // namespace

Medial2Scalar medial2_field_scalar(const MedialGraph& g, const GrassfireResult& r, Medial2Field field) {
  Medial2Scalar s;
  s.name = to_string(field);
  s.breakpoints = [&g, &r](std::uint32_t e) { return field_breakpoints(g, r, e); };
  s.along = [&g, &r, field](std::uint32_t e, double at) {
    return medial2_field_along(g, r, field, e, g.edge(e).u, at);
  };
  return s;
}

Medial2Scalar potential_residue_scalar(const MedialGraph& g, const ClosestPoints& cp, const PotentialResidue& pr) {
  if (pr.edge.size() != g.edge_count()) throw std::invalid_argument("svg: the potential residue is of another graph");
  Medial2Scalar s;
  s.name = "PR";
  s.breakpoints = [&g, &pr](std::uint32_t e) {
    const double w = g.edge(e).length.mid();
    if (!pr.edge[e].peak) return std::vector<double>{0.0, w};
    return std::vector<double>{0.0, std::clamp(pr.edge[e].peak_fraction.mid(), 0.0, 1.0) * w, w};
  };
  s.along = [&g, &cp, &pr](std::uint32_t e, double at) {
    const EdgeResidue& er = pr.edge[e];
    const double a = er.at_u.value.mid(), b = er.at_v.value.mid(), w = g.edge(e).length.mid();
    if (std::isinf(a) || std::isinf(b)) return kInf;
    const double t = w > 0 ? std::clamp(at / w, 0.0, 1.0) : 0.0;
    if (!er.peak) return a + (b - a) * t;
    // Up to half the perimeter at the peak, then down.
    const double top = 0.5 * cp.ring_length.at(er.at_u.ring).mid(), p = std::clamp(er.peak_fraction.mid(), 0.0, 1.0);
    if (t <= p) return p > 0 ? a + (top - a) * t / p : top;
    return p < 1 ? top + (b - top) * (t - p) / (1 - p) : top;
  };
  return s;
}

Medial2FieldRange medial2_scalar_range(const MedialGraph& g, const Medial2Scalar& scalar) {
  Medial2FieldRange range;
  double lo = kInf, hi = -kInf;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e)
    for (double s : scalar.breakpoints(e)) {
      const double v = scalar.along(e, s);
      if (std::isinf(v))
        range.has_infinite = true;
      else
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
  if (lo <= hi) range.lo = lo, range.hi = hi;
  return range;
}

Medial2Frame medial2_panel_frame(const Shape2& shape, const Medial2SvgOptions& o, double x, double y, double w,
                                 double h) {
  const double top = o.title.empty() ? 0 : kTitleStrip, bottom = o.colour_bar ? kBarStrip : 0;
  return Medial2Frame(shape, x + kMargin, y + top + kMargin, w - 2 * kMargin, h - top - bottom - 2 * kMargin);
}

std::size_t draw_medial2(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                         const MedialGraph& g, const GrassfireResult& r, const NodeMeasures& m,
                         const Medial2SvgOptions& o) {
  return draw_panel(c, x, y, w, h, shape, g, r, medial2_field_scalar(g, r, o.field),
                    medial2_field_range(g, r, m, o.field), o);
}

std::size_t draw_medial2_scalar(SvgCanvas& c, double x, double y, double w, double h, const Shape2& shape,
                                const MedialGraph& g, const GrassfireResult& r, const Medial2Scalar& scalar,
                                const Medial2SvgOptions& o) {
  return draw_panel(c, x, y, w, h, shape, g, r, scalar, medial2_scalar_range(g, scalar), o);
}

std::string medial2_svg(const Shape2& shape, const MedialGraph& g, const GrassfireResult& r, const NodeMeasures& m,
                        const Medial2SvgOptions& o) {
  if (!(o.width >= 100)) throw std::invalid_argument("svg: the width must be at least 100 px");
  if (!(o.max_piece > 0) || !(o.raster_cell >= 1)) throw std::invalid_argument("svg: bad piece or cell size");
  const double h = medial2_panel_height(shape, o, o.width);
  SvgCanvas c(o.width, h);
  draw_medial2(c, 0, 0, o.width, h, shape, g, r, m, o);
  return c.str();
}

}  // namespace grassfire
