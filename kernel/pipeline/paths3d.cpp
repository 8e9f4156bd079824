// paths3d.cpp -- see paths3d.h.
#include "pipeline/paths3d.h"

#include <algorithm>
#include <stdexcept>

#include "curves3/medial_curves.h"
#include "complex3/point_location.h"
#include "io/curves_export.h"

namespace grassfire {

Paths3dRun paths3d(const Paths3dSetup& setup) {
  const std::string& from = setup.from;
  if (from != "vertices" && from != "curves" && from != "ends" && from != "points")
    throw std::invalid_argument("--from must be vertices, curves, ends or points");
  if (from == "points" && setup.points.empty()) throw std::invalid_argument(setup.points_name + ": no points");
  if (from != "points" && !setup.points.empty()) throw std::invalid_argument("--points FILE goes with --from points");
  Paths3dRun run;
  run.field = load_burning_field(setup.field);
  const BurningField& field = *run.field.field;
  if (from == "vertices") {
    run.paths = paths_from_vertices(field);
  } else if (from == "curves" || from == "ends") {
    const MedialCurves curves = medial_curves(field);
    curves.validate(*run.field.complex);
    run.paths = from == "curves" ? paths_from_curve_nodes(field, curves) : paths_ending_on_curves(field, curves);
  } else {
    const ComplexLocator locator(*run.field.complex);
    std::vector<CellPoint> located;
    for (const CsvPoint& q : setup.points) {
      const ComplexPoint x = locator.locate(q.point);
      located.push_back(cell_point(field, x));
      run.farthest = std::max(run.farthest, x.snap());
    }
    run.paths = paths_from_points(field, located);
  }
  run.json = burning_paths_json(run.paths, setup.field.input, field.method(), from);
  return run;
}

}  // namespace grassfire
