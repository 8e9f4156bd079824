// match_svg.cpp -- see match_svg.h.
#include "apps2d/match_svg.h"

#include <algorithm>
#include <tuple>

namespace grassfire {

void draw_signature(SvgCanvas& c, const Medial2Frame& f, const BoundarySignature& s, double lo, double hi,
                    double width) {
  const std::size_t n = s.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double t = hi > lo ? (s.values[i] - lo) / (hi - lo) : 0.5;
    c.polyline({f(s.points[i]), f(s.points[(i + 1) % n])}, heat_color(t), width);
  }
}

namespace {

void range_of(const std::vector<double>& v, double* lo, double* hi) {
  const auto [a, b] = std::minmax_element(v.begin(), v.end());
  *lo = *a, *hi = *b;
}

}  // namespace

std::string match_svg(const Shape2& a, const BoundarySignature& sa, const Shape2& b, const BoundarySignature& sb,
                      const BoundaryMatch& match, const std::vector<std::uint32_t>& marked, const std::string& title,
                      double width) {
  const double pad = 20, top = title.empty() ? pad : 44, panel = (width - 3 * pad) / 2, height = top + panel + pad;
  SvgCanvas c(width, height);
  c.rect(0, 0, width, height, {1, 1, 1});
  if (!title.empty()) c.text({width / 2, 26}, title, 15, "middle");
  const Medial2Frame fa(a, pad, top, panel, panel), fb(b, 2 * pad + panel, top, panel, panel);
  const double line = width / 180;
  for (const auto& [shape, frame, sig] : {std::tuple{&a, &fa, &sa}, std::tuple{&b, &fb, &sb}}) {
    c.polygon(shape_polygon(*frame, *shape), {0.93, 0.93, 0.93});
    double lo, hi;
    range_of(sig->values, &lo, &hi);
    draw_signature(c, *frame, *sig, lo, hi, line);
  }
  const std::vector<std::uint32_t> to = correspondence_of(match, sa.points.size());
  for (std::size_t k = 0; k < marked.size(); ++k) {
    const std::uint32_t i = marked[k];
    if (i >= sa.points.size()) continue;
    const Rgb hue = hue_color(marked.size() > 1 ? double(k) / double(marked.size() - 1) : 0.0);
    const Point2d p = fa(sa.points[i]), q = fb(sb.points[to[i]]);
    c.polyline({p, q}, hue, 1.2, "5,4");
    c.circle(p, line * 1.3, hue, {0, 0, 0}, 1);
    c.circle(q, line * 1.3, hue, {0, 0, 0}, 1);
  }
  return c.str();
}

}  // namespace grassfire
