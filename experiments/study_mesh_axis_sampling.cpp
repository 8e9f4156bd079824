// study_mesh_axis_sampling -- the mesh axis (medial3/mesh/mesh_axis.h) against the
// sampling density: how far it is from the true axis, and whether its topology is the
// solid's (docs/exactness.md).
//
// For each closed mesh of MESH_DIR (*.off, smallest first by vertex count, so that a
// long run has the small meshes done early) and each density s = samples per mean edge
// length (default 1, 2, 4; spacing h = mean edge / s before the thickness rule refines thin
// parts further): the mesh axis with the default options otherwise, its Betti numbers
// against the solid's (those of the first round, at spacing h before any refinement, and
// of the returned axis, which the builder guarantees or refuses), and its distance to a
// reference axis (complex3/complex_distance.h, evaluated every D / 200, D the bounding
// diagonal):
//  - a convex mesh (convex_polyhedron_from_mesh accepts it): the exact convex axis
//    (convex_polyhedron_axis.h), the true medial axis;
//  - any other mesh: the mesh axis at the finest density that ran (the last of the list,
//    or less when the sample limit stops it), so its own row reads 0.
// Columns: extra = directed distance axis -> reference (parts that should not be there),
// missing = reference -> axis (parts of the true axis not found; the separation test
// prunes sheets whose two touching samples are closer than lambda h = 2 h, so a band of
// width about 2 h / sin(dihedral) along the convex edges is missing by design),
// missing_core = the same from the points of the reference with R >= lambda h_axis = 2 h_axis
// only (convex meshes; empty otherwise), h_axis the coarsest spacing of the axis' round
// (the thickness rule refines below h); hausdorff = max(extra, missing), also / h_axis.
// A mesh refused as open or non-manifold gets one row with its status.
// Output: OUT/mesh_axis_sampling.csv, OUT/mesh_axis_sampling.svg (mesh_axis_sampling_plot.h:
// Hausdorff / D against h_axis / D, h_axis rather than h because the refinement rules
// decide the spacing the axis is built at whatever s starts from; and the Betti number
// error of the first round against h / D). CPU seconds per axis and for its distances in
// the CSV.
// Usage: study_mesh_axis_sampling MESH_DIR [OUT] [--quick] [--densities S1,S2,...]
//                                  [--max-samples N] [--progress|--quiet]
//   MESH_DIR e.g. /work/shared/data/meshes; --quick runs s = 1, 2 only; N (default
//   200000) caps the samples of one axis (rows above it read `over-limit`). One note per
//   axis on stderr (mesh, density, samples, seconds of the axis and of the distances).
// Cost (2 cores, loaded): the 14 shared meshes at s = 1, 2, 4 in about N minutes.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "medial3/mesh/mesh_axis.h"
#include "complex3/complex_distance.h"
#include "geometry3/mesh_perturbation.h"
#include "support/cpu_clock.h"
#include "io/mesh_io.h"
#include "support/progress.h"
#include "mesh_axis_sampling_plot.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {

struct Row {
  double density = 0, h = 0;
  std::string status = "ok";
  std::optional<MeshAxis> axis;
  double seconds = 0;
};

std::string betti_field(const BettiNumbers& b) { return std::to_string(b.b0) + ":" + std::to_string(b.b1) + ":" + std::to_string(b.b2); }

// The exact convex axis of a convex mesh, or nothing.
std::optional<RawComplex> convex_reference(const TriangleMesh3& mesh) {
  try {
    return convex_polyhedron_axis(convex_polyhedron_from_mesh(mesh)).complex;
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // not convex
  }
}

std::vector<double> radii(const RawComplex& c) {
  std::vector<double> r;
  for (const mpq_class& r2 : c.radius_squared) r.push_back(std::sqrt(r2.get_d()));
  return r;
}

