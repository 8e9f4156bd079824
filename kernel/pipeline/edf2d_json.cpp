// edf2d_json.cpp -- see edf2d_json.h.
#include "pipeline/edf2d_json.h"

#include <optional>

#include "burn2/closest_points.h"
#include "burn2/potential_residue.h"
#include "io/medial2_json.h"

namespace grassfire {

std::string edf2d_json(const Shape2& shape, const Edf2dOptions& options, const Edf2dResult& r) {
  std::size_t samples = 0;
  for (const auto& ring : r.samples) samples += ring.size();
  std::optional<PotentialResidue> pr;  // PR needs arc lengths along the boundary
  if (options.axis != AxisMethod::DiskUnion)
    pr = potential_residue(*r.graph, closest_points(*r.graph, &shape, &r.samples));
  return medial2d_json({shape.name, samples, r.graph.get(), r.burning.get(), &r.measures, pr ? &*pr : nullptr,
                        r.polygon_report.voronoi_fallbacks});
}

}  // namespace grassfire
