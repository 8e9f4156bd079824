// study_curve_stability -- how far the medial curves move when a mesh's surface is
// perturbed, and whether their topology is kept (5.1.3 for the lower-dimensional forms).
//
// For each mesh, amplitude a (a fraction of the bounding diagonal D) and seed: the mesh
// with every vertex moved along its normal by a D u, u uniform in [-1, 1]
// (geometry3/mesh_perturbation.h; Hausdorff distance <= a D), its medial axis by the builder
// `grassfire medial3d` uses for closed meshes (medial3/mesh/mesh_axis.h, default
// options: the solid's Betti numbers checked, thin parts refined), the discrete burning at h = D / 100, and the medial curves (curves3/medial_curves.h)
// with two significance settings: all path ends ("raw", min_et_fraction 0) and those whose
// ET reaches a tenth of the axis' largest ("significant", 0.1). Compared with the
// unperturbed mesh's curves (same settings):
//   hausdorff = the Hausdorff distance between the curve graphs (curves3/curve_distance.h,
//               sampled every h / 2), and ratio = hausdorff / (a D); its two directions:
//               extra = from the perturbed curves to the original (new branches, hair),
//               missing = from the original to the perturbed (branches lost or moved);
//   topology  = whether the curves' (b0, b1) equal the unperturbed ones (they always equal
//               their own axis', which has the solid's);
//   length    = total curve length, against the unperturbed;
//   axis_hausdorff = the same distance between the two medial axes (the vertices of their
//               refinements, spacing about h): how far the axis itself moved, the control.
// A perturbed mesh whose axis is refused (a self-intersecting mesh, or the Betti numbers not
// reached) gives a row with status "axis failed"; nothing is dropped.
// Output: OUT/curve_stability.csv (one row per run and setting),
// OUT/curve_stability_summary.csv (per mesh, setting and amplitude: median and max ratio,
// runs that kept the topology), OUT/curve_stability.svg (median ratio against a, log-log,
// per mesh and setting). The meshes are read from MESH_DIR (the shared dataset's
// meshes/); tests do not run this.
// Usage: study_curve_stability MESH_DIR [OUT] [--quick] [--seeds K] [--max-samples N]
//                              [--shard I/N] [--progress|--quiet]
// (--seeds: seeds per amplitude, default 3; --max-samples: the mesh axis' sample limit,
// default 200000: a perturbed surface whose axis would need more, e.g. a rough pipe whose
// thickness rounds went on to 2 million samples, is an "axis failed" row, not an hour;
// one note per run on stderr)
// (--shard splits the meshes, experiments/shard.h: a shard writes its rows only).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "curves3/curve_distance.h"
#include "burn3/discrete/discrete_burning_field.h"
#include "curves3/medial_curves.h"
#include "medial3/mesh/mesh_axis.h"
#include "geometry3/mesh_perturbation.h"
#include "io/mesh_io.h"
#include "support/progress.h"
#include "plot_svg.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {


struct Curves {
  bool ok = false;
  std::string status;
  MedialCurves raw, significant;
  MedialCurves axis_points;  // the refinement's vertices as a graph without edges
  BettiNumbers axis;
};

Curves analyse(const TriangleMesh3& mesh, double h, std::size_t max_samples) {
  Curves c;
  try {
    MeshAxisOptions options;
    options.max_samples = max_samples;
    const MedialComplex mc(mesh_medial_axis(mesh, options).complex);
    mc.validate();
    const DiscreteBurning d = burn_discrete(mc, {h});
    const DiscreteBurningField field(mc, d);
    const AxisRefinement k = AxisRefinement::build(field);
    MedialCurveOptions o;
    c.raw = medial_curves(k, field, o);
    o.min_et_fraction = 0.1;
    c.significant = medial_curves(k, field, o);
    c.raw.validate(mc);
    c.significant.validate(mc);
    c.axis = c.raw.axis_betti;
    for (const RefinedVertex& v : k.vertices) c.axis_points.nodes.push_back({v.position});
    c.ok = true;
    c.status = "ok";
  } catch (const std::exception& e) {
    c.status = std::string("axis failed: ") + e.what();
    for (char& ch : c.status)
      if (ch == ',' || ch == '\n') ch = ';';
  }
  return c;
}