// The mesh axis at s samples per mean edge, or the reason there is none.
Row axis_at(const TriangleMesh3& mesh, double s, std::size_t max_samples) {
  Row r;
  r.density = s;
  r.h = mean_edge_length(mesh) / s;
  MeshAxisOptions options;
  options.samples_per_edge = s;
  options.max_samples = max_samples;
  const double t = cpu_seconds();
  try {
    r.axis = mesh_medial_axis(mesh, options);
    if (r.axis->rounds.back().samples > max_samples) r.status = "thickness-rule-capped";
  } catch (const MeshAxisTopologyError& e) {
    r.status = std::string(e.what()).find("exceed") != std::string::npos ? "over-limit" : "topology-not-reached";
  } catch (const std::exception& e) {
    r.status = std::string("refused: ") + e.what();
  }
  r.seconds = cpu_seconds() - t;
  return r;
}

std::string caption(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// "1,2,4" -> {1, 2, 4}.
std::vector<double> parse_densities(const std::string& list) {
  std::vector<double> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    out.push_back(std::stod(list.substr(start, comma - start)));
    start = comma + 1;
  }
  return out;
}

struct Input {
  std::string name, path, error;
  TriangleMesh3 mesh;
};

// The meshes of the folder, smallest first (vertex count, then name); unreadable ones last.
std::vector<Input> read_inputs(const std::string& dir) {
  std::vector<Input> inputs;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".off") {
      Input in;
      in.name = e.path().stem().string();
      in.path = e.path().string();
      try {
        in.mesh = read_triangle_mesh(in.path);
      } catch (const std::exception& ex) {
        in.error = ex.what();
      }
      inputs.push_back(std::move(in));
    }
  std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) {
    const std::size_t na = a.error.empty() ? a.mesh.vertices.size() : SIZE_MAX, nb = b.error.empty() ? b.mesh.vertices.size() : SIZE_MAX;
    return na != nb ? na < nb : a.name < b.name;
  });
  return inputs;
}

constexpr const char* kUsage =
    "usage: study_mesh_axis_sampling MESH_DIR [OUT] [--quick] [--densities S1,S2,...] [--max-samples N]\nthe mesh axis (medial3/mesh/mesh_axis.h) against the sampling density: how far it is from the true axis, and whether its topology is the solid's (docs/exactness.md).\n(CSV columns and details: the header of experiments/study_mesh_axis_sampling.cpp)\n";

