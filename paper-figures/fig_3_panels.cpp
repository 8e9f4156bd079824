// fig_3_panels.cpp -- see fig_3_panels.h.
#include "fig_3_panels.h"

#include <algorithm>
#include <cstdio>

#include "io/load_shape.h"

namespace grassfire::figures {

Chapter3Shape chapter3_shape(const std::string& arg, std::size_t samples) {
  Chapter3Shape s;
  s.shape = load_shape(arg);
  Edf2dOptions o;
  o.samples = samples;
  s.result = compute_edf2d(s.shape, o);
  return s;
}

double row_height(const std::vector<const Chapter3Shape*>& shapes, Medial2SvgOptions o, double panel_w) {
  o.title = "title";
  double h = 0;
  for (const Chapter3Shape* s : shapes) h = std::max(h, medial2_panel_height(s->shape, o, panel_w));
  return h;
}

void panel_row(SvgCanvas& c, double y, double panel_w, const std::vector<const Chapter3Shape*>& shapes,
               Medial2SvgOptions o, const std::vector<std::string>& titles) {
  const double h = row_height(shapes, o, panel_w);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const Chapter3Shape& s = *shapes[i];
    o.title = titles.at(i);
    draw_medial2(c, panel_w * static_cast<double>(i), y, panel_w, h, s.shape, *s.result.graph, *s.result.burning,
                 s.result.measures, o);
  }
}

std::string ema_summary(const Chapter3Shape& s) {
  const MedialGraph& g = *s.result.graph;
  std::string out;
  for (const ExtendedMedialAxis& e : s.result.burning->ema) {
    char buf[160];
    if (e.kind == ExtendedMedialAxis::Kind::Cycles) {
      std::snprintf(buf, sizeof buf, "a loop of %zu edges (EDF infinite)", e.edges.size());
    } else {
      const Point2 p = position_of(g, e.point);
      std::snprintf(buf, sizeof buf, "the point (%.3g, %.3g) with EDF %.4g", p.x, p.y, e.edf.mid());
    }
    out += (out.empty() ? "" : "; ") + std::string(buf);
  }
  return out;
}

}  // namespace grassfire::figures
