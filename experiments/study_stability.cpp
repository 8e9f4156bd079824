// study_stability -- how far the EMA, the EDF and the PR maximum move when the boundary is
// perturbed (3.4, Fig. 3.5; 5.1.3, Fig. 5.3).
//
// Shapes: a unit square, the key class (key-*.json), and 20 shapes of other classes.
// For each shape, amplitude a (a fraction of the diameter D), kind (uniform, or one-sided:
// only the boundary right of the bounding-box centre, apps2d/perturbation.h) and seed:
// the perturbed shape (densified at spacing max(D/200, a D), noise along the normal,
// Hausdorff distance <= a D), its exact polygon axis and burning (pipeline/edf2d.h), compared with
// the original's:
//   ema_drift   = |EMA(perturbed) - EMA(original)| / D;
//   edf_change  = max over the nodes x of the original axis of |EDF(x) - EDF'(y(x))| / D,
//                 y(x) the nearest point of the perturbed axis (apps2d/axis_correspondence.h);
//                 The EDF jumps across junctions (Prop 2), so a node of a short branch next
//                 to a junction whose nearest perturbed point lies on the main branch shows
//                 a large change although neither EDF is wrong: the max measures that;
//   edf_p95, edf_mean = the 95th percentile and the mean of the same, over the nodes;
//   pr_drift    = the same as ema_drift for the potential-residue maximum, when available.
// Output: OUT/stability.csv (one row per run), OUT/stability_summary.csv (per kind and
// amplitude: median and max over shapes and seeds, and the largest drift / amplitude with
// its shape), OUT/stability_ema.svg, OUT/stability_edf.svg and OUT/stability_pr.svg
// (log-log, median and max).
// --shard I/N runs every N-th shape of the list and writes its rows only (experiments/shard.h).
// Usage: study_stability SHAPES_DIR [OUT] [--quick] [--shard I/N] [--progress|--quiet]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "apps2d/axis_correspondence.h"
#include "apps2d/perturbation.h"
#include "burn2/closest_points.h"
#include "burn2/potential_residue.h"
#include "support/progress.h"
#include "pipeline/edf2d.h"
#include "plot_svg.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {

const char* const kOthers[] = {"apple-3",  "bell-3",    "bird-3",   "Bone-3",    "bottle-03", "car-03",    "cattle-7",
                               "chicken-3", "children-3", "classic-3", "Comma-3", "cup-3",     "device3-3", "dog-10",
                               "fork-3",   "guitar-3",  "hammer-3", "horseshoe-3", "ray-3",   "spoon-3"};
const double kAmplitudes[] = {0.001, 0.002, 0.005, 0.01, 0.02};

struct Original {
  std::string name;
  Shape2 shape;
  double diameter = 0;
  Edf2dResult axis;
  std::optional<Point2> pr_maximum;
};

struct Run {
  std::string shape;
  PerturbationKind kind;
  double amplitude = 0;
  std::uint64_t seed = 0;
  int attempts = 0;
  std::size_t vertices = 0, nodes = 0;
  double ema_drift = std::nan(""), edf_change = std::nan(""), edf_mean = std::nan(""), pr_drift = std::nan("");
  double edf_p95 = std::nan("");
  std::string error;
};

Edf2dResult exact_axis(const Shape2& s) {
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  return compute_edf2d(s, o);
}

// The PR maximum of an exact polygon axis (burn2/potential_residue.h); none when infinite.
std::optional<Point2> pr_maximum(const MedialGraph& g) {
  const PotentialResidue pr = potential_residue(g, closest_points(g));
  if (pr.maximum.value.value.is_infinite()) return std::nullopt;
  return pr.maximum.position;
}

