// fig_4_scene.cpp -- shared scene and drawing helpers of the chapter-4 figures.
#include "fig_4_scene.h"

#include <cmath>
#include <cstdio>

#include "complex3/synthetic_complexes.h"

namespace grassfire::figures {

namespace {
bool in_window(const Vec3d& p) { return p[0] >= -3 && p[0] <= 8 && p[1] <= 8 && p[2] <= 3; }
}  // namespace

BoardFinScene::BoardFinScene() : mc(board_fin({10, 4})) {
  mc.validate();
  burning = burn_discrete(mc, {1.0 / 16});
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    bool inside = true;
    for (std::uint32_t v : mc.triangle(t).v) inside = inside && in_window(mc.vertex(v).approx);
    if (inside) drawn.push_back(t);
  }
}

const BoardFinScene& board_fin_scene() {
  static const BoardFinScene scene;
  return scene;
}

Point3d p3(const Vec3d& v) { return {v[0], v[1], v[2]}; }

double sector_burn_time(const MedialComplex& mc, const DiscreteBurning& d, std::uint32_t t, int c) {
  const std::uint32_t v = mc.triangle(t).v[c];
  const double arrival = d.arrival_time[d.vertex_slot[v] + mc.corner_element(t, c)];
  return std::min(arrival, d.vertex_bt[v]);
}

void draw_scalar(Renderer3d& r, const MedialComplex& mc, const std::vector<std::uint32_t>& triangles,
                 const CornerValue& value, double lo, double hi, double step, int subdivisions) {
  std::vector<double> levels;
  for (double l = lo + step; step > 0 && l < hi; l += step) levels.push_back(l);
  for (std::uint32_t t : triangles) {
    const auto& tv = mc.triangle(t).v;
    const std::array<Point3d, 3> p = {p3(mc.vertex(tv[0]).approx), p3(mc.vertex(tv[1]).approx), p3(mc.vertex(tv[2]).approx)};
    const std::array<double, 3> v = {value(t, 0), value(t, 1), value(t, 2)};
    r.scalar_triangle(p, v, lo, hi, subdivisions);
    r.iso_lines(p, v, levels, {0, 0, 0}, 0.6);
  }
}

void draw_edges(Renderer3d& r, const MedialComplex& mc, const std::vector<std::uint32_t>& triangles, EdgeStratum s,
                const Rgb& color, double width, bool skip_never) {
  std::vector<bool> done(mc.edge_count(), false);
  for (std::uint32_t t : triangles)
    for (std::uint32_t e : mc.triangle(t).e) {
      if (done[e] || mc.edge(e).stratum != s) continue;
      done[e] = true;
      if (skip_never && mc.edge(e).rule == IgnitionRule::Never) continue;
      r.line(p3(mc.vertex(mc.edge(e).v[0]).approx), p3(mc.vertex(mc.edge(e).v[1]).approx), color, width);
    }
}

void colour_bar(SvgCanvas& c, double x, double y, double w, double lo, double hi, const std::string& title) {
  const int n = 60;
  for (int i = 0; i < n; ++i) c.rect(x + w * i / n, y, w / n + 0.5, 12, hue_color((i + 0.5) / n));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", lo);
  c.text({x, y + 26}, buf, 11, "middle");
  std::snprintf(buf, sizeof buf, "%.3g", hi);
  c.text({x + w, y + 26}, buf, 11, "middle");
  c.text({x + w / 2, y - 4}, title, 12, "middle");
}

Camera board_fin_camera() {
  Camera cam;
  // From the front side (y > x), high enough to see the back side past the fin.
  cam.eye = {-5.0, 15.0, 21.0};
  cam.target = {2.5, 3.0, 0.0};
  cam.up = {0, 0, 1};
  cam.fov_degrees = 35;
  return cam;
}

}  // namespace grassfire::figures
