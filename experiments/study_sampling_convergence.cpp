// study_sampling_convergence -- does the EDF on the sampled Voronoi axis converge to the
// EDF on the exact polygon axis as the boundary sampling densifies (docs/exactness.md)?
//
// For each shape of a fixed list (22 real shapes of the 2D Shape Structure dataset and the
// built-ins) and each sample count N: the sampled pipeline (pipeline/edf2d.h, Sampled, N
// samples) against the exact polygon axis (ExactPolygon), compared by
// apps2d/axis_correspondence.h: each node of the sampled axis is mapped to the nearest
// point of the exact axis, and the EDFs there are compared (the exact EDF inside an edge
// by edf_along). Reported, all divided by the shape's diameter D: max, mean and 95th /
// 99th percentile of the absolute EDF error, the max error when a node may match any
// exact point within 3 sample spacings more than its nearest (junction-tolerant, see
// axis_correspondence.h), the distance between the two EMA points, the Hausdorff
// distance between the axes (evaluated at points D/2000 apart). The comparison is measurement in double
// precision (see axis_correspondence.h); both axes and both burnings are certified.
// Output: OUT/sampling_convergence.csv (one row per shape and N), OUT/sampling_convergence
// _summary.csv (per N: mean and median over shapes, slope of the mean against the previous
// N in log-log), OUT/sampling_convergence.svg (log-log plot of the means).
// Usage: study_sampling_convergence SHAPES_DIR [OUT] [--quick] [--shard I/N] [--progress|--quiet]
//   SHAPES_DIR holds the dataset's *.json files (e.g. /work/shared/data/shapes2d);
//   --quick runs N = 500, 1000, 2000 only; --shard I/N runs every N-th shape of the list
//   and writes its rows only (experiments/shard.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "apps2d/axis_correspondence.h"
#include "support/progress.h"
#include "pipeline/edf2d.h"
#include "plot_svg.h"
#include "shapes/builtin_shapes.h"
#include "io/load_shape.h"
#include "shapes/resample.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"
#include "support/cpu_clock.h"

using namespace grassfire;

