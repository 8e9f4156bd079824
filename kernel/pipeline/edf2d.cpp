// edf2d.cpp -- see edf2d.h.
#include "pipeline/edf2d.h"

#include <stdexcept>

#include "support/cpu_clock.h"

namespace grassfire {

namespace {
}  // namespace

Edf2dResult compute_edf2d(const Shape2& shape, const Edf2dOptions& options) {
  Edf2dResult r;
  double t = thread_seconds();
  if (options.axis == AxisMethod::ExactPolygon) {
    r.graph = std::make_unique<MedialGraph>(exact_polygon_axis(shape, {}, &r.polygon_report));
    r.timings.axis = thread_seconds_since(t);
  } else if (options.axis == AxisMethod::DiskUnion) {
    if (!options.disks) throw std::invalid_argument("edf2d: the disk-union axis needs a disk list");
    r.graph = std::make_unique<MedialGraph>(disk_union_axis(*options.disks, &r.disk_report));
    r.timings.axis = thread_seconds_since(t);
  } else {
    r.samples = options.spacing > 0 ? resample_by_spacing(shape, options.spacing)
                                    : resample_by_count(shape, options.samples);
    r.timings.resample = thread_seconds_since(t);
    r.graph = std::make_unique<MedialGraph>(sampled_medial_axis(shape, r.samples, &r.axis_report));
    r.timings.delaunay = r.axis_report.delaunay_seconds;
    r.timings.axis = r.axis_report.axis_seconds;
  }
  t = thread_seconds();
  r.burning = std::make_unique<GrassfireResult>(extended_grassfire(*r.graph, options.variant));
  r.timings.burn = thread_seconds_since(t);
  t = thread_seconds();
  r.measures = node_measures(*r.graph, *r.burning);
  r.timings.measures = thread_seconds_since(t);
  return r;
}

}  // namespace grassfire
