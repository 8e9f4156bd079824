// plot_svg.h -- small line plots as SVG for the studies (log or linear axes, several
// series, a legend, optional reference slopes), drawn on render/render3d.h's SvgCanvas.
//
// Computes: a picture of the series' points joined by lines, with ticks at powers of ten on
// a logarithmic axis and at "nice" steps (1, 2, 5 x 10^k) on a linear one. Points whose
// value cannot be shown (not finite, or <= 0 on a logarithmic axis) break the line and
// are counted in the legend entry ("n not shown"), never dropped silently.
// Contract: none; an empty plot draws only its frame. Complexity: O(points).
// Header-only so that every experiments/ executable (and paper-figures/) can include it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "render/render3d.h"

namespace grassfire::plot {

struct Series {
  std::string name;
  std::vector<double> x, y;
  Rgb colour{0.1, 0.3, 0.8};
  std::string dash;     // SVG dash pattern, "" for a solid line
  bool markers = true;  // a dot at every point
  bool line = true;     // join consecutive points
};

// A straight line of slope `slope` in log-log coordinates through (x0, y0): y = y0 (x/x0)^slope.
struct ReferenceSlope {
  double slope = 1, x0 = 1, y0 = 1;
  std::string label;
};

struct Plot {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  double width = 860, height = 460;  // the legend takes the rightmost 230 px
  std::vector<Series> series;
  std::vector<ReferenceSlope> slopes;  // drawn only on log-log plots
};

// Colours for series i = 0, 1, ...: 16 distinct, print-friendly colours, then hues spaced by
// the golden angle (so a figure with many series, e.g. the 14 shared meshes, repeats none).
// The median of a series' samples (NaN for none): what the studies plot per point.
inline double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

inline Rgb series_colour(std::size_t i) {
  static const Rgb k[] = {{0.80, 0.10, 0.10}, {0.10, 0.30, 0.80}, {0.10, 0.60, 0.20}, {0.85, 0.50, 0.05},
                          {0.55, 0.15, 0.65}, {0.10, 0.60, 0.65}, {0.45, 0.45, 0.45}, {0.70, 0.35, 0.20},
                          {0.95, 0.40, 0.60}, {0.50, 0.70, 0.10}, {0.00, 0.00, 0.00}, {0.40, 0.60, 0.95},
                          {0.75, 0.65, 0.10}, {0.20, 0.20, 0.50}, {0.60, 0.00, 0.30}, {0.00, 0.40, 0.35}};
  const std::size_t n = sizeof k / sizeof k[0];
  if (i < n) return k[i];
  const double h = std::fmod(0.618033988749895 * static_cast<double>(i - n), 1.0) * 6;  // hue sector
  const double f = h - std::floor(h), v = 0.75, lo = 0.15, up = lo + (v - lo) * f, dn = v - (v - lo) * f;
  switch (static_cast<int>(h)) {
    case 0: return {v, up, lo};
    case 1: return {dn, v, lo};
    case 2: return {lo, v, up};
    case 3: return {lo, dn, v};
    case 4: return {up, lo, v};
    default: return {v, lo, dn};
  }
}

namespace detail {

struct Axis {
  bool log = false;
  double lo = 0, hi = 1;  // data range shown (log: positive)
  double a = 0, b = 1;    // canvas coordinates of lo and hi

