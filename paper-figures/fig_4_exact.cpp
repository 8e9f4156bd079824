// fig_4_exact.cpp -- chapter-4 figures from the exact engine (docs/exact-engine.md): Fig. 4.5
// (a complex decomposed into M2, M1, M0 and its border), Figs. 4.4 and 5.1 redone with
// the exact burning time, and the exact burning time on real medial axes.
//
// The exact engine burns every complex by Definition 9 (the junction rule on singular
// curves, the link rule at singular points); ExactScene::semantics still says which rule a
// figure shows (ExactBurningField::definition9). The kinks, merges and quench points drawn
// are the engine's (junction_points.h: located exactly where the data is exact, else as
// certified enclosures), not closed forms. Values are the engine's certified side values
// (BT_t at a point of triangle t, burning_field.h) on a barycentric grid of each triangle;
// iso-lines interpolate them linearly on that grid (a drawing of the exact curves, within
// O(grid spacing^2) of them).
#include <cmath>
#include <cstdio>
#include <memory>

#include "burn3/exact/exact_burning_field.h"
#include "burn3/exact/junction_points.h"
#include "medial3/balls/union_alpha_complex.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "curves3/lpdf.h"
#include "complex3/synthetic_complexes.h"
#include "geometry3/vec3.h"
#include "fig_4_scene.h"
#include "figure_registry.h"
#include "io/complex_ma.h"
#include "number/sqrt_field.h"

namespace grassfire::figures {
namespace {

const Rgb kBlack{0, 0, 0}, kRed{0.85, 0.1, 0.1}, kBlue{0.1, 0.3, 0.85}, kWhite{1, 1, 1}, kNever{0.6, 0.6, 0.6};

struct ExactScene {
  std::unique_ptr<MedialComplex> mc;
  std::unique_ptr<ExactBurning> eb;
  std::unique_ptr<ExactBurningField> field;
  explicit ExactScene(const RawComplex& raw) {
    mc = std::make_unique<MedialComplex>(raw);
    mc->validate();
    eb = std::make_unique<ExactBurning>(*mc);
    eb->add_border_ignition();
    eb->run();
    field = std::make_unique<ExactBurningField>(*eb, 1.0);
    points = junction_points(*eb);
  }
  JunctionPoints points;
  std::string semantics() const {
    return field->definition9() ? "exact BT (Definition 9)"
                                : "exact engine with singular edges as walls: an upper bound of BT, not Definition 9";
  }
};

Vec3d corner_mix(const std::array<Vec3d, 3>& c, double a, double b) {
  return v3::add(v3::scale(c[0], a), v3::add(v3::scale(c[1], b), v3::scale(c[2], 1 - a - b)));
}

// Each triangle split n x n: colour by the field's side values at the grid points, and
// iso-lines at the levels.
void draw_field(Renderer3d& r, const BurningField& f, const std::vector<std::uint32_t>& tris, double lo, double hi,
                const std::vector<double>& levels, int n) {
  const MedialComplex& mc = f.complex();
  for (std::uint32_t t : tris) {
    const auto& tv = mc.triangle(t).v;
    const std::array<Vec3d, 3> c = {mc.vertex(tv[0]).approx, mc.vertex(tv[1]).approx, mc.vertex(tv[2]).approx};
    auto at = [&](int i, int j) { return corner_mix(c, static_cast<double>(i) / n, static_cast<double>(j) / n); };
    std::vector<double> value((n + 1) * (n + 1));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) value[i * (n + 1) + j] = f.sample_in_triangle(t, at(i, j)).bt;
    auto small = [&](std::array<std::array<int, 2>, 3> g) {
      std::array<Point3d, 3> p;
      std::array<double, 3> v;
      for (int k = 0; k < 3; ++k) p[k] = p3(at(g[k][0], g[k][1])), v[k] = value[g[k][0] * (n + 1) + g[k][1]];
      if (!std::isfinite(v[0] + v[1] + v[2])) {
        r.triangle(p[0], p[1], p[2], kNever);  // never burns (Prop 7), or not reached through a wall
        return;
      }
      r.scalar_triangle(p, v, lo, hi, 1);
      r.iso_lines(p, v, levels, kBlack, 0.6);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        small({{{i, j}, {i + 1, j}, {i, j + 1}}});
        if (i + j + 1 < n) small({{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}});
      }
  }
}

std::vector<double> levels_every(double step, double hi) {
  std::vector<double> l;
  for (double x = step; x < hi; x += step) l.push_back(x);
  return l;
}

std::vector<std::uint32_t> all_triangles(const MedialComplex& mc) {
  std::vector<std::uint32_t> t(mc.triangle_count());
  for (std::uint32_t i = 0; i < t.size(); ++i) t[i] = i;
  return t;
}

// A camera looking at the complex's bounding box from the direction (dx, dy, dz).
Camera box_camera(const MedialComplex& mc, const Vec3d& dir, double fov = 30) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], mc.vertex(v).approx[i]), hi[i] = std::max(hi[i], mc.vertex(v).approx[i]);
  const Vec3d mid = v3::scale(v3::add(lo, hi), 0.5);
  const double size = v3::dist(lo, hi);
  Camera cam;
  cam.target = p3(mid);
  cam.eye = p3(v3::add(mid, v3::scale(v3::unit(dir), 2.2 * size)));
  cam.up = {0, 0, 1};
  cam.fov_degrees = fov;
  return cam;
}