namespace {

const char* const kShapes[] = {"apple-3",   "bell-3",     "bird-3",   "Bone-3",   "bottle-03", "car-03",
                               "cattle-7",  "chicken-3",  "children-3", "classic-3", "Comma-3", "cup-3",
                               "device3-3", "dog-10",     "fork-3",   "guitar-3", "hammer-3",  "horseshoe-3",
                               "key-3",     "ray-3",      "spoon-3",  "Heart-3"};
const char* const kBuiltins[] = {"rectangle", "rectangle-bump", "branches", "blunt-sharp", "noisy", "hole"};

struct Row {
  std::string shape;
  std::size_t samples = 0, nodes = 0, infinite = 0;
  AxisComparison cmp;
  double seconds = 0;
  std::string error;
};

std::vector<Row> run_shape(const std::string& arg, const std::string& label, const std::vector<std::size_t>& levels) {
  std::vector<Row> rows;
  try {
    const Shape2 shape = load_shape(arg);
    const double diameter = shape_diameter(shape);
    Edf2dOptions exact_opt;
    exact_opt.axis = AxisMethod::ExactPolygon;
    const Edf2dResult exact = compute_edf2d(shape, exact_opt);
    for (std::size_t n : levels) {
      Row r;
      r.shape = label;
      r.samples = n;
      try {
        const auto t0 = std::chrono::steady_clock::now();
        Edf2dOptions opt;
        opt.samples = n;
        const Edf2dResult sampled = compute_edf2d(shape, opt);
        r.seconds = wall_seconds_since(t0);
        r.nodes = sampled.graph->node_count();
        // Junction-tolerant error: any point of the exact axis within three sample spacings
        // more than the nearest one (axis_correspondence.h); a sampled junction sits up to
        // about two spacings along the axis from the exact one where branches meet at
        // shallow angles (seen on apple-3 at N = 2000).
        double perimeter = 0;
        for (const Ring& ring : shape.rings) perimeter += ring_length(ring);
        r.cmp = compare_axes(*sampled.graph, *sampled.burning, *exact.graph, *exact.burning, diameter, diameter / 2000,
                             3 * perimeter / double(n));
      } catch (const std::exception& e) {
        r.error = e.what();
      }
      rows.push_back(r);
    }
  } catch (const std::exception& e) {
    for (std::size_t n : levels) {
      Row r;
      r.shape = label;
      r.samples = n;
      r.error = e.what();
      rows.push_back(r);
    }
  }
  return rows;
}

std::string csv_text(std::string s) {
  std::replace(s.begin(), s.end(), ',', ';');
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? std::nan("") : s / static_cast<double>(v.size());
}

struct Metric {
  const char* name;
  double (*get)(const AxisComparison&);
};
const Metric kMetrics[] = {
    {"max_edf_error", [](const AxisComparison& c) { return c.max_edf_error; }},
    {"max_edf_error_near", [](const AxisComparison& c) { return c.max_edf_error_near; }},
    {"mean_edf_error", [](const AxisComparison& c) { return c.mean_edf_error; }},
    {"p95_edf_error", [](const AxisComparison& c) { return c.p95_edf_error; }},
    {"ema_distance", [](const AxisComparison& c) { return c.ema_distance; }},
    {"hausdorff", [](const AxisComparison& c) { return c.hausdorff; }},
};

// Per level and metric, the values over the shapes without error (NaN EMA distances skipped).
std::map<std::size_t, std::vector<std::vector<double>>> collect(const std::vector<Row>& rows) {
  std::map<std::size_t, std::vector<std::vector<double>>> by_level;
  for (const Row& r : rows) {
    auto& v = by_level[r.samples];
    v.resize(std::size(kMetrics));
    if (!r.error.empty()) continue;
    for (std::size_t m = 0; m < std::size(kMetrics); ++m) {
      const double x = kMetrics[m].get(r.cmp);
      if (std::isfinite(x)) v[m].push_back(x);
    }
  }
  return by_level;
}

void write_summary(const std::vector<Row>& rows, const std::string& path) {
  std::ofstream os(path);
  os << "samples,metric,shapes,mean,median,max,slope_of_mean\n";
  const auto by_level = collect(rows);
  std::vector<double> prev_mean(std::size(kMetrics), std::nan(""));
  std::size_t prev_n = 0;
  for (const auto& [n, values] : by_level) {
    for (std::size_t m = 0; m < std::size(kMetrics); ++m) {
      const double mu = mean(values[m]);
      const bool both = prev_n && mu > 0 && prev_mean[m] > 0;  // no slope through a zero
      const double slope = both ? std::log(mu / prev_mean[m]) / std::log(double(n) / double(prev_n)) : std::nan("");
      const double mx = values[m].empty() ? std::nan("") : *std::max_element(values[m].begin(), values[m].end());
      char buf[256];
      std::snprintf(buf, sizeof buf, "%zu,%s,%zu,%.4g,%.4g,%.4g,%.3f\n", n, kMetrics[m].name, values[m].size(), mu,
                    plot::median(values[m]), mx, slope);
      os << buf;
      prev_mean[m] = mu;
    }
    prev_n = n;
  }
}

void write_plot(const std::vector<Row>& rows, const std::string& path) {
  plot::Plot p;
  p.title = "Sampled axis vs exact polygon axis: mean over shapes (all / D)";
  p.x_label = "boundary samples N";
  p.y_label = "error / diameter";
  p.log_x = p.log_y = true;
  const auto by_level = collect(rows);
  for (std::size_t m = 0; m < std::size(kMetrics); ++m) {
    plot::Series s;
    s.name = kMetrics[m].name;
    s.colour = plot::series_colour(m);
    for (const auto& [n, values] : by_level) s.x.push_back(double(n)), s.y.push_back(mean(values[m]));
    p.series.push_back(s);
  }
  const plot::Series& mean_error = p.series[2];  // kMetrics[2], mean_edf_error
  if (!mean_error.y.empty())
    p.slopes.push_back({-1, mean_error.x.front(), mean_error.y.front() * 2, "slope -1"});
  plot::save(p, path);
}

constexpr const char* kUsage =
    "usage: study_sampling_convergence SHAPES_DIR [OUT] [--quick] [--shard I/N] [--progress|--quiet]\ndoes the EDF on the sampled Voronoi axis converge to the EDF on the exact polygon axis as the boundary sampling densifies (docs/exactness.md)?\n(CSV columns and details: the header of experiments/study_sampling_convergence.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{"--quick"}, {}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string dir = cmd.positional[0], out = cmd.positional_or(1, ".");
  const bool quick = cmd.flag("--quick");
  const std::vector<std::size_t> levels =
      quick ? std::vector<std::size_t>{500, 1000, 2000} : std::vector<std::size_t>{500, 1000, 2000, 4000, 8000, 16000};
  std::vector<std::pair<std::string, std::string>> inputs;  // (argument, label)
  for (const char* name : kShapes) inputs.emplace_back(dir + "/" + name + ".json", name);
  for (const char* name : kBuiltins) inputs.emplace_back(std::string("builtin:") + name, name);
  inputs = experiments::shard_of(inputs, shard);
  std::vector<Row> rows;
  Progress progress("study_sampling_convergence " + shard.label(), inputs.size());
  for (const auto& [arg, label] : inputs) {
    progress.item(label);
    const auto r = run_shape(arg, label, levels);
    rows.insert(rows.end(), r.begin(), r.end());
    progress.advance();
  }
  progress.done();
  std::vector<std::string> lines;
  std::size_t failures = 0;
  for (const Row& r : rows) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s,%zu,%zu,%zu,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.4f,", r.shape.c_str(),
                  r.samples, r.nodes, r.cmp.nodes, r.cmp.infinite, r.cmp.max_edf_error, r.cmp.max_edf_error_near,
                  r.cmp.mean_edf_error,
                  r.cmp.p95_edf_error, r.cmp.p99_edf_error, r.cmp.max_node_offset, r.cmp.ema_distance, r.cmp.hausdorff,
                  r.seconds);
    lines.push_back(buf + csv_text(r.error));
    failures += !r.error.empty();
  }
  experiments::write_sorted_csv(out + "/sampling_convergence.csv",
                                "shape,samples,nodes,compared,infinite,max_edf_error,max_edf_error_near,mean_edf_error,"
                                "p95_edf_error,p99_edf_error,max_node_offset,ema_distance,hausdorff,seconds,error",
                                lines);
  if (experiments::rows_only(shard, out + "/sampling_convergence.csv")) return failures ? 1 : 0;
  write_summary(rows, out + "/sampling_convergence_summary.csv");
  write_plot(rows, out + "/sampling_convergence.svg");
  note(std::to_string(rows.size()) + " rows, " + std::to_string(failures) + " failures; wrote " + out +
       "/sampling_convergence{.csv,_summary.csv,.svg}");
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_sampling_convergence", kUsage, run);
}