  double map(double v) const {
    const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
    return a + t * (b - a);
  }
  bool shows(double v) const { return std::isfinite(v) && (!log || v > 0); }
};

inline double nice_step(double span) {
  const double raw = span / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

// The range of the shown values, widened by a margin (log: a factor 1.25) or to nice
// steps (linear).
inline void fit(Axis& ax, const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (ax.shows(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) lo = ax.log ? 1 : 0, hi = ax.log ? 10 : 1;
  if (ax.log) {
    ax.lo = lo / 1.25;
    ax.hi = hi * 1.25;
    if (ax.hi / ax.lo < 10) {  // at least one decade, centred on the data
      const double widen = std::sqrt(10 / (ax.hi / ax.lo));
      ax.lo /= widen, ax.hi *= widen;
    }
  } else {
    if (hi == lo) lo -= 0.5, hi += 0.5;
    const double step = nice_step(hi - lo);
    ax.lo = std::floor(lo / step) * step;
    ax.hi = std::ceil(hi / step) * step;
  }
}

// Log axes: powers of ten, plus 2 and 5 times them when the range spans few decades.
inline std::vector<double> ticks(const Axis& ax) {
  std::vector<double> t;
  if (ax.log) {
    const bool fine = std::log10(ax.hi / ax.lo) < 3.5;
    for (double d = std::pow(10.0, std::floor(std::log10(ax.lo))); d <= ax.hi; d *= 10)
      for (double m : {1.0, 2.0, 5.0})
        if ((m == 1.0 || fine) && m * d >= ax.lo && m * d <= ax.hi) t.push_back(m * d);
  } else {
    const double step = nice_step(ax.hi - ax.lo);
    for (double v = ax.lo; v <= ax.hi + step * 1e-6; v += step) t.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
  }
  return t;
}

inline std::string tick_label(const Axis& ax, double v) {
  char buf[32];
  const double a = std::abs(v);
  if (ax.log && (a >= 1e5 || a < 1e-2)) {
    const int e = static_cast<int>(std::floor(std::log10(a) + 1e-9));
    const long m = std::lround(a / std::pow(10.0, e));
    if (m == 1)
      std::snprintf(buf, sizeof buf, "1e%d", e);
    else
      std::snprintf(buf, sizeof buf, "%lde%d", m, e);
  } else {
    std::snprintf(buf, sizeof buf, "%g", v);
  }
  return buf;
}

}  // namespace detail

inline void draw(SvgCanvas& c, const Plot& p, double left, double top) {
  const double x0 = left + 78, x1 = left + p.width - 250, y0 = top + p.height - 58, y1 = top + 40;
  const double lx = x1 + 16;  // legend column
  detail::Axis ax{p.log_x}, ay{p.log_y};
  std::vector<double> xs, ys;
  for (const Series& s : p.series) xs.insert(xs.end(), s.x.begin(), s.x.end()), ys.insert(ys.end(), s.y.begin(), s.y.end());
  detail::fit(ax, xs);
  detail::fit(ay, ys);
  ax.a = x0, ax.b = x1, ay.a = y0, ay.b = y1;
  const Rgb grid{0.87, 0.87, 0.87}, black{0, 0, 0};
  for (double t : detail::ticks(ay)) {
    const double y = ay.map(t);
    c.polyline({{x0, y}, {x1, y}}, grid, 0.6);
    c.text({x0 - 7, y + 4}, detail::tick_label(ay, t), 11, "end");
  }
  for (double t : detail::ticks(ax)) {
    const double x = ax.map(t);
    c.polyline({{x, y0}, {x, y1}}, grid, 0.6);
    c.text({x, y0 + 17}, detail::tick_label(ax, t), 11, "middle");
  }
  c.polyline({{x0, y1}, {x0, y0}, {x1, y0}}, black, 1.2);
  c.text({(x0 + x1) / 2, y0 + 38}, p.x_label, 13, "middle");
  c.text({left + 8, y1 - 14}, p.y_label, 12, "start");
  c.text({left + p.width / 2, top + 18}, p.title, 13, "middle");
  int legend = 0;
  for (const Series& s : p.series) {
    std::vector<Point2d> run;
    std::size_t hidden = 0;
    auto flush = [&] {
      if (s.line && run.size() > 1) c.polyline(run, s.colour, 1.8, s.dash);
      run.clear();
    };
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!ax.shows(s.x[i]) || !ay.shows(s.y[i])) {
        ++hidden;
        flush();
        continue;
      }
      const Point2d q{ax.map(s.x[i]), ay.map(s.y[i])};
      run.push_back(q);
      if (s.markers) c.circle(q, 2.6, s.colour, s.colour, 0);
    }
    flush();
    std::string name = s.name;
    if (hidden > 0) name += " (" + std::to_string(hidden) + " not shown)";
    c.polyline({{lx, y1 + 10 + 16.0 * legend}, {lx + 20, y1 + 10 + 16.0 * legend}}, s.colour, 2, s.dash);
    c.text({lx + 25, y1 + 14 + 16.0 * legend}, name, 11, "start", s.colour);
    ++legend;
  }
  if (!(p.log_x && p.log_y)) return;
  for (const ReferenceSlope& r : p.slopes) {
    const double xa = ax.lo, xb = ax.hi;
    const double ya = r.y0 * std::pow(xa / r.x0, r.slope), yb = r.y0 * std::pow(xb / r.x0, r.slope);
    // Clip the canvas segment to the frame's height (the line is straight on the canvas).
    double pa = ax.map(xa), qa = ay.map(ya), pb = ax.map(xb), qb = ay.map(yb);
    auto clip = [&](double& px, double& qy, double ox, double oy) {
      const double bound = qy > y0 ? y0 : (qy < y1 ? y1 : qy);
      if (bound == qy || oy == qy) return;
      px += (bound - qy) / (oy - qy) * (ox - px);
      qy = bound;
    };
    const double pa0 = pa, qa0 = qa;
    clip(pa, qa, pb, qb);
    clip(pb, qb, pa0, qa0);
    if (qa >= y1 && qa <= y0 && qb >= y1 && qb <= y0) c.polyline({{pa, qa}, {pb, qb}}, {0.5, 0.5, 0.5}, 1, "2,3");
    c.polyline({{lx, y1 + 10 + 16.0 * legend}, {lx + 20, y1 + 10 + 16.0 * legend}}, {0.5, 0.5, 0.5}, 1, "2,3");
    c.text({lx + 25, y1 + 14 + 16.0 * legend}, r.label, 11, "start", {0.4, 0.4, 0.4});
    ++legend;
  }
}

inline void save(const Plot& p, const std::string& path) {
  SvgCanvas c(p.width, p.height);
  c.rect(0, 0, p.width, p.height, {1, 1, 1});
  draw(c, p, 0, 0);
  c.save(path);
}

}  // namespace grassfire::plot
