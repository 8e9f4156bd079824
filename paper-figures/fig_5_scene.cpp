// fig_5_scene.cpp -- shared scene and drawing helpers of the chapter-5 figures.
#include "fig_5_scene.h"

#include <algorithm>
#include <cmath>

#include "geometry3/vec3.h"
#include "fig_4_scene.h"

namespace grassfire::figures {

CurvesScene::CurvesScene(const RawComplex& raw, double h, const MedialCurveOptions& options)
    : mc(raw), burning(burn_discrete(mc, {h})) {
  mc.validate();
  field = std::make_unique<DiscreteBurningField>(mc, burning);
  k = AxisRefinement::build(*field);
  curves = medial_curves(k, *field, options);
  curves.validate(mc);
  analysis = analyze_shape(k, curves);
}

void draw_wire_and_curves(Renderer3d& r, const CurvesScene& s) {
  for (const ComplexEdge& e : s.mc.edges())
    r.line(p3(s.mc.vertex(e.v[0]).approx), p3(s.mc.vertex(e.v[1]).approx), {0.7, 0.72, 0.76}, 0.5);
  draw_curves(r, s.curves, {0.85, 0.05, 0.05}, 2.6);
}

void draw_rows_of_three(SvgCanvas& canvas, const Camera& cam, const std::array<std::string, 3>& titles,
                        const std::function<void(int row, int column, Renderer3d& r)>& draw) {
  for (int c = 0; c < 3; ++c) canvas.text({250.0 + 500 * c, 26}, titles[c], 15, "middle");
  for (int row = 0; row < 2; ++row) {
    const double y = 40 + 450.0 * row;
    for (int c = 0; c < 3; ++c) {
      Renderer3d r(cam);
      draw(row, c, r);
      r.render(canvas, 500.0 * c, y, 500, 430);
    }
    canvas.text({14, y + 20}, row == 0 ? "tripod" : "perturbed", 15);
  }
}

double max_finite_bt(const CurvesScene& s) {
  double m = 0;
  for (double bt : s.burning.vertex_bt)
    if (std::isfinite(bt)) m = std::max(m, bt);
  return m;
}

std::vector<Vec3d> vertex_positions(const MedialComplex& mc) {
  std::vector<Vec3d> out;
  for (const ComplexVertex& v : mc.vertices()) out.push_back(v.approx);
  return out;
}

Camera framing_camera(const std::vector<Vec3d>& points, double azimuth, double elevation, double fov) {
  Vec3d lo = points.front(), hi = lo;
  for (const Vec3d& p : points)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  const Vec3d centre = v3::scale(v3::add(lo, hi), 0.5);
  const double radius = std::max(v3::dist(lo, hi) / 2, 1e-9);
  const double a = azimuth * M_PI / 180, e = elevation * M_PI / 180;
  const double distance = radius / std::sin(fov * M_PI / 360) * 1.05;
  Camera cam;
  cam.target = {centre[0], centre[1], centre[2]};
  cam.eye = {centre[0] + distance * std::cos(e) * std::cos(a), centre[1] + distance * std::cos(e) * std::sin(a),
             centre[2] + distance * std::sin(e)};
  cam.up = {0, 0, 1};
  cam.fov_degrees = fov;
  return cam;
}

void draw_burning(Renderer3d& r, const CurvesScene& s, double lo, double hi, double iso_step) {
  std::vector<std::uint32_t> all(s.mc.triangle_count());
  for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
  draw_scalar(r, s.mc, all, [&s](std::uint32_t t, int c) { return sector_burn_time(s.mc, s.burning, t, c); }, lo, hi,
              iso_step);
}

void draw_flat(Renderer3d& r, const MedialComplex& mc, const std::function<Rgb(std::uint32_t)>& color) {
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    const auto& v = mc.triangle(t).v;
    r.triangle(p3(mc.vertex(v[0]).approx), p3(mc.vertex(v[1]).approx), p3(mc.vertex(v[2]).approx), color(t));
  }
}

void draw_curves(Renderer3d& r, const MedialCurves& c, const Rgb& color, double width,
                 const std::function<bool(std::uint32_t)>& keep) {
  for (std::uint32_t e = 0; e < c.edges.size(); ++e)
    if (!keep || keep(e)) r.line(p3(c.nodes[c.edges[e].u].position), p3(c.nodes[c.edges[e].v].position), color, width);
  for (std::uint32_t n = 0; n < c.nodes.size(); ++n)  // isolated nodes: a curve shrunk to a point
    if (c.edges.empty()) r.point(p3(c.nodes[n].position), 2.5 * width, color);
}

void draw_paths(Renderer3d& r, const std::vector<BurningPath>& paths, const Rgb& color, double width, double head) {
  for (const BurningPath& p : paths) {
    if (p.points.size() < 2) continue;
    for (std::size_t i = 1; i < p.points.size(); ++i) r.line(p3(p.points[i - 1]), p3(p.points[i]), color, width);
    // The arrowhead at points[0], along the last straight piece, its wings in the plane of
    // that piece and the vertical (or x when the piece is vertical).
    const Vec3d tip = p.points[0], dir = v3::unit(v3::sub(p.points[0], p.points[1]));
    Vec3d side = v3::cross(dir, Vec3d{0, 0, 1});
    if (v3::norm(side) < 0.2) side = v3::cross(dir, Vec3d{1, 0, 0});
    side = v3::unit(side);
    const double len = std::min(head, v3::dist(p.points[0], p.points[1]));
    for (double s : {-0.45, 0.45})
      r.line(p3(tip), p3(v3::add(tip, v3::add(v3::scale(dir, -len), v3::scale(side, s * len)))), color, width);
  }
}

void draw_mesh_scalar(Renderer3d& r, const TriangleMesh3& mesh, const std::vector<double>& value, double lo, double hi,
                      int subdivisions) {
  for (const auto& t : mesh.triangles) {
    const std::array<Point3d, 3> p = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    r.scalar_triangle(p, {value[t[0]], value[t[1]], value[t[2]]}, lo, hi, subdivisions);
  }
}

void draw_mesh_flat(Renderer3d& r, const TriangleMesh3& mesh, const Rgb& color) {
  for (const auto& t : mesh.triangles) r.triangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], color);
}

}  // namespace grassfire::figures

namespace grassfire::figures {

void draw_surface_burning(Renderer3d& r, const TriangleMesh3& mesh, const AxisRefinement& k, int n, double lo, double hi) {
  std::vector<Vec3d> points;
  for (const auto& t : mesh.triangles) {
    const Vec3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        points.push_back(v3::add(a, v3::add(v3::scale(v3::sub(b, a), double(i) / n), v3::scale(v3::sub(c, a), double(j) / n))));
  }
  const SurfaceValues v = map_to_surface(k, points);
  std::size_t base = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    auto id = [&](int i, int j) { return base + static_cast<std::size_t>(i * (n + 1) - i * (i - 1) / 2 + j); };
    auto tri = [&](std::size_t p, std::size_t q, std::size_t s) {
      r.scalar_triangle({points[p], points[q], points[s]}, {v.bt[p], v.bt[q], v.bt[s]}, lo, hi, 1);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        tri(id(i, j), id(i + 1, j), id(i, j + 1));
        if (i + j + 2 <= n) tri(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
    base += static_cast<std::size_t>((n + 1) * (n + 2) / 2);
  }
}

}  // namespace grassfire::figures
