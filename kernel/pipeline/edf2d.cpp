// edf2d.cpp -- see edf2d.h.
#include "pipeline/edf2d.h"

#include <chrono>
#include <stdexcept>

namespace grassfire {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

Edf2dResult compute_edf2d(const Shape2& shape, const Edf2dOptions& options) {
  Edf2dResult r;
  auto t = std::chrono::steady_clock::now();
  if (options.axis == AxisMethod::ExactPolygon) {
    r.graph = std::make_unique<MedialGraph>(exact_polygon_axis(shape, {}, &r.polygon_report));
    r.timings.axis = seconds_since(t);
  } else if (options.axis == AxisMethod::DiskUnion) {
    if (!options.disks) throw std::invalid_argument("edf2d: the disk-union axis needs a disk list");
    r.graph = std::make_unique<MedialGraph>(disk_union_axis(*options.disks, &r.disk_report));
    r.timings.axis = seconds_since(t);
  } else {
    r.samples = options.spacing > 0 ? resample_by_spacing(shape, options.spacing)
                                    : resample_by_count(shape, options.samples);
    r.timings.resample = seconds_since(t);
    r.graph = std::make_unique<MedialGraph>(sampled_medial_axis(shape, r.samples, &r.axis_report));
    r.timings.delaunay = r.axis_report.delaunay_seconds;
    r.timings.axis = r.axis_report.axis_seconds;
  }
  t = std::chrono::steady_clock::now();
  r.burning = std::make_unique<GrassfireResult>(extended_grassfire(*r.graph, options.variant));
  r.timings.burn = seconds_since(t);
  t = std::chrono::steady_clock::now();
  r.measures = node_measures(*r.graph, *r.burning);
  r.timings.measures = seconds_since(t);
  return r;
}

}  // namespace grassfire
