// edf2d.h -- the whole 2D pipeline: shape -> samples -> medial axis -> EDF, EMA, ET, ST.
//
// Computes: for a validated shape, its medial axis, either from uniform arc-length
// boundary samples (shapes/resample.h, medial2/sampled/sampled_axis.h) or exactly for the polygon
// (medial2/polygon/polygon_axis.h) -- or exactly for a union of disks (medial2/disks/disk_union_axis.h,
// from options.disks; the shape is then unused) -- then the extended grassfire on it
// (burn2/extended_grassfire.h) and the node measures (burn2/measures.h), with timings.
// This is what `grassfire edf2d`, the benchmark, the figures and the proof checks run.
// Contract: a validated Shape2 (io/load_shape.h gives one).
// Complexity: O(n log n) for n samples.
#pragma once

#include <cstddef>
#include <memory>

#include "burn2/extended_grassfire.h"
#include "burn2/measures.h"
#include "medial2/disks/disk_union_axis.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/sampled/sampled_axis.h"
#include "shapes/resample.h"

namespace grassfire {

constexpr std::size_t kDefaultSamples = 2000;

enum class AxisMethod { Sampled, ExactPolygon, DiskUnion };

struct Edf2dOptions {
  AxisMethod axis = AxisMethod::Sampled;
  std::size_t samples = kDefaultSamples;  // total boundary samples (ignored when spacing > 0)
  double spacing = 0.0;                   // arc-length spacing, if > 0
  GrassfireVariant variant = GrassfireVariant::Exact;
  const DiskList* disks = nullptr;        // AxisMethod::DiskUnion
};

// Thread CPU seconds per stage (support/cpu_clock.h).
struct Edf2dTimings {
  double resample = 0, delaunay = 0, axis = 0, burn = 0, measures = 0;
  double total() const { return resample + delaunay + axis + burn + measures; }
};

struct Edf2dResult {
  BoundarySamples samples;  // empty for the exact polygon axis
  std::unique_ptr<MedialGraph> graph;  // stable address: `burning` refers to it
  std::unique_ptr<GrassfireResult> burning;
  NodeMeasures measures;
  SampledAxisReport axis_report;    // sampled axis
  PolygonAxisReport polygon_report;  // exact polygon axis
  DiskUnionAxisReport disk_report;    // union of disks
  Edf2dTimings timings;
};

Edf2dResult compute_edf2d(const Shape2& shape, const Edf2dOptions& options = {});

}  // namespace grassfire
