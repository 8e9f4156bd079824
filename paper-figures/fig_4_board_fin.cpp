// fig_4_board_fin.cpp -- Figures 4.2, 4.3, 4.4 and 5.1: the board and fin, its LPDF by the
// three zones of 4.1.2, and its burning time from the discrete baseline (h = 1/16).
#include <cmath>
#include <cstdio>

#include "complex3/synthetic_complexes.h"
#include "fig_4_scene.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

const Rgb kBlack{0, 0, 0}, kRed{0.85, 0.1, 0.1}, kGrey{0.55, 0.55, 0.55};
const double kKink = 2 + std::sqrt(2.0);

std::vector<std::uint32_t> select(const MedialComplex& mc, const std::vector<std::uint32_t>& from,
                                  const std::function<bool(const Vec3d& centroid)>& keep) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t : from) {
    Vec3d c{0, 0, 0};
    for (std::uint32_t v : mc.triangle(t).v)
      for (int i = 0; i < 3; ++i) c[i] += mc.vertex(v).approx[i] / 3;
    if (keep(c)) out.push_back(t);
  }
  return out;
}

// Borders B and F (black), the junction N (red), truncations not drawn, c and k labelled.
void annotate(Renderer3d& r, const MedialComplex& mc, const std::vector<std::uint32_t>& tris, bool kink) {
  draw_edges(r, mc, tris, EdgeStratum::Border, kBlack, 1.8, true);
  draw_edges(r, mc, tris, EdgeStratum::Singular, kRed, 2.2);
  r.point({1, 1, 0}, 3.5, kBlack);
  r.label({1, 1, 0}, "c", 15, {-10, 14});
  if (kink) {
    r.point({kKink, kKink, 0}, 4.5, {1, 1, 1});
    r.label({kKink, kKink, 0}, "k", 15, {-12, 14});
  }
}

CornerValue bt_value(const BoardFinScene& s) {
  return [&s](std::uint32_t t, int c) { return sector_burn_time(s.mc, s.burning, t, c); };
}

CornerValue lpdf_value(const BoardFinScene& s) {
  return [&s](std::uint32_t t, int c) {
    // The limit from inside the triangle (the LPDF jumps across N beyond k, like BT): the
    // zone of the triangle's centroid, its formula at the corner.
    const auto& tv = s.mc.triangle(t).v;
    Vec3d centroid{0, 0, 0};
    for (std::uint32_t v : tv)
      for (int i = 0; i < 3; ++i) centroid[i] += s.mc.vertex(v).approx[i] / 3;
    const Vec3d& p = s.mc.vertex(tv[c]).approx;
    switch (board_fin_lpdf_zone(centroid)) {
      case 1: return std::sqrt(2.0) * (p[0] - 1);
      case 2: return std::hypot(p[0] - 1, p[1] - 1);
      default: return p[1];
    }
  };
}

std::vector<FigureFile> fig_4_2(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  SvgCanvas canvas(1200, 420);
  const Rgb board{0.62, 0.72, 0.86}, fin{0.95, 0.7, 0.45};
  const auto board_tris = select(s.mc, s.drawn, [](const Vec3d& c) { return c[2] == 0; });
  const auto fin_tris = select(s.mc, s.drawn, [](const Vec3d& c) { return c[2] > 0; });
  const char* titles[3] = {"board (border B)", "fin (borders F and N)", "board and fin (junction N)"};
  for (int panel = 0; panel < 3; ++panel) {
    Renderer3d r(board_fin_camera());
    if (panel != 1)
      for (std::uint32_t t : board_tris) {
        const auto& tv = s.mc.triangle(t).v;
        r.triangle(p3(s.mc.vertex(tv[0]).approx), p3(s.mc.vertex(tv[1]).approx), p3(s.mc.vertex(tv[2]).approx), board);
      }
    if (panel != 0)
      for (std::uint32_t t : fin_tris) {
        const auto& tv = s.mc.triangle(t).v;
        r.triangle(p3(s.mc.vertex(tv[0]).approx), p3(s.mc.vertex(tv[1]).approx), p3(s.mc.vertex(tv[2]).approx), fin);
      }
    if (panel == 0) {
      r.line({-3, 0, 0}, {8, 0, 0}, kBlack, 1.8);
      r.label({3, 0, 0}, "B", 16, {0, 20});
    } else {
      annotate(r, s.mc, panel == 1 ? fin_tris : s.drawn, false);
      r.label({1, 1, 3}, "F", 16, {-14, 0});
      r.label({6, 6, 0}, "N", 16, {14, 14});
      if (panel == 2) r.label({7, 0, 0}, "B", 16, {6, 18});
    }
    r.render(canvas, 400.0 * panel, 30, 400, 390);
    canvas.text({400.0 * panel + 200, 24}, titles[panel], 14, "middle");
  }
  canvas.save(ctx.out_dir + "/fig4_2.svg");
  return {{"fig4_2.svg",
           "Fig. 4.2: the board (half-plane, border B), the fin (quarter-plane, borders F and N) and the board and fin "
           "joined along the junction N (red) from the corner c. Drawn: x in [-3, 8], y in [0, 8], fin height 3 of the "
           "complex truncated at E = 10 (exact rational vertices, triangles of side 1/4)."}};
}