void draw_singular(Renderer3d& r, const MedialComplex& mc) {
  for (const ComplexEdge& e : mc.edges())
    if (e.stratum == EdgeStratum::Singular) r.line(p3(mc.vertex(e.v[0]).approx), p3(mc.vertex(e.v[1]).approx), kRed, 2.2);
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    if (mc.vertex(v).kind == VertexKind::SingularPoint) r.point(p3(mc.vertex(v).approx), 3.5, kBlack);
}

// The engine's kinks (white), merges (green) and quench points (blue) on the curves.
void draw_junction_points(Renderer3d& r, const JunctionPoints& j, double radius) {
  for (const JunctionPoint& p : j.merges) r.point({p.x[0], p.x[1], p.x[2]}, radius, {0.1, 0.7, 0.2});
  for (const JunctionPoint& p : j.quenches) r.point({p.x[0], p.x[1], p.x[2]}, radius, kBlue);
  for (const JunctionPoint& p : j.kinks) r.point({p.x[0], p.x[1], p.x[2]}, radius, kWhite);
}

// Whether the engine's kinks include the board-and-fin kink, proved equal to 2 + sqrt2.
bool kink_proved(const JunctionPoints& j) {
  ExactSum k = ExactSum::sqrt_of(2);
  k += ExactSum::rational(2);
  for (const JunctionPoint& p : j.kinks)
    if (p.exact_x && exact_sign((*p.exact_x)[0] - k) == 0 && exact_sign((*p.exact_x)[1] - k) == 0 &&
        exact_sign((*p.exact_x)[2]) == 0)
      return true;
  return false;
}

void legend(SvgCanvas& c, double x, double y, const std::vector<std::pair<Rgb, std::string>>& items) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    c.rect(x, y + 20.0 * i, 14, 10, items[i].first);
    c.text({x + 20, y + 20.0 * i + 10}, items[i].second, 12);
  }
}

std::vector<FigureFile> fig_4_5(const FigureContext& ctx) {
  const MedialComplex mc(box_medial_axis(4, 3, 2));
  mc.validate();
  SvgCanvas canvas(1250, 700);
  Renderer3d r(box_camera(mc, {0.7, -1.3, 2.4}));
  const Rgb sheet_tints[4] = {{0.62, 0.75, 0.9}, {0.7, 0.86, 0.66}, {0.95, 0.82, 0.6}, {0.85, 0.72, 0.9}};
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const auto& tv = mc.triangle(t).v;
    r.triangle(p3(mc.vertex(tv[0]).approx), p3(mc.vertex(tv[1]).approx), p3(mc.vertex(tv[2]).approx),
               sheet_tints[mc.triangle(t).sheet % 4]);
  }
  std::size_t counts[4] = {0, 0, 0, 0};
  for (const ComplexEdge& e : mc.edges()) {
    if (e.stratum == EdgeStratum::Border) ++counts[3], r.line(p3(mc.vertex(e.v[0]).approx), p3(mc.vertex(e.v[1]).approx), kBlue, 2.0);
    if (e.stratum == EdgeStratum::Singular) ++counts[1];
  }
  draw_singular(r, mc);
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) counts[2] += mc.vertex(v).kind == VertexKind::SingularPoint;
  r.render(canvas, 0, 40, 850, 640);
  canvas.text({425, 26}, "the medial axis of a 4 x 3 x 2 box: M2, M1, M0 and the border", 15, "middle");
  char m2[64], m1[64], m0[64], bd[64];
  std::snprintf(m2, sizeof m2, "M2: sheets (%zu triangles)", mc.triangle_count());
  std::snprintf(m1, sizeof m1, "M1: singular curves (%zu edges)", counts[1]);
  std::snprintf(m0, sizeof m0, "M0: singular points (%zu)", counts[2]);
  std::snprintf(bd, sizeof bd, "border dM (%zu edges)", counts[3]);
  legend(canvas, 860, 280, {{sheet_tints[0], m2}, {kRed, m1}, {kBlack, m0}, {kBlue, bd}});
  canvas.save(ctx.out_dir + "/fig4_5.svg");
  return {{"fig4_5.svg",
           "Fig. 4.5: a complex decomposed into its strata (MedialComplex): the sheets M2 (tinted per sheet), the "
           "singular curves M1 where three sheets meet (red), the singular points M0 where curves meet (black dots), "
           "and the border (blue, where the sheets reach the box's edges), on the exact medial axis of a 4 x 3 x 2 box "
           "(synthetic_complexes.h box_medial_axis): the middle rectangle and the twelve sheets towards the edges."}};
}

