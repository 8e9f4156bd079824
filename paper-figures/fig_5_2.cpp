// fig_5_2.cpp -- Figure 5.2: burning paths and the medial curves they end on (5.1.2), on
// the board and fin, on the exact medial axis of a box (.ma) and on the medial axis of a
// mesh (the tripod, its mesh axis as medial3d builds it).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "complex3/synthetic_complexes.h"
#include "pipeline/medial_axis_input.h"
#include "geometry3/vec3.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"
#include "io/complex_ma.h"

namespace grassfire::figures {
namespace {

const Rgb kSheet{0.9, 0.91, 0.94}, kCurve{0.85, 0.05, 0.05}, kPath{0.1, 0.1, 0.1}, kFlow{0.45, 0.45, 0.5};

bool in_board_fin_window(const Vec3d& p) { return p[0] >= -3 && p[0] <= 8 && p[1] <= 8 && p[2] <= 3; }

// Sheets in grey with BT iso-curves every `step`, so that paths and curves stand out.
void draw_sheets(Renderer3d& r, const CurvesScene& s, const std::function<bool(std::uint32_t)>& keep, double step) {
  std::vector<std::uint32_t> tris;
  for (std::uint32_t t = 0; t < s.mc.triangle_count(); ++t)
    if (keep(t)) tris.push_back(t);
  std::vector<double> levels;
  for (double l = step; l < 100 * step; l += step) levels.push_back(l);
  for (std::uint32_t t : tris) {
    const auto& v = s.mc.triangle(t).v;
    const std::array<Point3d, 3> p = {p3(s.mc.vertex(v[0]).approx), p3(s.mc.vertex(v[1]).approx), p3(s.mc.vertex(v[2]).approx)};
    r.triangle(p[0], p[1], p[2], kSheet);
    r.iso_lines(p, {sector_burn_time(s.mc, s.burning, t, 0), sector_burn_time(s.mc, s.burning, t, 1),
                    sector_burn_time(s.mc, s.burning, t, 2)},
                levels, {0.6, 0.6, 0.65}, 0.5);
  }
  draw_edges(r, s.mc, tris, EdgeStratum::Singular, {0.2, 0.55, 0.2}, 1.2);
}

std::vector<FigureFile> fig_5_2(const FigureContext& ctx) {
  SvgCanvas canvas(1500, 560);
  char caption[900];
  {  // the board and fin
    const CurvesScene s(board_fin({10, 2}), 0.125);
    Camera cam;  // from above the back side, so that N and the paths that end on it show
    cam.eye = {9.5, -7.5, 10.5};
    cam.target = {3.0, 3.2, 0.5};
    cam.fov_degrees = 38;
    Renderer3d r(cam);
    draw_sheets(r, s, [&](std::uint32_t t) {
      for (std::uint32_t v : s.mc.triangle(t).v)
        if (!in_board_fin_window(s.mc.vertex(v).approx)) return false;
      return true;
    }, 1.0);
    std::vector<CellPoint> grid;
    for (std::uint32_t t = 0; t < s.mc.triangle_count(); t += 37) {
      const auto& v = s.mc.triangle(t).v;
      const Vec3d c = v3::scale(v3::add(s.mc.vertex(v[0]).approx, v3::add(s.mc.vertex(v[1]).approx, s.mc.vertex(v[2]).approx)), 1.0 / 3);
      if (in_board_fin_window(c) && c[1] > 0.5) grid.push_back({CellPoint::Kind::Triangle, t, c, 0});
    }
    draw_paths(r, paths_from_points(*s.field, grid), kFlow, 0.7, 0.18);
    std::vector<BurningPath> ends = paths_ending_on_curves(*s.field, s.curves);
    std::vector<BurningPath> shown;
    for (std::size_t i = 0; i < ends.size(); i += 4)
      if (in_board_fin_window(ends[i].points[0])) shown.push_back(ends[i]);
    draw_paths(r, shown, kPath, 1.1, 0.25);
    draw_curves(r, s.curves, kCurve, 3.2, [&](std::uint32_t e) {
      return in_board_fin_window(s.curves.nodes[s.curves.edges[e].u].position) &&
             in_board_fin_window(s.curves.nodes[s.curves.edges[e].v].position);
    });
    r.point({1, 1, 0}, 3.5, {0, 0, 0});
    r.label({1, 1, 0}, "c", 15, {-10, 14});
    const double k = 2 + std::sqrt(2.0);
    r.point({k, k, 0}, 4.5, {1, 1, 1});
    r.label({k, k, 0}, "k", 15, {-12, 14});
    r.render(canvas, 0, 40, 560, 500);
    canvas.text({280, 28}, "board and fin (h = 1/8)", 15, "middle");
  }
  double box_length = 0, tripod_length = 0;
  std::size_t tripod_walls = 0;
  {  // a box's exact medial axis
    const CurvesScene s(read_ma(ctx.data_dir + "/ma/box_7_4_3.ma"), 0.15);
    box_length = s.curves.total_length();
    // The upper half (z >= 0), so that the middle rectangle shows.
    Renderer3d r(framing_camera(vertex_positions(s.mc), -62, 38));
    auto upper = [](const Vec3d& p) { return p[2] >= -1e-9; };
    draw_sheets(r, s, [&](std::uint32_t t) {
      for (std::uint32_t v : s.mc.triangle(t).v)
        if (!upper(s.mc.vertex(v).approx)) return false;
      return true;
    }, 0.5);
    std::vector<BurningPath> shown;
    for (const BurningPath& p : every(paths_ending_on_curves(*s.field, s.curves), 5))
      if (std::all_of(p.points.begin(), p.points.end(), upper)) shown.push_back(p);
    draw_paths(r, shown, kPath, 0.9, 0.22);
    draw_curves(r, s.curves, kCurve, 3.0, [&](std::uint32_t e) {
      return upper(s.curves.nodes[s.curves.edges[e].u].position) && upper(s.curves.nodes[s.curves.edges[e].v].position);
    });
    r.render(canvas, 540, 40, 480, 500);
    canvas.text({780, 28}, "box 14 x 8 x 6: exact medial axis (.ma), upper half", 15, "middle");
  }
  {  // a mesh's medial axis
    MedialAxisBuild axis = build_medial_axis(ctx.data_dir + "/meshes/tripod.off", MedialInputKind::Auto);
    const CurvesScene s(axis.complex, 0.006);
    tripod_length = s.curves.total_length();
    tripod_walls = s.curves.stats.walls_opened;
    Renderer3d r(framing_camera(vertex_positions(s.mc), 60, 50, 24));
    draw_sheets(r, s, [](std::uint32_t) { return true; }, 0.02);
    draw_paths(r, every(paths_ending_on_curves(*s.field, s.curves), 9), kPath, 0.8, 0.012);
    draw_curves(r, s.curves, kCurve, 3.0);
    r.render(canvas, 1020, 40, 480, 500);
    canvas.text({1260, 28}, "tripod mesh: its medial axis (medial3d)", 15, "middle");
  }
  canvas.save(ctx.out_dir + "/fig5_2.svg");
  std::snprintf(caption, sizeof caption,
                "Fig. 5.2: burning paths (black arrows: the paths that end on the medial curves, traced back to the "
                "border where their fire started; grey: paths into sample points) and the medial curves (red, medial_curves.h: "
                "where paths end, joined homotopy-preservingly by the burning collapse), discrete baseline. Left: on the "
                "board and fin the curve is the junction N beyond the kink k, where the back side's fire dies; before k "
                "that fire passes through N into the front side (grey isochrones every 1; green: N). Middle: a box's "
                "axis, curves of total length %.2f: the middle rectangle's medial axis and the eight segments to the "
                "box corners. Right: the tripod's mesh axis (mesh_axis.h), curves of length %.3f along the legs "
                "(%zu walls opened to keep b1 = 0).",
                box_length, tripod_length, tripod_walls);
  return {{"fig5_2.svg", caption}};
}

GF_REGISTER_FIGURE("fig5_2", "Figure 5.2: burning paths and medial curves", fig_5_2);

}  // namespace
}  // namespace grassfire::figures