constexpr const char* kUsage =
    "usage: study_curve_stability MESH_DIR [OUT] [--quick] [--seeds K] [--max-samples N] [--shard I/N] [--progress|--quiet]\nhow far the medial curves move when a mesh's surface is perturbed, and whether their topology is kept (5.1.3 for the lower-dimensional forms).\n(CSV columns and details: the header of experiments/study_curve_stability.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd =
      experiments::parse_run_options(argc, argv, {{"--quick"}, {"--seeds", "--max-samples"}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string dir = cmd.positional[0], out = cmd.positional_or(1, "experiments/results");
  const bool quick = cmd.flag("--quick");
  const int seeds_wanted = static_cast<int>(cmd.count("--seeds", 3));
  const std::size_t max_samples = cmd.count("--max-samples", 200000);
  std::filesystem::create_directories(out);
  const std::vector<std::string> meshes = experiments::shard_of(
      quick ? std::vector<std::string>{"tripod", "pipe"} : std::vector<std::string>{"tripod", "cross", "pipe", "joint"}, shard);
  const std::vector<double> amplitudes = quick ? std::vector<double>{0.0025, 0.01, 0.04}
                                               : std::vector<double>{0.00125, 0.0025, 0.005, 0.01, 0.02, 0.04};
  const int seeds = quick ? 1 : seeds_wanted;
  const std::string header =
      "mesh,setting,amplitude_fraction,amplitude,seed,status,hausdorff,ratio,extra,missing,b0,b1,b0_original,b1_original,"
      "topology_kept,axis_b0,axis_b1,axis_b2,length,length_original,nodes,axis_hausdorff,seconds";
  std::vector<std::string> rows;  // without their newline, written sorted (experiments/shard.h)
  Progress progress("study_curve_stability " + shard.label(), meshes.size() * amplitudes.size() * seeds);
  // (mesh, setting, amplitude) -> ratios, and kept counts.
  std::map<std::tuple<std::string, std::string, double>, std::vector<double>> ratios;
  std::map<std::tuple<std::string, std::string, double>, std::pair<int, int>> kept;
  std::map<std::tuple<std::string, std::string, double>, std::vector<double>> axis_ratios;
  for (const std::string& name : meshes) {
    const TriangleMesh3 mesh = read_triangle_mesh(dir + "/" + name + ".off");
    const double diagonal = mesh_bounding_diagonal(mesh), h = diagonal / 100;
    const Curves base = analyse(mesh, h, max_samples);
    progress.item(name);
    note(name + ": " + base.status + "; curves " + std::to_string(base.raw.nodes.size()) + " / " +
         std::to_string(base.significant.nodes.size()) + " nodes, betti [" + std::to_string(base.raw.curve_betti.b0) +
         ", " + std::to_string(base.raw.curve_betti.b1) + "]");
    if (!base.ok) continue;
    for (double a : amplitudes)
      for (int seed = 1; seed <= seeds; ++seed) {
        const auto start = std::chrono::steady_clock::now();
        const Curves run = analyse(perturb_mesh(mesh, a * diagonal, static_cast<std::uint64_t>(seed)), h, max_samples);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        note(name + " a=" + std::to_string(a) + " seed " + std::to_string(seed) + ": " + run.status + ", " +
             std::to_string(seconds) + " s");
        for (const char* setting : {"raw", "significant"}) {
          const bool raw = std::string(setting) == "raw";
          const MedialCurves& b0 = raw ? base.raw : base.significant;
          char line[512];
          if (!run.ok) {
            std::snprintf(line, sizeof line, "%s,%s,%g,%.6g,%d,%s,,,,,,,%ld,%ld,,,,,,%.6g,,,%.3f", name.c_str(), setting, a,
                          a * diagonal, seed, run.status.c_str(), b0.curve_betti.b0, b0.curve_betti.b1, b0.total_length(),
                          seconds);
            rows.push_back(line);
            continue;
          }
          const MedialCurves& c = raw ? run.raw : run.significant;
          const double extra = directed_curve_distance(c, b0, h / 2), missing = directed_curve_distance(b0, c, h / 2);
          const double d = std::max(extra, missing), ratio = d / (a * diagonal);
          const bool same = c.curve_betti.b0 == b0.curve_betti.b0 && c.curve_betti.b1 == b0.curve_betti.b1;
          const double axis_d = curve_hausdorff(base.axis_points, run.axis_points, h);
          std::snprintf(line, sizeof line, "%s,%s,%g,%.6g,%d,ok,%.6g,%.4g,%.6g,%.6g,%ld,%ld,%ld,%ld,%d,%ld,%ld,%ld,%.6g,%.6g,%zu,%.6g,%.3f",
                        name.c_str(), setting, a, a * diagonal, seed, d, ratio, extra, missing, c.curve_betti.b0, c.curve_betti.b1,
                        b0.curve_betti.b0, b0.curve_betti.b1, same ? 1 : 0, run.axis.b0, run.axis.b1, run.axis.b2,
                        c.total_length(), b0.total_length(), c.nodes.size(), axis_d, seconds);
          rows.push_back(line);
          ratios[{name, setting, a}].push_back(ratio);
          axis_ratios[{name, setting, a}].push_back(axis_d / (a * diagonal));
          auto& k = kept[{name, setting, a}];
          k.first += same ? 1 : 0;
          ++k.second;
        }
        progress.advance();
      }
  }
  progress.done();
  experiments::write_sorted_csv(out + "/curve_stability.csv", header, rows);
  if (experiments::rows_only(shard, out + "/curve_stability.csv")) return 0;
  std::ofstream summary(out + "/curve_stability_summary.csv");
  summary << "mesh,setting,amplitude_fraction,runs,median_ratio,max_ratio,median_axis_ratio,topology_kept\n";
  std::map<std::pair<std::string, std::string>, plot::Series> series;
  for (const auto& [key, r] : ratios) {
    const auto& [mesh, setting, a] = key;
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%g,%zu,%.4g,%.4g,%.4g,%d/%d\n", mesh.c_str(), setting.c_str(), a, r.size(),
                  plot::median(r), *std::max_element(r.begin(), r.end()), plot::median(axis_ratios[key]), kept[key].first,
                  kept[key].second);
    summary << line;
    plot::Series& s = series[{mesh, setting}];
    s.name = mesh + " (" + setting + ")";
    s.x.push_back(a);
    s.y.push_back(plot::median(r));
    s.dash = setting == "raw" ? "5,3" : "";
  }
  plot::Plot p;
  p.title = "medial curves under surface perturbation: Hausdorff distance / amplitude (median over seeds)";
  p.x_label = "amplitude / bounding diagonal";
  p.y_label = "Hausdorff(curves) / amplitude";
  p.log_x = p.log_y = true;
  std::size_t i = 0;
  std::map<std::string, Rgb> colour;
  for (auto& [key, s] : series) {
    if (!colour.count(key.first)) colour[key.first] = plot::series_colour(i++);
    s.colour = colour[key.first];
    p.series.push_back(s);
  }
  plot::save(p, out + "/curve_stability.svg");
  note("wrote " + out + "/curve_stability.csv, curve_stability_summary.csv, curve_stability.svg");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_curve_stability", kUsage, run);
}