std::vector<FigureFile> fig_4_3(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  SvgCanvas canvas(1000, 900);
  {
    Renderer3d r(board_fin_camera());
    draw_scalar(r, s.mc, s.drawn, lpdf_value(s), 0, 8, 0.5);
    annotate(r, s.mc, s.drawn, true);
    r.render(canvas, 0, 20, 1000, 440);
  }
  {
    Renderer3d r(board_fin_camera());
    const Rgb zone[4] = {{}, {0.95, 0.6, 0.4}, {0.55, 0.8, 0.5}, {0.6, 0.7, 0.9}};
    for (std::uint32_t t : s.drawn) {
      const auto& tv = s.mc.triangle(t).v;
      Vec3d c{0, 0, 0};
      for (std::uint32_t v : tv)
        for (int i = 0; i < 3; ++i) c[i] += s.mc.vertex(v).approx[i] / 3;
      r.triangle(p3(s.mc.vertex(tv[0]).approx), p3(s.mc.vertex(tv[1]).approx), p3(s.mc.vertex(tv[2]).approx),
                 zone[board_fin_lpdf_zone(c)]);
    }
    // The parabola P: points of the board equidistant to B and c, (x - 1)^2 = 2 y - 1.
    for (double x = kKink; x < 4.6; x += 0.05) {
      auto py = [](double u) { return ((u - 1) * (u - 1) + 1) / 2; };
      if (py(x + 0.05) <= 8) r.line({x, py(x), 0}, {x + 0.05, py(x + 0.05), 0}, kBlack, 1.6, "5,3");
    }
    annotate(r, s.mc, s.drawn, true);
    r.label({3.5, 3.5, 1.5}, "zone 1", 14);
    r.label({5.6, 6.4, 0}, "zone 2", 14);
    r.label({-1.5, 5, 0}, "zone 3", 14);
    r.label({6.5, 1.5, 0}, "zone 3", 14);
    r.label({4.6, 7.3, 0}, "P", 15, {12, 0});
    r.render(canvas, 0, 460, 1000, 430);
  }
  colour_bar(canvas, 380, 18, 240, 0, 8, "LPDF");
  canvas.save(ctx.out_dir + "/fig4_3.svg");
  return {{"fig4_3.svg",
           "Fig. 4.3: the largest-plate distance (LPDF) of the zero-radius board and fin by its three zones (4.1.2), "
           "hue from red (0) to purple (8), iso-curves every 0.5 (top); the zones (bottom): 1 the fin (distance to F), "
           "2 the wedge between N and the parabola P (distance to c, the plate uses the fin and touches c), 3 the rest "
           "of the board (distance to B). The iso-curves have corners on P, where the LPDF is only C0."}};
}

