// study_pruning_stability -- how far the 3D medial axis moves when a mesh's surface is
// perturbed: the raw axis, the angle-pruned axis and the axis pruned by erosion thickness
// (3.4.1 with the burning time of ch. 4: the 3D form of the stability of 3.5.3), and
// whether each keeps its topology.
//
// For each mesh, amplitude a (a fraction of the bounding diagonal D) and seed: the mesh
// with every vertex moved along its normal by a D u, u uniform in [-1, 1]
// (geometry3/mesh_perturbation.h; Hausdorff distance <= a D). For it and for the
// unperturbed mesh, three axes:
//   raw    = the mesh axis builder's axis (medial3/mesh/mesh_axis.h, default options: the
//            solid's Betti numbers checked, thin parts refined; `grassfire medial3d`);
//   angle  = the same builder with the angle test at THETA degrees (`medial3d --angle`);
//   et T   = the raw axis pruned at ET >= T times the axis' largest R, T = 0.05 and 0.2,
//            on the discrete burning at h = D / 100 (pipeline/prune3d.h, what
//            `grassfire prune3d AXIS --et T --relative --method discrete --spacing h` does;
//            the exact engine refuses the singular edges of mesh axes).
// Compared with the same setting on the unperturbed mesh:
//   hausdorff = the Hausdorff distance between the two axes, each sampled on its triangles
//               and segments every D / 400 (curves3/curve_distance.h on the samples; the
//               sampling under-estimates by at most about D / 400), ratio = hausdorff / (a D);
//               extra = from the perturbed axis to the original (new sheets, spikes),
//               missing = from the original to the perturbed (parts lost);
//   topology  = whether the axis' Betti numbers equal the unperturbed raw axis' (which are
//               the solid's: the builder checks them);
//   area      = the axis' total triangle area, against the unperturbed.
// A perturbed mesh whose axis is refused (self-intersecting after the perturbation, or the
// Betti numbers not reached within the sample limit) gives a row with status "axis failed".
// Output: OUT/pruning_stability.csv (one row per run and setting),
// OUT/pruning_stability_summary.csv (per mesh, setting and amplitude: median and max ratio,
// runs that kept the topology), OUT/pruning_stability.svg (median ratio against a, log-log).
// The meshes are read from MESH_DIR (the shared dataset's meshes/); tests do not run this.
// Usage: study_pruning_stability MESH_DIR [OUT] [--meshes a,b,c] [--seeds K] [--angle THETA]
//                                [--max-samples N] [--shard I/N] [--progress|--quiet]
// (--shard splits the meshes, experiments/shard.h: a shard writes its rows only;
// defaults: tripod,cross,pipe; 3 seeds; THETA 90: at 20-60 the angle test removes nothing the
// builder's separation test has not removed already, on tripod 750 triangles at 0, 20, 40, 60, 397 at 90; 200000 samples per axis).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "complex3/medial_complex.h"
#include "complex3/simplicial_homology.h"
#include "curves3/curve_distance.h"
#include "geometry3/mesh_perturbation.h"
#include "io/complex_json.h"
#include "io/mesh_io.h"
#include "medial3/mesh/mesh_axis.h"
#include "pipeline/prune3d.h"
#include "support/progress.h"
#include "cli.h"
#include "plot_svg.h"
#include "run_options.h"
#include "shard.h"

using namespace grassfire;
using namespace grassfire::v3;