std::vector<FigureFile> fig_4_4_exact(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  const ExactScene e(board_fin({10, 4}));
  SvgCanvas canvas(1200, 560);
  Renderer3d r(board_fin_camera());
  draw_field(r, *e.field, s.drawn, 0, 8, levels_every(0.5, 8), 3);
  draw_edges(r, s.mc, s.drawn, EdgeStratum::Border, kBlack, 1.8, true);
  draw_edges(r, s.mc, s.drawn, EdgeStratum::Singular, kRed, 2.2);
  for (const JunctionPoint& p : e.points.kinks) r.point({p.x[0], p.x[1], p.x[2]}, 4.5, kWhite);
  const bool proved = kink_proved(e.points);
  for (const JunctionPoint& p : e.points.kinks)
    r.label({p.x[0], p.x[1], p.x[2]}, proved ? "k = 2 + sqrt 2 (engine, proved)" : "k (engine)", 13, {10, 30});
  r.render(canvas, 100, 30, 1000, 520);
  colour_bar(canvas, 480, 18, 240, 0, 8, "burning time BT (exact engine)");
  canvas.save(ctx.out_dir + "/fig4_4_exact.svg");
  char found[200];
  std::snprintf(found, sizeof found, "%zu kink(s) and %zu quench point(s) (%llu switch points unclassified)",
                e.points.kinks.size(), e.points.quenches.size(), static_cast<unsigned long long>(e.points.unclassified));
  return {{"fig4_4_exact.svg",
           "Fig. 4.4 from the exact engine: " + e.semantics() +
               " on the board and fin (E = 10, triangles of side 1/4), certified side values on a 3 x 3 grid per "
               "triangle, iso-lines every 0.5. The engine found " + found +
               " on N (junction_points.h); k (white) is its kink, whose coordinates it " +
               (proved ? "proved equal to 2 + sqrt 2 (exact arithmetic)" : "located only as an enclosure") +
               ". Beyond k the fin's fire continues across N into the front side (the circles about k); the quench "
               "point, where that front meets the fire of the truncated far end (10, 10, 0) on N, is off the picture "
               "(s = 1/2 + 10 (2 + sqrt 2)/4, BT above 8)."}};
}

std::vector<FigureFile> fig_5_1_exact(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  const ExactScene e(board_fin({10, 4}));
  SvgCanvas canvas(1200, 470);
  Camera top;
  top.eye = {2.5, 4.0, 60};
  top.target = {2.5, 4.0, 0};
  top.up = {0, 1, 0};
  top.fov_degrees = 12;
  std::vector<std::uint32_t> board;
  for (std::uint32_t t : s.drawn) {
    bool flat = true;
    for (std::uint32_t v : s.mc.triangle(t).v) flat = flat && s.mc.vertex(v).approx[2] == 0;
    if (flat) board.push_back(t);
  }
  const bool proved = kink_proved(e.points);
  for (int panel = 0; panel < 2; ++panel) {
    Renderer3d r(top);
    if (panel == 0)
      draw_scalar(r, s.mc, board, [&](std::uint32_t t, int c) { return board_fin_lpdf(s.mc.vertex(s.mc.triangle(t).v[c]).approx); },
                  0, 8, 0.5, 3);
    else
      draw_field(r, *e.field, board, 0, 8, levels_every(0.5, 8), 3);
    draw_edges(r, s.mc, board, EdgeStratum::Singular, kRed, 2.2);
    for (const JunctionPoint& p : e.points.kinks) {
      r.point({p.x[0], p.x[1], p.x[2]}, 4.5, kWhite);
      r.label({p.x[0], p.x[1], p.x[2]}, "k", 15, {-12, 14});
    }
    r.render(canvas, 600.0 * panel, 40, 600, 420);
    canvas.text({600.0 * panel + 300, 30}, panel == 0 ? "LPDF (closed form, 4.1.2)" : "burning time (exact engine)", 15,
                "middle");
  }
  canvas.save(ctx.out_dir + "/fig5_1_exact.svg");
  return {{"fig5_1_exact.svg",
           "Fig. 5.1 from the exact engine: the board seen from above, LPDF (left, closed form) against the " +
               e.semantics() + " (right), iso-curves every 0.5; k is the engine's kink (junction_points.h), " +
               (proved ? "proved equal to 2 + sqrt 2" : "located as an enclosure") + ", marked in both panels."}};
}