std::vector<FigureFile> fig_4_4(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  SvgCanvas canvas(1200, 900);
  {
    Renderer3d r(board_fin_camera());
    draw_scalar(r, s.mc, s.drawn, bt_value(s), 0, 8, 0.5);
    annotate(r, s.mc, s.drawn, true);
    r.render(canvas, 100, 20, 1000, 520);
  }
  colour_bar(canvas, 480, 18, 240, 0, 8, "burning time BT");
  const double times[3] = {1.5, kKink, 5.0};
  const char* names[3] = {"t = 1.5: the fin's front leads", "t = 2 + sqrt 2: fronts meet at k",
                          "t = 5: back side leads, fin joins front"};
  for (int i = 0; i < 3; ++i) {
    Renderer3d r(board_fin_camera());
    const double t = times[i];
    for (std::uint32_t tri : s.drawn) {
      const auto& tv = s.mc.triangle(tri).v;
      double mean = 0;
      for (int c = 0; c < 3; ++c) mean += sector_burn_time(s.mc, s.burning, tri, c) / 3;
      r.triangle(p3(s.mc.vertex(tv[0]).approx), p3(s.mc.vertex(tv[1]).approx), p3(s.mc.vertex(tv[2]).approx),
                 mean <= t ? Rgb{0.97, 0.62, 0.35} : Rgb{0.82, 0.84, 0.86});
      const std::array<Point3d, 3> p = {p3(s.mc.vertex(tv[0]).approx), p3(s.mc.vertex(tv[1]).approx),
                                        p3(s.mc.vertex(tv[2]).approx)};
      const std::array<double, 3> v = {sector_burn_time(s.mc, s.burning, tri, 0), sector_burn_time(s.mc, s.burning, tri, 1),
                                        sector_burn_time(s.mc, s.burning, tri, 2)};
      r.iso_lines(p, v, {t}, kBlack, 1.6);
    }
    annotate(r, s.mc, s.drawn, true);
    r.render(canvas, 400.0 * i, 560, 400, 320);
    canvas.text({400.0 * i + 200, 895}, names[i], 13, "middle");
  }
  canvas.save(ctx.out_dir + "/fig4_4.svg");
  return {{"fig4_4.svg",
           "Fig. 4.4: the burning time of the board and fin (top; discrete baseline, h = 1/16, hue 0..8, iso-curves "
           "every 0.5) and the fronts (bottom; burned in orange) at t = 1.5, at t = 2 + sqrt 2 when they meet at the "
           "kink k = (2 + sqrt 2, 2 + sqrt 2, 0), and at t = 5. Before k the fin's front waits at N; after k the back "
           "side's front waits and the fin's front continues into the front side as a circle about k."}};
}

std::vector<FigureFile> fig_5_1(const FigureContext& ctx) {
  const BoardFinScene& s = board_fin_scene();
  SvgCanvas canvas(1200, 900);
  Camera top;
  top.eye = {2.5, 4.0, 60};
  top.target = {2.5, 4.0, 0};
  top.up = {0, 1, 0};
  top.fov_degrees = 12;
  const auto board_tris = select(s.mc, s.drawn, [](const Vec3d& c) { return c[2] == 0; });
  for (int row = 0; row < 2; ++row) {
    const CornerValue value = row == 0 ? lpdf_value(s) : bt_value(s);
    Renderer3d r(board_fin_camera());
    draw_scalar(r, s.mc, s.drawn, value, 0, 8, 0.5);
    annotate(r, s.mc, s.drawn, true);
    r.render(canvas, 0, 30 + 440.0 * row, 700, 420);
    Renderer3d t(top);
    draw_scalar(t, s.mc, board_tris, value, 0, 8, 0.5);
    annotate(t, s.mc, board_tris, true);
    t.render(canvas, 700, 30 + 440.0 * row, 500, 420);
    canvas.text({600, 24 + 440.0 * row}, row == 0 ? "LPDF (closed form, 4.1.2)" : "burning time (discrete, h = 1/16)", 15,
                "middle");
  }
  canvas.save(ctx.out_dir + "/fig5_1.svg");
  return {{"fig5_1.svg",
           "Fig. 5.1: LPDF (top) and burning time (bottom) on the board and fin, with iso-curves every 0.5; right: the "
           "board alone seen from above. They agree away from the front side beyond k, where the LPDF is |p - c| "
           "(corners of the iso-curves on P) and BT is 2 + sqrt 2 + |p - k| (smooth)."}};
}

GF_REGISTER_FIGURE("fig4_2", "Figure 4.2: the board and fin", fig_4_2);
GF_REGISTER_FIGURE("fig4_3", "Figure 4.3: LPDF of the board and fin by zones", fig_4_3);
GF_REGISTER_FIGURE("fig4_4", "Figure 4.4: burning time and fronts of the board and fin", fig_4_4);
GF_REGISTER_FIGURE("fig5_1", "Figure 5.1: LPDF versus burning time", fig_5_1);

}  // namespace
}  // namespace grassfire::figures