namespace {

const std::vector<double> kEtThresholds = {0.05, 0.2};

// One axis as sample points (a MedialCurves without edges: curve_distance.h's point sets).
struct SampledAxis {
  MedialCurves points;
  BettiNumbers betti;
  double area = 0;
  std::size_t triangles = 0;
};

Vec3d add3(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return add(add(a, b), c); }

SampledAxis sample_axis(const RawComplex& raw, double step) {
  const MedialComplex mc(raw);
  mc.validate();
  SampledAxis s;
  s.betti = betti_numbers(raw);
  s.triangles = raw.triangles.size();
  auto keep = [&](const Vec3d& p) { s.points.nodes.push_back({p}); };
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) keep(mc.vertex(v).approx);
  for (const auto& t : raw.triangles) {
    const Vec3d a = mc.vertex(t[0]).approx, b = mc.vertex(t[1]).approx, c = mc.vertex(t[2]).approx;
    s.area += 0.5 * norm(cross(sub(b, a), sub(c, a)));
    const int n = std::max(1, static_cast<int>(std::ceil(std::max({dist(a, b), dist(a, c), dist(b, c)}) / step)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
        if (i + j != 0 && i != n && j != n) keep(add3(a, scale(sub(b, a), double(i) / n), scale(sub(c, a), double(j) / n)));
  }
  for (const auto& e : raw.segments) {
    const Vec3d a = mc.vertex(e[0]).approx, b = mc.vertex(e[1]).approx;
    const int n = static_cast<int>(std::ceil(dist(a, b) / step));
    for (int i = 1; i < n; ++i) keep(lerp(a, b, double(i) / n));
  }
  return s;
}

struct Axes {
  bool ok = false;
  std::string status;
  std::map<std::string, SampledAxis> settings;  // "raw", "angle", "et 0.05", "et 0.2"
};

std::string setting_name(double t) {
  std::ostringstream o;
  o << "et " << t;
  return o.str();
}

Axes analyse(const TriangleMesh3& mesh, double h, double theta, std::size_t max_samples, const std::string& tmp) {
  Axes axes;
  try {
    MeshAxisOptions options;
    options.max_samples = max_samples;
    const RawComplex raw = mesh_medial_axis(mesh, options).complex;
    options.angle_degrees = theta;
    const RawComplex angle = mesh_medial_axis(mesh, options).complex;
    const double step = h / 4;
    axes.settings["raw"] = sample_axis(raw, step);
    axes.settings["angle"] = sample_axis(angle, step);
    write_complex_json(raw, tmp);
    for (double t : kEtThresholds) {
      Prune3dSetup setup = default_prune3d_setup();
      setup.field.input = tmp;
      setup.field.method = "discrete";
      setup.field.spacing = h;
      setup.erosion = mpq_class(t);
      setup.relative = true;
      const Prune3dRun run = prune3d(setup);
      axes.settings[setting_name(t)] = sample_axis(run.pruned.complex, step);
    }
    axes.ok = true;
    axes.status = "ok";
  } catch (const std::exception& e) {
    axes.status = std::string("axis failed: ") + e.what();
    for (char& ch : axes.status)
      if (ch == ',' || ch == '\n') ch = ';';
  }
  return axes;
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

constexpr const char* kUsage =
    "usage: study_pruning_stability MESH_DIR [OUT] [--meshes a,b,c] [--seeds K] [--angle THETA] [--max-samples N] "
    "[--shard I/N] [--progress|--quiet]\nhow far the raw, angle-pruned and ET-pruned 3D medial axes move when a mesh's surface is "
    "perturbed, and whether their topology is kept.\n(CSV columns and details: the header of "
    "experiments/study_pruning_stability.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd =
      experiments::parse_run_options(argc, argv, {{}, {"--meshes", "--seeds", "--angle", "--max-samples"}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string dir = cmd.positional[0], out = cmd.positional_or(1, "experiments/results");
  const int seeds = static_cast<int>(cmd.count("--seeds", 3));
  const double theta = cmd.number("--angle", 90);
  const std::size_t max_samples = cmd.count("--max-samples", 200000);
  const std::vector<std::string> meshes =
      experiments::shard_of(split_commas(cmd.text("--meshes", "tripod,cross,pipe")), shard);
  std::filesystem::create_directories(out);
  const std::string tmp = out + "/.pruning_stability_axis_" + std::to_string(shard.index) + ".json";
  const std::vector<double> amplitudes = {0.0025, 0.01, 0.04};
  std::vector<std::string> settings = {"raw", "angle"};
  for (double t : kEtThresholds) settings.push_back(setting_name(t));
  const std::string header =
      "mesh,setting,amplitude_fraction,amplitude,seed,status,hausdorff,ratio,extra,missing,b0,b1,b2,"
      "b0_original,b1_original,b2_original,topology_kept,triangles,triangles_original,area,area_original,seconds";
  std::vector<std::string> rows;  // without their newline, written sorted (experiments/shard.h)
  Progress progress("study_pruning_stability " + shard.label(), meshes.size() * amplitudes.size() * seeds);
  std::map<std::tuple<std::string, std::string, double>, std::vector<double>> ratios;
  std::map<std::tuple<std::string, std::string, double>, std::pair<int, int>> kept;
  for (const std::string& name : meshes) {
    const TriangleMesh3 mesh = read_triangle_mesh(dir + "/" + name + ".off");
    const double diagonal = mesh_bounding_diagonal(mesh), h = diagonal / 100;
    const Axes base = analyse(mesh, h, theta, max_samples, tmp);
    progress.item(name);
    note(name + ": " + base.status);
    if (!base.ok) continue;
    const BettiNumbers solid = base.settings.at("raw").betti;
    for (double a : amplitudes)
      for (int seed = 1; seed <= seeds; ++seed) {
        const auto start = std::chrono::steady_clock::now();
        const Axes run = analyse(perturb_mesh(mesh, a * diagonal, static_cast<std::uint64_t>(seed)), h, theta,
                                 max_samples, tmp);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        note(name + " a=" + std::to_string(a) + " seed " + std::to_string(seed) + ": " + run.status + ", " +
             std::to_string(seconds) + " s");
        for (const std::string& setting : settings) {
          const SampledAxis& b = base.settings.at(setting);
          char line[1024];
          if (!run.ok) {
            std::snprintf(line, sizeof line, "%s,%s,%g,%.6g,%d,%s,,,,,,,,%ld,%ld,%ld,,,%zu,,%.6g,%.3f", name.c_str(),
                          setting.c_str(), a, a * diagonal, seed, run.status.c_str(), solid.b0, solid.b1, solid.b2,
                          b.triangles, b.area, seconds);
            rows.push_back(line);
            continue;
          }
          const SampledAxis& s = run.settings.at(setting);
          const double extra = directed_curve_distance(s.points, b.points, h / 4);
          const double missing = directed_curve_distance(b.points, s.points, h / 4);
          const double d = std::max(extra, missing), ratio = d / (a * diagonal);
          const bool same = s.betti.b0 == solid.b0 && s.betti.b1 == solid.b1 && s.betti.b2 == solid.b2;
          std::snprintf(line, sizeof line,
                        "%s,%s,%g,%.6g,%d,ok,%.6g,%.4g,%.6g,%.6g,%ld,%ld,%ld,%ld,%ld,%ld,%d,%zu,%zu,%.6g,%.6g,%.3f",
                        name.c_str(), setting.c_str(), a, a * diagonal, seed, d, ratio, extra, missing, s.betti.b0,
                        s.betti.b1, s.betti.b2, solid.b0, solid.b1, solid.b2, same ? 1 : 0, s.triangles, b.triangles,
                        s.area, b.area, seconds);
          rows.push_back(line);
          ratios[{name, setting, a}].push_back(ratio);
          auto& k = kept[{name, setting, a}];
          k.first += same ? 1 : 0;
          ++k.second;
        }
        progress.advance();
      }
  }
  progress.done();
  std::filesystem::remove(tmp);
  experiments::write_sorted_csv(out + "/pruning_stability.csv", header, rows);
  if (experiments::rows_only(shard, out + "/pruning_stability.csv")) return 0;
  std::ofstream summary(out + "/pruning_stability_summary.csv");
  summary << "mesh,setting,amplitude_fraction,runs,median_ratio,max_ratio,topology_kept\n";
  std::map<std::pair<std::string, std::string>, plot::Series> series;
  for (const auto& [key, r] : ratios) {
    const auto& [mesh, setting, a] = key;
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%g,%zu,%.4g,%.4g,%d/%d\n", mesh.c_str(), setting.c_str(), a, r.size(),
                  plot::median(r), *std::max_element(r.begin(), r.end()), kept[key].first, kept[key].second);
    summary << line;
    plot::Series& s = series[{mesh, setting}];
    s.name = mesh + " (" + setting + ")";
    s.x.push_back(a);
    s.y.push_back(plot::median(r));
    s.dash = setting == "raw" ? "6,3" : setting == "angle" ? "2,2" : setting == setting_name(kEtThresholds[0]) ? "" : "10,2,2,2";
  }
  plot::Plot p;
  p.title = "3D medial axes under surface perturbation: Hausdorff distance / amplitude (median over seeds)";
  p.x_label = "amplitude / bounding diagonal";
  p.y_label = "Hausdorff(axes) / amplitude";
  p.log_x = p.log_y = true;
  std::size_t i = 0;
  std::map<std::string, Rgb> colour;
  for (auto& [key, s] : series) {
    if (!colour.count(key.first)) colour[key.first] = plot::series_colour(i++);
    s.colour = colour[key.first];
    p.series.push_back(s);
  }
  plot::save(p, out + "/pruning_stability.svg");
  note("wrote " + out + "/pruning_stability.csv, pruning_stability_summary.csv, pruning_stability.svg");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_pruning_stability", kUsage, run);
}
