// fig_5_4.cpp -- tubular against planar parts (5.3, after Fig. 5.4's protein: alpha
// helices as tubes, beta sheets as plates): a paddle made of balls -- a round plate of
// radius-1 balls and a handle of radius-0.8 balls -- its exact medial axis split by
// ST = 1 - R / BT (>= 1/2: planar, a medial sheet; below: tubular, represented by the
// medial curves; curves3/shape_analysis.h), and the mixed-dimensional medial structure:
// the planar sheets with the curves of the tubular parts.
#include <cmath>

#include "caption_printf.h"
#include "number/exact_sum.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

const Rgb kPlanar{0.35, 0.55, 0.9}, kTubular{0.95, 0.6, 0.25}, kCurve{0.8, 0.05, 0.05};
constexpr double kSignificance = 0.25;  // pieces of path ends below a quarter of the largest ET go

BallSet paddle() {
  BallSet b;
  b.source = "paddle of balls";
  auto add = [&](const mpq_class& x, const mpq_class& y, const mpq_class& w) {
    b.centers.push_back({x, y, 0});
    b.squared_radii.push_back(w);
    b.approx_centers.push_back({x.get_d(), y.get_d(), 0});
    b.approx_radii.push_back(std::sqrt(w.get_d()));
  };
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j)
      if (i * i + j * j <= 64) add(make_rational(i, 2), make_rational(j, 2), 1);  // the plate: |c| <= 4
  for (int k = 0; k <= 12; ++k) add(make_rational(9 + k, 2), 0, make_rational(16, 25));  // the handle
  return b;
}

std::vector<FigureFile> fig_5_4(const FigureContext& ctx) {
  MedialCurveOptions o;
  o.min_et_fraction = kSignificance;
  const CurvesScene s(union_of_balls_axis(paddle()).complex, 0.12, o);
  const Camera cam = framing_camera(vertex_positions(s.mc), -70, 40, 24);
  SvgCanvas canvas(1400, 560);
  {
    Renderer3d r(cam);
    for (std::uint32_t t = 0; t < s.k.triangles.size(); ++t) {
      const auto& v = s.k.triangles[t].v;
      r.triangle(p3(s.k.vertices[v[0]].position), p3(s.k.vertices[v[1]].position), p3(s.k.vertices[v[2]].position),
                 s.analysis.planar[t] ? kPlanar : kTubular);
    }
    draw_curves(r, s.curves, kCurve, 2.2);
    r.render(canvas, 0, 40, 700, 500);
    canvas.text({350, 28}, "the axis: planar (blue, ST >= 1/2) and tubular (orange); medial curves (red)", 14, "middle");
  }
  {
    Renderer3d r(cam);
    for (std::uint32_t t = 0; t < s.k.triangles.size(); ++t) {
      if (!s.analysis.planar[t]) continue;
      const auto& v = s.k.triangles[t].v;
      r.triangle(p3(s.k.vertices[v[0]].position), p3(s.k.vertices[v[1]].position), p3(s.k.vertices[v[2]].position),
                 kPlanar);
    }
    draw_curves(r, s.curves, kCurve, 2.6, [&](std::uint32_t e) { return s.analysis.tubular_edge[e]; });
    r.render(canvas, 700, 40, 700, 500);
    canvas.text({1050, 28}, "mixed-dimensional medial structure: sheets + tubular curves", 14, "middle");
  }
  canvas.save(ctx.out_dir + "/fig5_4.svg");
  const ShapeSignature& g = s.analysis.signature;
  const double longest = g.curve_lengths.empty() ? 0 : g.curve_lengths[0];
  return {{"fig5_4.svg",
           caption_printf("Tubular against planar parts (5.3): a paddle of %zu balls (a plate of radius-1 balls over a "
                          "disk of radius 4, a handle of 13 radius-0.8 balls), its exact medial axis (%zu triangles) "
                          "split by shape tubularity ST = 1 - R / BT at 1/2 (ET >= R: the sheet reaches a ball radius "
                          "beyond the ball; discrete BT, h = 0.12; curves without the pieces of path ends whose ET stays below %.2f of "
                          "the largest, the ridges of the plate's scalloped rim). Signature: planar area %.2f in %zu sheet(s), the "
                          "largest %.2f; tubular area %.2f; medial curves %.2f long in the tubular parts (%zu branches, "
                          "the longest %.2f, along the handle) and %.2f in the planar parts. Right: what 5.3 proposes "
                          "to keep: the sheets, and curves where the shape is a tube.",
                          union_of_balls_axis(paddle()).balls, s.mc.triangle_count(), kSignificance, g.planar_area, g.sheet_areas.size(),
                          g.sheet_areas.empty() ? 0.0 : g.sheet_areas[0], g.tubular_area, g.tubular_curve_length,
                          g.curve_lengths.size(), longest, g.planar_curve_length)}};
}

GF_REGISTER_FIGURE("fig5_4", "Tubular against planar parts of a medial axis (5.3)", fig_5_4);

}  // namespace
}  // namespace grassfire::figures
