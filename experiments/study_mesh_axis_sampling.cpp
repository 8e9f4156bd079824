// study_mesh_axis_sampling -- the mesh axis (complex3/builders/mesh_axis.h) against the
// sampling density: how far it is from the true axis, and whether its topology is the
// solid's (issue 10, item 7).
//
// For each closed mesh of MESH_DIR (*.off, sorted by name) and each density
// s = samples per mean edge length (1, 2, 4, 8; spacing h = mean edge / s before the
// thickness rule refines thin parts further): the mesh axis with the default options
// otherwise, its Betti numbers against the solid's, and its distance to a reference axis
// (complex3/complex_distance.h, evaluated every D / 400, D the bounding diagonal):
//  - a convex mesh (convex_polyhedron_from_mesh accepts it): the exact convex axis
//    (convex_polyhedron_axis.h), the true medial axis;
//  - any other mesh: the mesh axis at the finest density that ran (s = 8, or less when the
//    sample limit stops it), so its own row reads 0.
// Columns: extra = directed distance axis -> reference (parts that should not be there),
// missing = reference -> axis (parts of the true axis not found; the separation test
// prunes sheets whose two touching samples are closer than lambda h = 2 h, so a band of
// width about 2 h / sin(dihedral) along the convex edges is missing by design),
// missing_core = the same from the points of the reference with R >= lambda h_axis = 2 h_axis
// only (convex meshes; empty otherwise), h_axis the coarsest spacing of the axis' round
// (the thickness rule refines below h); hausdorff = max(extra, missing), also / h_axis.
// A mesh refused as open or non-manifold gets one row with its status.
// Output: OUT/mesh_axis_sampling.csv, OUT/mesh_axis_sampling.svg (Hausdorff / D against h / D,
// log-log, one series per mesh). CPU seconds per axis in the CSV.
// Usage: study_mesh_axis_sampling MESH_DIR [OUT] [--quick] [--max-samples N]
//   MESH_DIR e.g. /work/shared/data/meshes; --quick runs s = 1, 2 only; N (default
//   300000) caps the samples of one axis (rows above it read `over-limit`).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "complex3/builders/convex_polyhedron_axis.h"
#include "complex3/builders/mesh_axis.h"
#include "complex3/complex_distance.h"
#include "complex3/mesh_perturbation.h"
#include "io/cpu_clock.h"
#include "io/mesh_io.h"
#include "io/progress.h"
#include "plot_svg.h"

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

}  // namespace

int main(int argc, char** argv) {
  take_verbosity_flags(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: study_mesh_axis_sampling MESH_DIR [OUT] [--quick] [--max-samples N]\n");
    return 2;
  }
  std::string out = "experiments/results";
  bool quick = false;
  std::size_t max_samples = 300000;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") quick = true;
    else if (a == "--max-samples" && i + 1 < argc) max_samples = std::stoul(argv[++i]);
    else out = a;
  }
  std::vector<std::string> paths;
  for (const auto& e : std::filesystem::directory_iterator(argv[1]))
    if (e.path().extension() == ".off") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  if (paths.empty()) {
    std::fprintf(stderr, "study_mesh_axis_sampling: no .off mesh in %s\n", argv[1]);
    return 2;
  }
  std::filesystem::create_directories(out);
  const std::vector<double> densities = quick ? std::vector<double>{1, 2} : std::vector<double>{1, 2, 4, 8};
  std::ofstream csv(out + "/mesh_axis_sampling.csv");
  csv << "mesh,convex,samples_per_edge,h,h_over_D,h_axis,samples,refinements,axis_round,betti_solid,betti_axis,topology_kept,"
         "axis_vertices,reference,extra,missing,missing_core,hausdorff,hausdorff_over_D,hausdorff_over_h,missing_core_over_h,"
         "status,seconds\n";
  plot::Plot p;
  p.title = "mesh axis against sampling: Hausdorff distance to the reference axis";
  p.x_label = "h / D (spacing / bounding diagonal)";
  p.y_label = "Hausdorff / D";
  p.log_x = p.log_y = true;
  Progress progress("study_mesh_axis_sampling", paths.size());
  for (const std::string& path : paths) {
    const std::string name = std::filesystem::path(path).stem().string();
    progress.item(name);
    TriangleMesh3 mesh;
    try {
      mesh = read_triangle_mesh(path);
    } catch (const std::exception& e) {
      csv << name << ",,,,,,,,,,,,,,,,,,,,,\"" << e.what() << "\",\n";
      continue;
    }
    const double diagonal = mesh_bounding_diagonal(mesh), step = diagonal / 400;
    const std::optional<RawComplex> convex = convex_reference(mesh);
    std::vector<Row> rows;
    for (double s : densities) {
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
      note(name + " s=" + std::to_string(s) + ": " + r.status + " " + std::to_string(r.seconds) + " s");
      const bool refused = r.status.rfind("refused", 0) == 0;
      rows.push_back(std::move(r));
      if (refused || !rows.back().axis) break;  // denser would not run either
    }
    const Row* finest = nullptr;
    for (const Row& r : rows)
      if (r.axis) finest = &r;
    plot::Series series;
    series.name = name + (convex ? " (exact convex axis)" : " (finest axis)");
    for (const Row& r : rows) {
      char line[1024];
      if (!r.axis) {
        std::string status = r.status;
        std::replace(status.begin(), status.end(), ',', ';');
        std::snprintf(line, sizeof line, "%s,%d,%g,%.6g,%.6g,,,,,,,,,,,,,,,,,\"%s\",%.3f\n", name.c_str(), convex ? 1 : 0, r.density, r.h,
                      r.h / diagonal, status.c_str(), r.seconds);
        csv << line;
        continue;
      }
      const MeshAxis& a = *r.axis;
      const RawComplex& reference = convex ? *convex : finest->axis->complex;
      const double extra = directed_complex_distance(a.complex, reference, step);
      const double missing = directed_complex_distance(reference, a.complex, step);
      const double h_axis = a.rounds[a.axis_round].max_spacing;
      const double core = convex ? directed_complex_distance(reference, radii(reference), 2 * h_axis, a.complex, step) : NAN;
      const double d = std::max(extra, missing);
      std::snprintf(line, sizeof line,
                    "%s,%d,%g,%.6g,%.6g,%.6g,%zu,%d,%zu,%s,%s,%d,%zu,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.4g,%.4g,%s,%.3f\n", name.c_str(),
                    convex ? 1 : 0, r.density, r.h, r.h / diagonal, h_axis, a.samples.lattice.size(), a.refinements(), a.axis_round,
                    betti_field(a.solid.betti).c_str(), betti_field(a.axis_betti).c_str(), a.axis_betti == a.solid.betti ? 1 : 0,
                    a.complex.vertices.size(), convex ? "exact-convex" : "finest", extra, missing, core, d, d / diagonal,
                    d / h_axis, core / h_axis, r.status.c_str(), r.seconds);
      csv << line;
      if (convex || &r != finest) {
        series.x.push_back(r.h / diagonal);
        series.y.push_back(d / diagonal);
      }
    }
    if (!series.x.empty()) {
      series.colour = plot::series_colour(p.series.size());
      p.series.push_back(series);
    }
    progress.advance();
  }
  progress.done();
  p.slopes.push_back({1, 0.01, 0.02, "slope 1 (Hausdorff ~ h)"});
  plot::save(p, out + "/mesh_axis_sampling.svg");
  note("wrote " + out + "/mesh_axis_sampling.csv and mesh_axis_sampling.svg");
  return 0;
}
