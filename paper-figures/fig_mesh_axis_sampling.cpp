// fig_mesh_axis_sampling.cpp -- the mesh-axis sampling study as a figure (docs/exactness.md;
// 2.1.2 in 3D): redrawn from the committed CSV experiments/results/mesh_axis_sampling.csv
// (the study takes minutes on the shared meshes, which the project does not ship; rerun it
// with `build/experiments/study_mesh_axis_sampling ../shared/data/meshes`). The panels are
// experiments/mesh_axis_sampling_plot.h's; the caption gives, per mesh, the distance at
// the coarsest and the finest density and whether the first round had the solid's Betti
// numbers.
#include <string>
#include <vector>

#include "../experiments/mesh_axis_sampling_plot.h"
#include "caption_printf.h"
#include "figure_registry.h"

namespace grassfire::figures {
namespace {

std::vector<FigureFile> fig_mesh_axis_sampling(const FigureContext& ctx) {
  const std::vector<sampling_plot::Point> points =
      sampling_plot::read_csv(ctx.data_dir + "/../experiments/results/mesh_axis_sampling.csv");
  sampling_plot::save(points, ctx.out_dir + "/fig_mesh_axis_sampling.svg");
  std::string rows;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const sampling_plot::Point& p = points[i];
    if (i == 0 || points[i - 1].mesh != p.mesh) rows += std::string(i ? "; " : "") + p.mesh + ":";
    if (p.reference) {
      rows += caption_printf(" reference at h_axis/D %.3g", p.h_axis_over_d);
      continue;
    }
    rows += caption_printf(" %.3g at %.3g%s", p.hausdorff_over_d, p.h_axis_over_d,
                           p.first_round_betti_error ? caption_printf(" (first round Betti off by %ld)", p.first_round_betti_error).c_str() : "");
  }
  return {{"fig_mesh_axis_sampling.svg",
           "Mesh medial axis against sampling density (experiments/study_mesh_axis_sampling on the shared meshes; "
           "from the committed CSV). Top: Hausdorff distance / D (D the bounding diagonal) to the exact convex axis "
           "(convex meshes; dashed: from its points of depth R >= 2 h_axis only) or to the finest axis of the "
           "study (other meshes), against the coarsest spacing of the returned round h_axis / D. Bottom: how far "
           "the first round's Betti numbers (plain sampling at spacing h, before any refinement) are from the "
           "solid's; the returned axis always has the solid's. Per mesh, Hausdorff / D at h_axis / D: " +
               rows + "."}};
}

}  // namespace

GF_REGISTER_FIGURE("fig_mesh_axis_sampling", "Study: mesh axis error and topology against sampling density",
                   fig_mesh_axis_sampling);

}  // namespace grassfire::figures
