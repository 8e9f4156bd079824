// fig_3_3.cpp -- Figure 3.3: EDF and EMA of a simply connected shape (a silhouette of the
// 2D Shape Structure dataset) and of a shape with a hole: (a) the axis coloured by the
// EDF with the EMA, (b) over the distance function R, (c) EDF and R as a 3D height map.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "fig_3_panels.h"
#include "figure_registry.h"

namespace grassfire::figures {

namespace {

const Rgb kEmaGrey{0.6, 0.6, 0.6}, kOutline{0.5, 0.5, 0.5}, kFootprint{0.85, 0.85, 0.85}, kRadius{0.55, 0.1, 0.6};

// (c): the outline at height 0, the axis' footprint, R (purple) and the EDF (heat colours;
// thick grey at a cap height where infinite, the EMA's colour in (a)) over it, seen obliquely.
void height_map(SvgCanvas& c, double x, double y, double w, double h, const Chapter3Shape& s,
                const std::string& title) {
  const MedialGraph& g = *s.result.graph;
  const GrassfireResult& r = *s.result.burning;
  const Medial2FieldRange range = medial2_field_range(g, r, s.result.measures, Medial2Field::Edf);
  double minx = std::numeric_limits<double>::infinity(), maxx = -minx, miny = minx, maxy = -minx;
  for (const Point2& p : s.shape.rings[0].points)
    minx = std::min(minx, p.x), maxx = std::max(maxx, p.x), miny = std::min(miny, p.y), maxy = std::max(maxy, p.y);
  const double diag = std::hypot(maxx - minx, maxy - miny), cap = 1.15 * range.hi;
  const double zs = 0.45 * diag / cap;  // the highest curve rises to about half the diagonal
  Camera cam;
  const double cx = 0.5 * (minx + maxx), cy = 0.5 * (miny + maxy);
  cam.eye = {cx + 0.5 * diag, cy - 1.7 * diag, 1.3 * diag};
  cam.target = {cx, cy, 0.12 * diag};
  cam.fov_degrees = 30;
  Renderer3d rd(cam);
  for (const Ring& ring : s.shape.rings)
    for (std::size_t i = 0; i < ring.points.size(); ++i) {
      const Point2& a = ring.points[i];
      const Point2& b = ring.points[(i + 1) % ring.points.size()];
      rd.line({a.x, a.y, 0}, {b.x, b.y, 0}, kOutline, 1.2);
    }
  const double step = diag / 200;
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const std::vector<double> cuts = field_breakpoints(g, r, e);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const int n = std::max(1, static_cast<int>(std::ceil((cuts[k + 1] - cuts[k]) / step)));
      for (int i = 0; i < n; ++i) {
        const double s0 = cuts[k] + (cuts[k + 1] - cuts[k]) * i / n,
                     s1 = cuts[k] + (cuts[k + 1] - cuts[k]) * (i + 1) / n;
        const Point2 p0 = g.geometry().point_along(g, e, g.edge(e).u, s0);
        const Point2 p1 = g.geometry().point_along(g, e, g.edge(e).u, s1);
        auto at = [&](Medial2Field f, double si) {
          const double v = medial2_field_along(g, r, f, e, g.edge(e).u, si);
          return zs * (std::isinf(v) ? cap : v);
        };
        rd.line({p0.x, p0.y, 0}, {p1.x, p1.y, 0}, kFootprint, 0.9);
        rd.line({p0.x, p0.y, at(Medial2Field::R, s0)}, {p1.x, p1.y, at(Medial2Field::R, s1)}, kRadius, 1.8);
        const double mid = medial2_field_along(g, r, Medial2Field::Edf, e, g.edge(e).u, 0.5 * (s0 + s1));
        const bool inf = std::isinf(mid);
        rd.line({p0.x, p0.y, at(Medial2Field::Edf, s0)}, {p1.x, p1.y, at(Medial2Field::Edf, s1)},
                inf ? kEmaGrey : heat_color((mid - range.lo) / (range.hi - range.lo)), inf ? 5 : 2.4);
      }
    }
  }
  for (const ExtendedMedialAxis& ema : r.ema)
    if (ema.kind == ExtendedMedialAxis::Kind::Point) {
      const Point2 p = position_of(g, ema.point);
      rd.line({p.x, p.y, 0}, {p.x, p.y, zs * ema.edf.mid()}, {0.45, 0.45, 0.45}, 1.2, "4,3");
      rd.point({p.x, p.y, zs * ema.edf.mid()}, 6, {0.45, 0.45, 0.45});
    }
  rd.render(c, x, y + 30, w, h - 30);
  c.text({x + w / 2, y + 21}, title, 17, "middle");
}

const char* kSilhouette = "/shapes2d/elephant-1.json";
constexpr std::size_t kSamples = 3000;

std::vector<FigureFile> fig_3_3(const FigureContext& ctx) {
  const Chapter3Shape simple = chapter3_shape(ctx.data_dir + kSilhouette, kSamples);
  const Chapter3Shape holed = chapter3_shape("hole", kSamples);
  const std::vector<const Chapter3Shape*> both{&simple, &holed};
  const double pw = 700;
  std::vector<FigureFile> files;
  for (int part = 0; part < 2; ++part) {
    Medial2SvgOptions o;
    o.distance_background = part == 1;
    const double h = row_height(both, o, pw);
    SvgCanvas c(2 * pw, h);
    const std::string tag = part == 0 ? "(a) EDF" : "(b) EDF over R";
    panel_row(c, 0, pw, both, o, {tag + ": elephant-1 (simply connected)", tag + ": hole"});
    const std::string file = part == 0 ? "fig3_3a.svg" : "fig3_3b.svg";
    c.save(ctx.out_dir + "/" + file);
    files.push_back({file, part == 0 ? "Fig. 3.3 (a) redone: the medial axis (Voronoi of " + std::to_string(kSamples) +
                                           " boundary samples) coloured by the EDF, blue low to red high. EMA: " +
                                           ema_summary(simple) + " (grey dot, left); " + ema_summary(holed) +
                                           " (right: black, the colour of infinity, in a grey band). Look for EDF = R "
                                           "at the leaves, growing at slope 1 inwards, the maximum at the grey dot."
                                     : "Fig. 3.3 (b) redone: the same over the distance function R (grey, dark at the "
                                       "boundary, white at the largest R). Look for branches into small boundary "
                                       "features keeping an EDF close to the R around them, and long limbs "
                                       "reaching far higher."});
  }
  SvgCanvas c(2 * pw, 560);
  height_map(c, 0, 0, pw, 560, simple, "(c) EDF (heat colours) and R (purple) as heights: elephant-1");
  height_map(c, pw, 0, pw, 560, holed, "(c) the same for hole (infinite EDF: grey, at a cap)");
  c.save(ctx.out_dir + "/fig3_3c.svg");
  files.push_back(
      {"fig3_3c.svg",
       "Fig. 3.3 (c) redone: EDF (heat colours) and R (purple) as heights over the axis (light grey "
       "footprint), shape outline (grey) at height 0. Look for the EDF rising at constant slope from the leaves, "
       "where it starts on R, always above R, with its peak at the EMA (grey dot on its drop line); on "
       "the hole the loop's infinite EDF is drawn as a thick grey loop at 1.15 times the largest finite EDF."});
  return files;
}

GF_REGISTER_FIGURE("fig3_3", "Figure 3.3: EDF and EMA of a simply connected shape and a shape with a hole", fig_3_3);

}  // namespace
}  // namespace grassfire::figures