// The exact BT on a real medial axis: coloured triangles (segments as coloured lines),
// singular curves red.
FigureFile real_axis_panel(const FigureContext& ctx, const std::string& file, const RawComplex& raw,
                           const std::string& what, const Vec3d& view) {
  const ExactScene e(raw);
  double hi = 0;
  for (std::uint32_t v = 0; v < e.mc->vertex_count(); ++v) {
    const double bt = e.field->vertex_burn_time(v);
    if (std::isfinite(bt)) hi = std::max(hi, bt);
  }
  if (!(hi > 0)) hi = 1;
  SvgCanvas canvas(1000, 720);
  Renderer3d r(box_camera(*e.mc, view));
  draw_field(r, *e.field, all_triangles(*e.mc), 0, hi, levels_every(hi / 12, hi), 2);
  for (std::uint32_t id = 0; id < e.mc->edge_count(); ++id) {
    if (e.mc->edge(id).stratum != EdgeStratum::Dangling) continue;
    const int pieces = 8;
    for (int i = 0; i < pieces; ++i) {
      const double t = e.field->sample_on_segment(id, (i + 0.5) / pieces).bt;
      r.line(p3(edge_point(*e.mc, id, static_cast<double>(i) / pieces)), p3(edge_point(*e.mc, id, (i + 1.0) / pieces)),
             std::isfinite(t) ? hue_color(t / hi) : kNever, 2.0);
    }
  }
  draw_singular(r, *e.mc);
  draw_junction_points(r, e.points, 4.0);
  r.render(canvas, 0, 40, 1000, 640);
  colour_bar(canvas, 380, 18, 240, 0, hi, "burning time");
  canvas.save(ctx.out_dir + "/" + file);
  char counts[320];
  std::snprintf(counts, sizeof counts,
                " (%zu triangles, %zu singular edges, %llu uncertified decisions; %zu kinks, %zu merges, %zu quench "
                "points, %llu switch points unclassified)",
                e.mc->triangle_count(), e.mc->count(EdgeStratum::Singular),
                static_cast<unsigned long long>(e.eb->certification().uncertified), e.points.kinks.size(),
                e.points.merges.size(), e.points.quenches.size(), static_cast<unsigned long long>(e.points.unclassified));
  return {file, what + counts + ": " + e.semantics() +
                    ", hue 0 .. max BT, 12 iso-lines; grey where it never burns (the closed part, Prop 7); singular "
                    "curves red, singular points black; the engine's kinks white, merges green, quench points blue "
                    "(junction_points.h)."};
}

std::vector<FigureFile> fig_exact_real_axes(const FigureContext& ctx) {
  return {real_axis_panel(ctx, "fig_exact_bt_balls.svg", union_of_balls_axis(random_ball_set(24, 2024)).complex,
                          "Exact burning time on the union-of-balls axis of 24 random balls (random_ball_set(24, "
                          "seed 2024), as in bench_burn3d_exact --axes)",
                          {1.0, -1.2, 0.9}),
          real_axis_panel(ctx, "fig_exact_bt_mesh.svg", read_ma(ctx.data_dir + "/ma/real/tripod-s2.ma"),
                          "Exact burning time on the mesh axis data/ma/real/tripod-s2.ma (built from data/meshes/tripod.off)",
                          {1.0, -1.4, 1.0})};
}

GF_REGISTER_FIGURE("fig4_5", "Figure 4.5: M2, M1, M0 and the border", fig_4_5);
GF_REGISTER_FIGURE("fig4_4_exact", "Figure 4.4 from the exact engine", fig_4_4_exact);
GF_REGISTER_FIGURE("fig5_1_exact", "Figure 5.1 from the exact engine", fig_5_1_exact);
GF_REGISTER_FIGURE("fig_exact_real_axes", "Exact burning time on real medial axes", fig_exact_real_axes);

}  // namespace
}  // namespace grassfire::figures