Shape2 unit_square() {
  Shape2 s{"square", {Ring{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}};
  validate_shape(s, s.name);
  return s;
}

Run perturb_and_compare(const Original& o, PerturbationKind kind, double amplitude, std::uint64_t seed) {
  Run r;
  r.shape = o.name;
  r.kind = kind;
  r.amplitude = amplitude;
  r.seed = seed;
  try {
    PerturbationOptions p;
    p.kind = kind;
    p.amplitude = amplitude * o.diameter;
    // Noise no denser than its amplitude: neighbouring points differ by at most twice the
    // spacing along the normal, so straight stretches never fold (corners still may).
    p.spacing = o.diameter * std::max(1.0 / 200, amplitude);
    p.seed = seed;
    const PerturbedShape ps = perturb_boundary(o.shape, p);
    r.attempts = ps.attempts;
    r.vertices = ps.points;
    const Edf2dResult pa = exact_axis(ps.shape);
    r.nodes = pa.graph->node_count();
    const AxisComparison c =
        compare_axes(*o.axis.graph, *o.axis.burning, *pa.graph, *pa.burning, o.diameter, o.diameter / 2000);
    r.ema_drift = c.ema_distance;
    const std::optional<Point2> pr = pr_maximum(*pa.graph);
    if (pr && o.pr_maximum) r.pr_drift = std::hypot(pr->x - o.pr_maximum->x, pr->y - o.pr_maximum->y) / o.diameter;
    r.edf_change = c.max_edf_error;
    r.edf_mean = c.mean_edf_error;
    r.edf_p95 = c.p95_edf_error;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

double quantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::lround(q * double(v.size() - 1)))];
}

struct Metric {
  const char* name;
  double Run::*field;
};
const Metric kMetrics[] = {{"ema_drift", &Run::ema_drift}, {"edf_change", &Run::edf_change},
                           {"edf_p95", &Run::edf_p95},
                           {"edf_mean", &Run::edf_mean},   {"pr_drift", &Run::pr_drift}};

void write_summary(const std::vector<Run>& runs, const std::string& path) {
  std::ofstream os(path);
  os << "kind,amplitude,metric,runs,median,p90,max,max_over_amplitude,worst_shape\n";
  for (PerturbationKind kind : {PerturbationKind::Uniform, PerturbationKind::OneSided})
    for (double a : kAmplitudes)
      for (const Metric& m : kMetrics) {
        std::vector<double> v;
        double worst = -1;
        std::string worst_shape;
        for (const Run& r : runs)
          if (r.kind == kind && r.amplitude == a && r.error.empty() && std::isfinite(r.*m.field)) {
            v.push_back(r.*m.field);
            if (r.*m.field > worst) worst = r.*m.field, worst_shape = r.shape;
          }
        if (v.empty()) continue;
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s,%g,%s,%zu,%.4g,%.4g,%.4g,%.3g,%s\n", to_string(kind), a, m.name, v.size(),
                      quantile(v, 0.5), quantile(v, 0.9), worst, worst / a, worst_shape.c_str());
        os << buf;
      }
}

void write_plot(const std::vector<Run>& runs, double Run::*field, const std::string& what, const std::string& path) {
  plot::Plot p;
  p.title = what + " under boundary perturbation (over shapes and seeds)";
  p.x_label = "perturbation amplitude / diameter";
  p.y_label = what + " / diameter";
  p.log_x = p.log_y = true;
  for (PerturbationKind kind : {PerturbationKind::Uniform, PerturbationKind::OneSided})
    for (double q : {0.5, 1.0}) {
      plot::Series s;
      s.name = std::string(to_string(kind)) + (q == 1.0 ? ", max" : ", median");
      s.colour = plot::series_colour(kind == PerturbationKind::Uniform ? 0 : 1);
      if (q == 1.0) s.dash = "6,4";
      for (double a : kAmplitudes) {
        std::vector<double> v;
        for (const Run& r : runs)
          if (r.kind == kind && r.amplitude == a && r.error.empty()) v.push_back(r.*field);
        s.x.push_back(a);
        s.y.push_back(quantile(v, q));
      }
      p.series.push_back(s);
    }
  p.slopes.push_back({1, kAmplitudes[0], kAmplitudes[0], "drift = amplitude (dotted)"});
  plot::save(p, path);
}