int run(int argc, char** argv) {
  experiments::RunOptionSpec spec{{"--quick"}, {"--densities", "--max-samples"}, 1, 2};
  spec.shard = false;
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, spec);
  const std::string out = cmd.positional_or(1, "experiments/results");
  std::vector<double> densities{1, 2, 4};
  if (cmd.flag("--quick")) densities = {1, 2};
  if (const auto d = cmd.value("--densities")) densities = parse_densities(*d);
  const std::size_t max_samples = cmd.count("--max-samples", 200000);
  const std::vector<Input> inputs = read_inputs(cmd.positional[0]);
  if (inputs.empty()) {
    std::fprintf(stderr, "study_mesh_axis_sampling: no .off mesh in %s\n", cmd.positional[0].c_str());
    return 2;
  }
  std::filesystem::create_directories(out);
  std::ofstream csv(out + "/mesh_axis_sampling.csv");
  csv << "mesh,convex,samples_per_edge,h,h_over_D,h_axis,samples,refinements,axis_round,betti_solid,betti_first_round,"
         "betti_axis,topology_first_round,topology_kept,axis_vertices,reference,extra,missing,missing_core,hausdorff,"
         "hausdorff_over_D,hausdorff_over_h,missing_core_over_h,status,seconds,distance_seconds\n";
  std::vector<sampling_plot::Point> points;
  Progress progress("study_mesh_axis_sampling", inputs.size());
  for (const Input& in : inputs) {
    const std::string& name = in.name;
    progress.item(name);
    if (!in.error.empty()) {
      std::string error = in.error;
      std::replace(error.begin(), error.end(), ',', ';');
      csv << name << ",,,,,,,,,,,,,,,,,,,,,,,\"" << error << "\",,\n";
      continue;
    }
    const TriangleMesh3& mesh = in.mesh;
    const double diagonal = mesh_bounding_diagonal(mesh), step = diagonal / 200;
    const std::optional<RawComplex> convex = convex_reference(mesh);
    std::vector<Row> rows;
    for (double s : densities) {
      rows.push_back(axis_at(mesh, s, max_samples));
      const Row& r = rows.back();
      note(name + " s=" + caption(s) + ": " + r.status + (r.axis ? ", " + std::to_string(r.axis->samples.lattice.size()) + " samples" : "") +
           ", " + caption(r.seconds) + " s");
      if (!r.axis) break;  // denser would not run either
    }
    const Row* finest = nullptr;
    for (const Row& r : rows)
      if (r.axis) finest = &r;
    for (const Row& r : rows) {
      char line[1024];
      if (!r.axis) {
        std::string status = r.status;
        std::replace(status.begin(), status.end(), ',', ';');
        std::snprintf(line, sizeof line, "%s,%d,%g,%.6g,%.6g,,,,,,,,,,,,,,,,,,,\"%s\",%.3f,\n", name.c_str(), convex ? 1 : 0,
                      r.density, r.h, r.h / diagonal, status.c_str(), r.seconds);
        csv << line;
        continue;
      }
      const MeshAxis& a = *r.axis;
      const double t = cpu_seconds();
      const RawComplex& reference = convex ? *convex : finest->axis->complex;
      const bool self = &r == finest && !convex;  // its own reference: 0 by definition
      const double extra = self ? 0 : directed_complex_distance(a.complex, reference, step);
      const double missing = self ? 0 : directed_complex_distance(reference, a.complex, step);
      const double h_axis = a.rounds[a.axis_round].max_spacing;
      const double core = convex ? directed_complex_distance(reference, radii(reference), 2 * h_axis, a.complex, step) : NAN;
      const double d = std::max(extra, missing), distance_seconds = cpu_seconds() - t;
      const BettiNumbers& first = a.rounds.front().betti;
      std::snprintf(line, sizeof line,
                    "%s,%d,%g,%.6g,%.6g,%.6g,%zu,%d,%zu,%s,%s,%s,%d,%d,%zu,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%.4g,%s,%.3f,%.3f\n",
                    name.c_str(), convex ? 1 : 0, r.density, r.h, r.h / diagonal, h_axis, a.samples.lattice.size(),
                    a.refinements(), a.axis_round, betti_field(a.solid.betti).c_str(), betti_field(first).c_str(),
                    betti_field(a.axis_betti).c_str(), first == a.solid.betti ? 1 : 0, a.axis_betti == a.solid.betti ? 1 : 0,
                    a.complex.vertices.size(), convex ? "exact-convex" : "finest", extra, missing, core, d, d / diagonal,
                    d / h_axis, core / h_axis, r.status.c_str(), r.seconds, distance_seconds);
      csv << line;
      note(name + " s=" + caption(r.density) + ": Hausdorff " + caption(d) + " (D " + caption(diagonal) + "), distances " +
           caption(distance_seconds) + " s");
      sampling_plot::Point point;
      point.mesh = name;
      point.convex = convex.has_value();
      point.reference = self;
      point.h_over_d = r.h / diagonal;
      point.h_axis_over_d = h_axis / diagonal;
      point.hausdorff_over_d = d / diagonal;
      point.core_over_d = core / diagonal;
      point.first_round_betti_error = sampling_plot::betti_error(betti_field(first), betti_field(a.solid.betti));
      points.push_back(point);
    }
    csv.flush();
    sampling_plot::save(points, out + "/mesh_axis_sampling.svg");  // after every mesh: a cut-short run has both files
    progress.advance();
  }
  progress.done();
  note("wrote " + out + "/mesh_axis_sampling.csv and mesh_axis_sampling.svg");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_mesh_axis_sampling", kUsage, run);
}
