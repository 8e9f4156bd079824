// burn3d_methods.h -- the burning methods behind `grassfire burn3d --method NAME` and the
// Python module's grassfire.burn3d(method=NAME).
//
// The pipeline (pipeline/burn3d.h) loads and validates the complex, locates the sources
// and the queries on it (exactly; complex3/point_location.h), then calls one method
// through this interface; the program writes what it returns (JSON, CSV, PLY, VTK), the
// module returns it as numpy arrays. A new method is one function of this signature and
// one row of the table in burn3d_methods.cpp.
// Contract for a method: vertex_bt has one value per vertex and query_values one per
// query (same order); +infinity where the point never burns; bt_error is a bound on
// |bt - BT| (+infinity when the method certifies no two-sided bound: the discrete
// baseline is an upper bound only); vertex_bt_error likewise per vertex. report holds the method's own counters (timings,
// event counts, certification counts); summary is one line for stdout.
// Complexity: that of the method. Section: ch. 4 (Definitions 9-10), docs/design.md 5.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/point_sources.h"
#include "complex3/medial_complex.h"
#include "complex3/point_location.h"

namespace grassfire {

struct BurnRequest {
  const MedialComplex& mc;
  std::vector<PointSource> sources;
  std::vector<ComplexPoint> queries;
  double spacing = 0.0;            // discrete: Steiner spacing h
  std::uint64_t max_points = 0;    // discrete: graph point budget
  // Reports progress: a stage name, the fraction done in [0, 1] and, for a long stage, its
  // state in words ("" when none; support/progress.h shows it).
  std::function<void(const std::string& stage, double done, const std::string& detail)> progress;
  std::string input;               // names the input in a method's messages
  // exact: burn a complex with singular edges or singular points anyway, with every
  // singular edge a wall (fire stops there; docs/exact-engine.md). That is not Definition 9's
  // BT (which needs the junction rule, docs/exact-engine.md): the report says so.
  bool singular_walls = false;
};

struct BurnValue {
  double bt = 0.0;
  double bt_error = 0.0;
};

struct BurnOutcome {
  std::vector<double> vertex_bt;
  // Per vertex, a bound on |vertex_bt - BT|; empty when the method certifies none (the
  // discrete baseline). The --json report lists it as vertex_values.BT_error.
  std::vector<double> vertex_bt_error;
  std::vector<BurnValue> query_values;
  nlohmann::json report;
  std::string summary;
  // The discrete method's whole burning (graph values and predecessors), which
  // burn3d --field writes (io/burn_field_file.h); null for the other methods.
  std::shared_ptr<const DiscreteBurning> discrete;
};

// Dijkstra over vertices and Steiner points (burn3/discrete/discrete_burning.h, discrete_query.h).
BurnOutcome burn_by_discrete(const BurnRequest& request);
// The exact window-propagation engine (docs/exact-engine.md); pipeline/burn3d_exact.cpp.
BurnOutcome burn_by_exact(const BurnRequest& request);

// The exact engine's sweep as progress (ExactBurningOptions::on_event): every 256 events,
// report(fraction, detail) with the current event time t against the largest ignition time
// (`largest_source_time` and the border rules' f at the vertices) and an estimate of the
// final time (the largest R when it is larger, as on a medial axis, where BT >= R; else the
// largest ignition time plus the complex's bounding box diagonal), the events and the
// windows so far; the fraction is t over the estimate, below 1 until the sweep ends. An
// empty function when progress lines are off (support/progress.h): the engine then calls
// nothing.
std::function<void(double, std::uint64_t, std::uint64_t)> exact_sweep_reporter(
    const MedialComplex& mc, double largest_source_time, std::function<void(double, const std::string&)> report);

using BurnMethod = BurnOutcome (*)(const BurnRequest&);
// The method called `name` ("discrete", "exact"); std::invalid_argument "unknown method
// 'NAME' (discrete or exact)" for any other name.
BurnMethod burn_method(const std::string& name);

}  // namespace grassfire
