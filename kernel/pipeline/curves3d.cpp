// curves3d.cpp -- see curves3d.h.
#include "pipeline/curves3d.h"

#include <stdexcept>

#include "io/curves_export.h"

namespace grassfire {

Curves3dRun curves3d(const Curves3dSetup& setup) {
  const MedialCurveOptions& o = setup.curves;
  if (!(o.min_et_fraction >= 0 && o.min_et_fraction <= 1)) throw std::invalid_argument("--min-et must be in [0, 1]");
  if (!(o.arrive_cosine >= 0 && o.arrive_cosine < 1) || !(o.depart_cosine >= 0 && o.depart_cosine < 1))
    throw std::invalid_argument("--arrive-cosine and --depart-cosine must be in [0, 1)");
  if (std::isnan(o.time_margin)) throw std::invalid_argument("--time-margin must be >= 0");
  const double split = setup.planar_tubularity;
  if (!(split >= 0 && split <= 1)) throw std::invalid_argument("--planar-tubularity must be in [0, 1]");
  Curves3dRun run;
  run.field = load_burning_field(setup.field);
  run.refinement = std::make_unique<AxisRefinement>(AxisRefinement::build(*run.field.field));
  run.curves = medial_curves(*run.refinement, *run.field.field, o);
  run.curves.validate(*run.field.complex);
  run.analysis = analyze_shape(*run.refinement, run.curves, {split});
  run.json = medial_curves_json(run.curves, setup.field.input);
  run.json["analysis"] = shape_analysis_json(run.analysis, split);
  return run;
}

}  // namespace grassfire
