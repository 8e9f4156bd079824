// fig_3_pruning3d.cpp -- the 3D analogue of Figures 3.6 and 3.7: the medial axis of a mesh
// (the tripod, as `grassfire medial3d` builds it) coloured by erosion thickness ET = BT - R
// (3.4.1 with the burning time of ch. 4), then pruned at a low and a high ET threshold, and
// on a second row coloured by shape tubularity ST = 1 - R / BT (3.5.1), pruned by ST alone
// and by ET with ST (pipeline/prune3d.h: exact cuts along the threshold lines, collapses
// from the border only, so every panel has the axis' Betti numbers). The discrete burning at
// h = D / 100 (the exact engine refuses the singular edges of mesh axes).
#include <algorithm>
#include <cmath>

#include "caption_printf.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"
#include "geometry3/mesh_perturbation.h"
#include "io/mesh_io.h"
#include "pipeline/prune3d.h"

namespace grassfire::figures {
namespace {

struct Panel {
  const char* title;
  double et, st;  // thresholds relative to the largest R (et) and absolute (st); < 0: none
  bool colour_by_st;
};

Prune3dRun prune(const std::string& mesh, double h, double et, double st) {
  Prune3dSetup setup = default_prune3d_setup();
  setup.field.input = mesh;
  setup.field.method = "discrete";
  setup.field.spacing = h;
  setup.field.command = "fig_3_pruning3d";
  setup.erosion = mpq_class(std::max(et, 0.0));
  setup.relative = true;
  if (st >= 0) setup.tubularity = mpq_class(st);
  return prune3d(setup);
}

// The pruned axis coloured by ET / (largest ET of the raw axis) or by ST, the mesh as a
// faint wireframe.
void draw_panel(SvgCanvas& canvas, const TriangleMesh3& mesh, const Prune3dRun& run, bool by_st, double et_top, double x,
                double y, double w, double h) {
  const Camera cam = framing_camera(std::vector<Vec3d>(mesh.vertices.begin(), mesh.vertices.end()), 35, 28, 28);
  Renderer3d r(cam);
  const MedialComplex& c = *run.pruned_complex;
  std::vector<double> value;
  std::vector<Point3d> p;
  for (std::uint32_t v = 0; v < c.vertex_count(); ++v) {
    const PrunedVertex3& pv = run.pruned.vertices[v];
    value.push_back(by_st ? (pv.bt > 0 ? 1 - pv.radius / pv.bt : 0) : (pv.bt - pv.radius) / et_top);
    const Vec3d& a = c.vertex(v).approx;
    p.push_back({a[0], a[1], a[2]});
  }
  for (std::uint32_t t = 0; t < c.triangle_count(); ++t) {
    const auto& v = c.triangle(t).v;
    r.scalar_triangle({p[v[0]], p[v[1]], p[v[2]]}, {value[v[0]], value[v[1]], value[v[2]]}, 0, 1, 1);
  }
  for (const auto& s : run.pruned.complex.segments)
    r.line(p[s[0]], p[s[1]], hue_color((value[s[0]] + value[s[1]]) / 2), 2.2);
  if (c.triangle_count() == 0 && run.pruned.complex.segments.empty())  // collapsed to points
    for (std::uint32_t v = 0; v < c.vertex_count(); ++v) r.point(p[v], 4, hue_color(value[v]));
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < t[(k + 1) % 3]) {
        const auto& a = mesh.vertices[t[k]];
        const auto& b = mesh.vertices[t[(k + 1) % 3]];
        r.line({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, {0.7, 0.72, 0.78}, 0.3);
      }
  r.render(canvas, x, y, w, h);
}

std::string betti_string(const BettiNumbers& b) { return caption_printf("[%ld, %ld, %ld]", b.b0, b.b1, b.b2); }

std::vector<FigureFile> fig_3_pruning3d(const FigureContext& ctx) {
  const std::string path = ctx.data_dir + "/meshes/tripod.off";
  const TriangleMesh3 mesh = read_triangle_mesh(path);
  const double h = mesh_bounding_diagonal(mesh) / 100;
  const Panel panels[] = {{"raw axis, ET", 0, -1, false},      {"ET >= 0.02 R_max", 0.02, -1, false},
                          {"ET >= 0.1 R_max", 0.1, -1, false}, {"raw axis, ST", 0, -1, true},
                          {"ST >= 0.15", -1, 0.15, true},      {"ET >= 0.02 R_max and ST >= 0.15", 0.02, 0.15, true}};
  constexpr double kW = 440, kH = 400;
  SvgCanvas canvas(3 * kW, 2 * kH + 100);
  const Prune3dRun raw = prune(path, h, 0, -1);
  double et_top = 0;
  for (const PrunedVertex3& v : raw.pruned.vertices) et_top = std::max(et_top, v.bt - v.radius);
  std::string rows;
  for (int i = 0; i < 6; ++i) {
    const Panel& q = panels[i];
    const Prune3dRun run = prune(path, h, q.et, q.st);
    const double x = kW * (i % 3), y = 30 + kH * (i / 3);
    draw_panel(canvas, mesh, run, q.colour_by_st, et_top, x, y, kW, kH - 20);
    canvas.text({x + kW / 2, y + 4}, q.title, 15, "middle");
    const MedialComplex& c = *run.pruned_complex;
    rows += caption_printf("%s%s: %u triangles, %u segments, Betti %s", i ? "; " : "", q.title, c.triangle_count(),
                           static_cast<unsigned>(run.pruned.complex.segments.size()),
                           betti_string(run.pruned.betti_pruned).c_str());
  }
  colour_bar(canvas, kW / 2 - 150 + kW / 2, 2 * kH + 55, 300, 0, et_top, "ET (row 1)");
  colour_bar(canvas, 3 * kW / 2 + kW / 2 - 150, 2 * kH + 55, 300, 0, 1, "ST (row 2)");
  canvas.save(ctx.out_dir + "/fig3_pruning3d.svg");
  return {{"fig3_pruning3d.svg",
           "The 3D analogue of Figs. 3.6 and 3.7 on the tripod mesh (grassfire prune3d data/meshes/tripod.off --method "
           "discrete --spacing D/100 --relative): its medial axis coloured by erosion thickness ET = BT - R (row 1, "
           "hue from red, 0, to magenta, the largest ET " +
               caption_printf("%.3g", et_top) +
               "), pruned at ET >= 0.02 and 0.1 times the largest R; row 2 coloured by shape tubularity ST = 1 - R / BT, "
               "pruned at ST >= 0.15 and at ET >= 0.02 R_max with ST >= 0.15. The tripod's arms are tubes whose mesh axis "
               "is a narrow strip that burns across in about R, so ET and ST stay small there: ET >= 0.1 R_max keeps the "
               "spine, ST keeps curves along it, and at ET >= 0.2 R_max a few triangles at the centre are left (the "
               "axis' homotopy type, a point). Cuts follow the threshold lines exactly and "
               "parts go only by collapses from the border, so every panel keeps the axis' Betti numbers; lines are the "
               "axis' 1-dimensional parts. Per panel: " +
               rows + "."}};
}

GF_REGISTER_FIGURE("fig3_pruning3d", "Figs 3.6/3.7 in 3D: a mesh axis coloured by ET and ST, pruned at low and high thresholds",
                   fig_3_pruning3d);

}  // namespace
}  // namespace grassfire::figures