std::vector<std::string> shape_args(const std::string& dir) {
  std::vector<std::string> keys;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".json" && e.path().stem().string().rfind("key-", 0) == 0) keys.push_back(e.path().string());
  std::sort(keys.begin(), keys.end(), [](const std::string& a, const std::string& b) {
    return std::make_pair(a.size(), a) < std::make_pair(b.size(), b);
  });
  for (const char* n : kOthers) keys.push_back(dir + "/" + n + ".json");
  return keys;
}

constexpr const char* kUsage =
    "usage: study_stability SHAPES_DIR [OUT] [--quick] [--shard I/N] [--progress|--quiet]\nhow far the EMA, the EDF and the PR maximum move when the boundary is perturbed (3.4, Fig. 3.5; 5.1.3, Fig. 5.3).\n(CSV columns and details: the header of experiments/study_stability.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{"--quick"}, {}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string dir = cmd.positional[0], out = cmd.positional_or(1, ".");
  const bool quick = cmd.flag("--quick");
  std::vector<std::string> inputs = {"square"};  // "square": the unit square, else a shape file
  std::vector<std::string> args = shape_args(dir);
  if (quick) args.resize(std::min<std::size_t>(args.size(), 3));
  inputs.insert(inputs.end(), args.begin(), args.end());
  inputs = experiments::shard_of(inputs, shard);
  std::vector<Original> originals;
  try {
    for (const std::string& a : inputs) {
      originals.emplace_back();
      Original& o = originals.back();
      o.name = a == "square" ? a : std::filesystem::path(a).stem().string();
      o.shape = a == "square" ? unit_square() : load_shape(a);
      o.diameter = shape_diameter(o.shape);
      o.axis = exact_axis(o.shape);
      o.pr_maximum = pr_maximum(*o.axis.graph);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_stability: %s\n", e.what());
    return 1;
  }
  const std::uint64_t seeds = quick ? 1 : 2;
  std::vector<Run> runs;
  Progress progress("study_stability " + shard.label(), originals.size());
  for (const Original& o : originals) {
    progress.item(o.name);
    for (PerturbationKind kind : {PerturbationKind::Uniform, PerturbationKind::OneSided})
      for (double a : kAmplitudes)
        for (std::uint64_t seed = 1; seed <= seeds; ++seed) runs.push_back(perturb_and_compare(o, kind, a, seed));
    progress.advance();
  }
  progress.done();
  std::vector<std::string> lines;
  std::size_t failures = 0;
  for (const Run& r : runs) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%s,%s,%g,%llu,%d,%zu,%zu,%.5g,%.5g,%.5g,%.5g,%.5g,", r.shape.c_str(),
                  to_string(r.kind), r.amplitude, static_cast<unsigned long long>(r.seed), r.attempts, r.vertices,
                  r.nodes, r.ema_drift, r.edf_change, r.edf_p95, r.edf_mean, r.pr_drift);
    std::string err = r.error;
    std::replace(err.begin(), err.end(), ',', ';');
    std::replace(err.begin(), err.end(), '\n', ' ');
    lines.push_back(buf + err);
    failures += !r.error.empty();
  }
  experiments::write_sorted_csv(out + "/stability.csv",
                                "shape,kind,amplitude,seed,attempts,vertices,nodes,ema_drift,edf_change,edf_p95,"
                                "edf_mean,pr_drift,error",
                                lines);
  if (experiments::rows_only(shard, out + "/stability.csv")) return 0;
  write_summary(runs, out + "/stability_summary.csv");
  write_plot(runs, &Run::ema_drift, "EMA drift", out + "/stability_ema.svg");
  write_plot(runs, &Run::edf_p95, "EDF change (95th percentile)", out + "/stability_edf.svg");
  write_plot(runs, &Run::pr_drift, "PR maximum drift", out + "/stability_pr.svg");
  note(std::to_string(runs.size()) + " runs, " + std::to_string(failures) + " failed (see the error column)");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_stability", kUsage, run);
}
