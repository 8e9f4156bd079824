// fig_5_5.cpp -- Figure 5.5 in the style of the dissertation (5.3): a shape and a
// perturbed copy, each shown as its surface coloured by the burning time of the medial
// ball that touches it, its medial axis coloured by BT, and its medial curves. The tripod
// mesh (data/meshes) and a copy whose vertices moved along their normals by up to 1.5% of
// its bounding diagonal; the mesh axes of medial3d (mesh_axis.h, default options), the
// discrete baseline at 1/150 of the diagonal.
#include <cmath>

#include "curves3/curve_distance.h"
#include "caption_printf.h"
#include "medial3/mesh/mesh_axis.h"
#include "geometry3/mesh_perturbation.h"
#include "fig_4_scene.h"
#include "fig_5_scene.h"
#include "figure_registry.h"
#include "io/mesh_io.h"

namespace grassfire::figures {
namespace {

constexpr double kAmplitude = 0.015;

std::vector<FigureFile> fig_5_5(const FigureContext& ctx) {
  const TriangleMesh3 original = read_triangle_mesh(ctx.data_dir + "/meshes/tripod.off");
  const double diagonal = mesh_bounding_diagonal(original), h = diagonal / 150;
  const TriangleMesh3 moved = perturb_mesh(original, kAmplitude * diagonal, 5);
  const CurvesScene a(mesh_medial_axis(original).complex, h), b(mesh_medial_axis(moved).complex, h);
  const double hi = std::max(max_finite_bt(a), max_finite_bt(b));
  const Camera cam = framing_camera(std::vector<Vec3d>(original.vertices.begin(), original.vertices.end()), 55, 35, 26);
  SvgCanvas canvas(1500, 960);
  draw_rows_of_three(canvas, cam,
                     {"surface: BT of the touching medial ball", "medial axis: BT", "medial curves (axis as wireframe)"},
                     [&](int row, int column, Renderer3d& r) {
                       const CurvesScene& s = row == 0 ? a : b;
                       if (column == 0) draw_surface_burning(r, row == 0 ? original : moved, s.k, 5, 0, hi);
                       if (column == 1) draw_burning(r, s, 0, hi, 0);
                       if (column == 2) draw_wire_and_curves(r, s);
                     });
  colour_bar(canvas, 630, 930, 240, 0, hi, "burning time BT");
  canvas.save(ctx.out_dir + "/fig5_5.svg");
  const double distance = curve_hausdorff(a.curves, b.curves, h / 2);
  return {{"fig5_5.svg",
           caption_printf("Fig. 5.5 style (5.3): the tripod (top) and a copy whose vertices moved along their normals by "
                          "up to %.1f%% of its diagonal (bottom, %.4f): the surface coloured by BT of the medial ball "
                          "touching each point (left), the mesh axis (medial3d) coloured by BT (middle; "
                          "hue 0..%.3f, shared), and the medial curves (right; b0 = %ld, b1 = %ld on both, as their axes). "
                          "Many of the axis' singular edges are where fronts die, so the curves run along them; "
                          "the two graphs are %.4f apart in Hausdorff distance "
                          "(%.1f x the perturbation), %zu and %zu nodes.",
                          100 * kAmplitude, kAmplitude * diagonal, hi, a.curves.curve_betti.b0, a.curves.curve_betti.b1,
                          distance, distance / (kAmplitude * diagonal), a.curves.nodes.size(), b.curves.nodes.size())}};
}

GF_REGISTER_FIGURE("fig5_5", "Figure 5.5 (style): burning and medial curves of a mesh and a perturbed copy", fig_5_5);

}  // namespace
}  // namespace grassfire::figures
