// fig_mesh_axes.cpp -- a gallery of mesh medial axes (docs/exactness.md; 2.1.2 in 3D): for each
// closed mesh of data/meshes, the axis of `grassfire medial3d --kind mesh` at its default
// options (mesh_axis.h: inner Voronoi complex of surface samples, pruned without changing
// its homotopy type, refined until it has the solid's Betti numbers and its thin parts
// are resolved), coloured by the radius R of the medial ball at each point relative to the
// largest on that axis, inside the mesh's edges drawn as a faint wireframe. The caption
// lists, per mesh, the Betti numbers of the solid and of the axis, the samples and the
// axis' size.
#include <algorithm>
#include <cmath>

#include "caption_printf.h"
#include "medial3/mesh/mesh_axis.h"
#include "geometry3/exact_predicates3.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"
#include "io/mesh_io.h"

namespace grassfire::figures {
namespace {

const char* const kMeshes[] = {"cube", "octahedron", "tripod", "cross", "double-torus-example", "joint"};

std::string betti_string(const BettiNumbers& b) { return caption_printf("[%ld, %ld, %ld]", long(b.b0), long(b.b1), long(b.b2)); }

// The axis coloured by R / R_max (hue 0..1) in the panel (x, y, w, h), the mesh as a wireframe.
void draw_panel(SvgCanvas& canvas, const TriangleMesh3& mesh, const MeshAxis& axis, double x, double y, double w, double h) {
  const Camera cam = framing_camera(std::vector<Vec3d>(mesh.vertices.begin(), mesh.vertices.end()), 35, 28, 28);
  Renderer3d r(cam);
  const RawComplex& c = axis.complex;
  std::vector<double> radius;
  std::vector<Point3d> p;
  for (std::size_t v = 0; v < c.vertices.size(); ++v) {
    radius.push_back(std::sqrt(c.radius_squared[v].get_d()));
    const auto d = to_double(c.vertices[v]);
    p.push_back({d[0], d[1], d[2]});
  }
  const double top = radius.empty() ? 1 : *std::max_element(radius.begin(), radius.end());
  for (const auto& t : c.triangles)
    r.scalar_triangle({p[t[0]], p[t[1]], p[t[2]]}, {radius[t[0]] / top, radius[t[1]] / top, radius[t[2]] / top}, 0, 1, 1);
  for (const auto& s : c.segments) r.line(p[s[0]], p[s[1]], {0.1, 0.1, 0.1}, 1.4);
  if (c.triangles.empty() && c.segments.empty())
    for (const Point3d& q : p) r.point(q, 3, {0.8, 0.1, 0.1});
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < t[(k + 1) % 3]) {
        const auto& a = mesh.vertices[t[k]];
        const auto& b = mesh.vertices[t[(k + 1) % 3]];
        r.line({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {0.55, 0.58, 0.65}, 0.4);
      }
  r.render(canvas, x, y, w, h);
}

std::vector<FigureFile> fig_mesh_axes(const FigureContext& ctx) {
  constexpr double kW = 440, kH = 400;
  SvgCanvas canvas(3 * kW, 2 * kH + 90);
  std::string rows;
  for (int i = 0; i < 6; ++i) {
    const TriangleMesh3 mesh = read_triangle_mesh(ctx.data_dir + "/meshes/" + kMeshes[i] + ".off");
    const MeshAxis axis = mesh_medial_axis(mesh);
    const double x = kW * (i % 3), y = 30 + kH * (i / 3);
    draw_panel(canvas, mesh, axis, x, y, kW, kH - 20);
    canvas.text({x + kW / 2, y + 4}, caption_printf("%s: solid %s, axis %s", kMeshes[i], betti_string(axis.solid.betti).c_str(),
                                                     betti_string(axis.axis_betti).c_str()),
                 14, "middle");
    rows += caption_printf("%s%s: solid %s, axis %s, %zu samples, %d refinements, %zu vertices, %zu triangles, %zu segments",
                           i ? "; " : "", kMeshes[i], betti_string(axis.solid.betti).c_str(), betti_string(axis.axis_betti).c_str(),
                           axis.samples.lattice.size(), axis.refinements(), axis.complex.vertices.size(),
                           axis.complex.triangles.size(), axis.complex.segments.size());
  }
  colour_bar(canvas, 3 * kW / 2 - 150, 2 * kH + 50, 300, 0, 1, "R / largest R on the axis");
  canvas.save(ctx.out_dir + "/fig_mesh_axes.svg");
  return {{"fig_mesh_axes.svg",
           "Mesh medial axes (2.1.2; grassfire medial3d --kind mesh at its default options): the inner Voronoi complex "
           "of surface samples, pruned by collapses that keep its homotopy type, refined until its Betti numbers "
           "[b0, b1, b2] are the solid's and its thin parts are resolved; coloured by the medial ball's radius R "
           "relative to the largest on each axis (hue from red, small, to magenta, largest), black lines the "
           "axis' 1-dimensional parts (Voronoi edges), the mesh as a grey wireframe. Along convex edges a band about 2 h wide (h the spacing) is pruned by design. Per mesh: " +
               rows + "."}};
}

GF_REGISTER_FIGURE("fig_mesh_axes", "Gallery: medial axes of closed meshes coloured by R, with Betti numbers", fig_mesh_axes);

}  // namespace
}  // namespace grassfire::figures
