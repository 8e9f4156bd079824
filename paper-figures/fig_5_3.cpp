// fig_5_3.cpp -- Figure 5.3 (5.1.3): the EMA is not stable under Hausdorff distance. A
// very thin strip and a copy whose left half carries teeth of height a: the two are within
// about a of each other, but the teeth lengthen the medial axis on the left, and the EMA
// (the midpoint of the longest tube, 3.2) moves far to the left.
#include <cmath>
#include <stdexcept>

#include "apps2d/axis_correspondence.h"
#include "caption_printf.h"
#include "figure_registry.h"
#include "render/render3d.h"
#include "pipeline/edf2d.h"
#include "shapes/validate_shape.h"

namespace grassfire::figures {
namespace {

constexpr double kLength = 4, kHalfThickness = 0.01, kTooth = 0.1, kPeriod = 0.1;

// Coordinates in thousandths, written as the doubles nearest to those decimals, so that
// the exact polygon axis runs on the decimal grid (Boost.Polygon; docs/exactness.md).
Point2 thousandths(long x, long y) { return {x / 1000.0, y / 1000.0}; }

Shape2 strip(bool teeth) {
  Shape2 s;
  s.name = teeth ? "thin strip with teeth" : "thin strip";
  Ring r;
  const long length = std::lround(kLength * 1000), half = std::lround(kHalfThickness * 1000);
  const long tooth = std::lround(kTooth * 1000), step = std::lround(kPeriod * 500);
  const int n = teeth ? static_cast<int>(length / step / 2) : 0;  // teeth over x in [0, L / 2]
  auto centre = [&](int j) { return (j % 2 == 1) ? tooth : 0L; };  // at x = j * period / 2
  for (int j = 0; j <= n; ++j) r.points.push_back(thousandths(j * step, centre(j) - half));
  r.points.push_back(thousandths(length, -half));
  r.points.push_back(thousandths(length, half));
  for (int j = n; j >= 0; --j) r.points.push_back(thousandths(j * step, centre(j) + half));
  s.rings.push_back(r);
  validate_shape(s, s.name);
  return s;
}

double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// One-sided Hausdorff distance from boundary A (sampled every `step`) to boundary B.
double directed_hausdorff(const Ring& a, const Ring& b, double step) {
  double worst = 0;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const Point2 p = a.points[i], q = a.points[(i + 1) % a.points.size()];
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(q.x - p.x, q.y - p.y) / step)));
    for (int k = 0; k <= n; ++k) {
      const Point2 x{p.x + (q.x - p.x) * k / n, p.y + (q.y - p.y) * k / n};
      double best = 1e300;
      for (std::size_t j = 0; j < b.points.size(); ++j)
        best = std::min(best, segment_distance(x, b.points[j], b.points[(j + 1) % b.points.size()]));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

struct Panel {
  Shape2 shape;
  Edf2dResult axis;
  Point2 ema;
};

Panel analyse(bool teeth) {
  Panel p{strip(teeth), {}, {}};
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  p.axis = compute_edf2d(p.shape, o);
  if (!ema_position(*p.axis.graph, *p.axis.burning, &p.ema)) throw std::runtime_error("fig5_3: the EMA is a loop");
  return p;
}

void draw(SvgCanvas& c, const Panel& p, double y0, const Rgb& axis_colour, const Point2* former) {
  const double scale = 270, x0 = 60;
  auto at = [&](const Point2& q) { return Point2d{x0 + scale * q.x, y0 - scale * q.y}; };
  std::vector<Point2d> outline;
  for (const Point2& q : p.shape.rings[0].points) outline.push_back(at(q));
  c.polygon_outline(outline, {0.9, 0.9, 0.9}, {0.45, 0.45, 0.45}, 0.8);
  const MedialGraph& g = *p.axis.graph;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    std::vector<Point2d> line;
    for (const Point2& q : g.geometry().polyline(g, e)) line.push_back(at(q));
    c.polyline(line, axis_colour, 1.6);
  }
  if (former) c.circle(at(*former), 7, {1, 1, 1}, {0, 0, 0}, 1.6);
  c.circle(at(p.ema), 5, axis_colour, {0, 0, 0}, 1);
}

std::vector<FigureFile> fig_5_3(const FigureContext& ctx) {
  const Panel thin = analyse(false), teeth = analyse(true);
  const double hausdorff = std::max(directed_hausdorff(thin.shape.rings[0], teeth.shape.rings[0], 0.002),
                                    directed_hausdorff(teeth.shape.rings[0], thin.shape.rings[0], 0.002));
  const double shift = std::hypot(teeth.ema.x - thin.ema.x, teeth.ema.y - thin.ema.y);
  SvgCanvas c(1200, 330);
  c.text({600, 26}, "a thin strip (black axis, EMA) and a copy with teeth on its left half (red axis, EMA)", 15, "middle");
  draw(c, thin, 120, {0, 0, 0}, nullptr);
  draw(c, teeth, 260, {0.85, 0.1, 0.1}, &thin.ema);
  c.text({60, 300}, caption_printf("Hausdorff distance %.3f; EMA moved by %.3f = %.1f x the distance", hausdorff, shift,
                                   shift / hausdorff), 14);
  c.save(ctx.out_dir + "/fig5_3.svg");
  return {{"fig5_3.svg",
           caption_printf("Fig. 5.3 (5.1.3): the EMA is not stable under Hausdorff distance. A strip of length %.0f and "
                          "thickness %.2f (top; exact polygon axis in black, its EMA at x = %.3f, the middle) and a "
                          "copy whose left half zigzags with %d teeth of height %.2f (bottom; axis in red). The shapes "
                          "are %.3f apart in Hausdorff distance (boundaries sampled every 0.002), but the teeth make "
                          "the axis on the left longer, so the longest tube's midpoint, the EMA, moves to x = %.3f: "
                          "a shift of %.3f, %.1f times the Hausdorff distance (the open circle marks the old EMA). "
                          "More and steeper teeth move it further, as 5.1.3 says.",
                          kLength, 2 * kHalfThickness, thin.ema.x, static_cast<int>(std::lround(kLength / kPeriod)) / 2,
                          kTooth, hausdorff, teeth.ema.x, shift, shift / hausdorff)}};
}

GF_REGISTER_FIGURE("fig5_3", "Figure 5.3: the EMA under a small Hausdorff perturbation", fig_5_3);

}  // namespace
}  // namespace grassfire::figures
