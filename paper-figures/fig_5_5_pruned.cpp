// fig_5_5_pruned.cpp -- Figure 5.5 redrawn on pruned axes: the tripod and the perturbed copy
// of fig5_5, each mesh axis pruned by erosion thickness (pipeline/prune3d.h: ET >= a fraction
// of the largest R, exact cuts along the threshold line, collapses from the border only, so
// the axis' homotopy type is kept), and the medial curves (5.1.2) of the pruned axis, burned
// as an axis of its own from its new border (f = R there, the discrete baseline at 1/150 of
// the diagonal, as fig5_5). Beside them the curves of the raw axes, as fig5_5 draws them, and
// the Hausdorff distance between the two copies' curves, raw and pruned. The threshold is
// fig3_pruning3d's high one, 0.1 R_max, which keeps the spine.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "caption_printf.h"
#include "curves3/curve_distance.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"
#include "geometry3/mesh_perturbation.h"
#include "io/mesh_io.h"
#include "medial3/mesh/mesh_axis.h"
#include "pipeline/prune3d.h"

namespace grassfire::figures {
namespace {

constexpr double kAmplitude = 0.015;  // fig5_5's perturbation
constexpr double kErosion = 0.1;     // ET >= kErosion R_max

// The mesh axis of `mesh_path` pruned at ET >= kErosion R_max (discrete burning at h).
Prune3dRun prune_by_et(const std::string& mesh_path, double h) {
  Prune3dSetup setup = default_prune3d_setup();
  setup.field.input = mesh_path;
  setup.field.method = "discrete";
  setup.field.spacing = h;
  setup.field.command = "fig5_5_pruned";
  setup.erosion = mpq_class(kErosion);
  setup.relative = true;
  return prune3d(setup);
}

std::vector<FigureFile> fig_5_5_pruned(const FigureContext& ctx) {
  const std::string tripod = ctx.data_dir + "/meshes/tripod.off";
  const TriangleMesh3 original = read_triangle_mesh(tripod);
  const double diagonal = mesh_bounding_diagonal(original), h = diagonal / 150;
  const TriangleMesh3 moved = perturb_mesh(original, kAmplitude * diagonal, 5);
  // prune3d reads its input as the program does: the perturbed copy goes through a file.
  const std::string moved_path = ctx.out_dir + "/fig5_5_pruned_perturbed.off";
  write_off(moved, moved_path);
  const Prune3dRun pa = prune_by_et(tripod, h), pb = prune_by_et(moved_path, h);
  std::filesystem::remove(moved_path);
  const CurvesScene raw_a(mesh_medial_axis(original).complex, h), raw_b(mesh_medial_axis(moved).complex, h);
  const CurvesScene a(pa.pruned.complex, h), b(pb.pruned.complex, h);
  const double hi = std::max(max_finite_bt(a), max_finite_bt(b));
  const Camera cam = framing_camera(std::vector<Vec3d>(original.vertices.begin(), original.vertices.end()), 55, 35, 26);
  SvgCanvas canvas(1500, 960);
  const std::string pruned_title = caption_printf("axis pruned at ET >= %.2f R_max: its BT", kErosion);
  draw_rows_of_three(canvas, cam, {"raw axis: medial curves (as Fig. 5.5)", pruned_title, "pruned axis: medial curves"},
                     [&](int row, int column, Renderer3d& r) {
                       const CurvesScene& s = row == 0 ? a : b;
                       if (column == 0) draw_wire_and_curves(r, row == 0 ? raw_a : raw_b);
                       if (column == 2) draw_wire_and_curves(r, s);
                       if (column != 1) return;
                       draw_burning(r, s, 0, hi, 0);
                       for (const ComplexEdge& e : s.mc.edges())  // the 1-dimensional parts pruning left
                         if (e.stratum == EdgeStratum::Dangling)
                           r.line(p3(s.mc.vertex(e.v[0]).approx), p3(s.mc.vertex(e.v[1]).approx), {0.3, 0.3, 0.35}, 1.2);
                     });
  colour_bar(canvas, 630, 930, 240, 0, hi, "burning time BT of the pruned axis");
  canvas.save(ctx.out_dir + "/fig5_5_pruned.svg");
  const double raw_distance = curve_hausdorff(raw_a.curves, raw_b.curves, h / 2);
  const double distance = curve_hausdorff(a.curves, b.curves, h / 2);
  const double amplitude = kAmplitude * diagonal;
  return {{"fig5_5_pruned.svg",
           caption_printf(
               "Fig. 5.5 redrawn on pruned axes: the tripod (top) and fig5_5's copy whose vertices moved along their "
               "normals by up to %.1f%% of its diagonal (bottom, %.4f). Left: the medial curves of the raw mesh axes "
               "(%zu and %zu nodes, %zu and %zu tubular branches). Middle: each axis pruned at ET >= %.2f R_max "
               "(grassfire prune3d --method discrete --relative --et %.2f: exact cuts, collapses from the border, "
               "Betti [%ld, %ld, %ld] and [%ld, %ld, %ld] as the raw axes), burned as an axis of its own from its new "
               "border (hue 0..%.3f). Right: the medial curves of the pruned axes (%zu and %zu nodes, %zu and %zu "
               "tubular branches; b0 = %ld, b1 = %ld). Pruning removes the spikes of the arms, so the curves of the "
               "spine lose most of their side branches; what ET keeps of the arms' ends are islands of triangles "
               "joined to the spine by segments, and short segments stand out of the spine (dark lines, middle): "
               "burning the pruned axis again from its new border gives short branches there. The two copies' curves are %.4f apart in Hausdorff distance raw (%.1f x "
               "the perturbation) and %.4f pruned (%.1f x): the farthest points are at the arms' ends, which pruning "
               "does not fix.",
               100 * kAmplitude, amplitude, raw_a.curves.nodes.size(), raw_b.curves.nodes.size(),
               raw_a.analysis.signature.curve_lengths.size(), raw_b.analysis.signature.curve_lengths.size(), kErosion,
               kErosion, pa.pruned.betti_pruned.b0, pa.pruned.betti_pruned.b1, pa.pruned.betti_pruned.b2,
               pb.pruned.betti_pruned.b0, pb.pruned.betti_pruned.b1, pb.pruned.betti_pruned.b2, hi,
               a.curves.nodes.size(), b.curves.nodes.size(), a.analysis.signature.curve_lengths.size(),
               b.analysis.signature.curve_lengths.size(), a.curves.curve_betti.b0, a.curves.curve_betti.b1,
               raw_distance, raw_distance / amplitude, distance, distance / amplitude)}};
}

GF_REGISTER_FIGURE("fig5_5_pruned",
                   "Figure 5.5 on axes pruned by erosion thickness: medial curves of the pruned tripod and its copy",
                   fig_5_5_pruned);

}  // namespace
}  // namespace grassfire::figures
