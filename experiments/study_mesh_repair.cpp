// study_mesh_repair -- the repair of defective meshes (medial3/mesh/mesh_repair.h):
// its cost and its Hausdorff distance on meshes with injected defects, against the axis
// of the valid mesh in the same run.
//
// usage: study_mesh_repair [--axis] [--max-samples N] [--defect D]... [--alpha-ratio R] MESH...
// For each mesh (valid or not as read): the row "as-read" (the mesh itself: repaired only
// when it is defective), then three injected defects:
//   hole:    the middle triangle removed (border edges; the fill step closes it);
//   spike:   the middle vertex moved through the solid to 1.5 times its distance past the
//            vertex centroid (self-intersecting triangles; wrapped);
//   overlap: a copy translated by 1/10 of the bounding box diagonal along x added (two
//            shells crossing each other; wrapped into one).
// Each row: the census of defects, the method, alpha and offset (the defaults relative to
// the diagonal: alpha = diagonal / R, R = 50, offset = diagonal / 300), the repaired
// mesh's size and shells, the CPU seconds of the repair (census, steps, exact check of
// the result) and of the two bounded-error Hausdorff distances, the distances, and the
// solid's Betti numbers; with --axis also the axis (mesh_axis.h, default options but
// --max-samples, default 2000000 as in medial3d) of the repaired mesh: its Betti numbers,
// CPU seconds and the samples of its round; the as-read row of a valid mesh is the
// baseline (the axis of the mesh itself). --defect keeps only the rows named (as-read,
// hole, spike, overlap). CPU seconds of the process (support/cpu_clock.h).
// CSV on stdout:
//   mesh,defect,triangles,self_intersecting_pairs,border_edges,non_manifold_edges,
//   non_manifold_vertices,shells,method,alpha,offset,repaired_vertices,repaired_triangles,
//   repaired_shells,repair_cpu_s,hausdorff,input_to_repaired,repaired_to_input,
//   hausdorff_error,hausdorff_cpu_s,solid_betti,axis_betti,axis_cpu_s,axis_samples,axis_rounds,
//   axis_dropped_components
// (Betti numbers b0:b1:b2; axis columns empty without --axis; axis_rounds: the rounds run;
// axis_dropped_components: components below the sampling's resolution dropped from the
// returned round by the resolution rule, mesh_axis.h step 7, 0 when it did not apply). A step that fails is a
// comment line with its message.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "run_options.h"
#include "medial3/mesh/mesh_axis.h"
#include "medial3/mesh/mesh_repair.h"
#include "medial3/mesh/mesh_solid.h"
#include "support/cpu_clock.h"
#include "io/mesh_io.h"

using namespace grassfire;

namespace {

const char* kUsage =
    "usage: study_mesh_repair [--axis] [--max-samples N] [--defect D]... [--alpha-ratio R] MESH...\n"
    "The repair of each mesh and of it with injected defects (hole, spike, overlap): census, method, CPU\n"
    "seconds, Hausdorff distances, Betti numbers; --axis builds the repaired solid's axis too. CSV on stdout.\n";

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  return name.substr(0, name.find_last_of('.'));
}

std::vector<std::pair<std::string, TriangleMesh3>> injected(const TriangleMesh3& mesh, double diagonal) {
  std::vector<std::pair<std::string, TriangleMesh3>> out{{"as-read", mesh}};
  TriangleMesh3 hole = mesh;
  hole.triangles.erase(hole.triangles.begin() + static_cast<long>(hole.triangles.size() / 2));
  out.emplace_back("hole", hole);
  TriangleMesh3 spike = mesh;
  std::array<double, 3> c{0, 0, 0};
  for (const auto& p : mesh.vertices)
    for (int i = 0; i < 3; ++i) c[i] += p[i] / static_cast<double>(mesh.vertices.size());
  auto& v = spike.vertices[spike.vertices.size() / 2];
  for (int i = 0; i < 3; ++i) v[i] = c[i] + 1.5 * (c[i] - v[i]);
  out.emplace_back("spike", spike);
  TriangleMesh3 overlap = mesh;
  const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
  for (auto p : mesh.vertices) overlap.vertices.push_back({p[0] + diagonal / 10, p[1], p[2]});
  for (const auto& t : mesh.triangles) overlap.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  overlap.vertex_origin.clear(), overlap.triangle_origin.clear();
  out.emplace_back("overlap", overlap);
  return out;
}

void study(const std::string& name, const std::string& defect, const TriangleMesh3& mesh, double alpha_ratio,
           double diagonal, bool axis, std::size_t max_samples) {
  MeshRepairOptions o;
  o.enabled = true;
  o.alpha = diagonal / alpha_ratio;
  const MeshRepair r = repair_mesh(mesh, o);
  const MeshDefects& d = r.defects;
  const SolidTopology solid = solid_topology(r.mesh);
  std::string axis_betti, axis_s, axis_samples, axis_rounds, axis_dropped;
  if (axis) {
    const double t = cpu_seconds();
    try {
      MeshAxisOptions ao;
      ao.max_samples = max_samples;
      const MeshAxis a = mesh_medial_axis(r.mesh, ao);
      axis_betti = betti_text(a.axis_betti);
      axis_samples = std::to_string(a.rounds[a.axis_round].samples);
      axis_rounds = std::to_string(a.rounds.size());
      const MeshAxisRound& accepted = a.rounds[a.axis_round];
      axis_dropped = std::to_string(accepted.resolution_rule ? accepted.unresolved_components : 0);
      axis_s = std::to_string(cpu_seconds() - t);
    } catch (const std::exception& e) {
      std::printf("# %s %s: axis: %s\n", name.c_str(), defect.c_str(), e.what());
    }
  }
  std::printf("%s,%s,%zu,%zu,%zu,%zu,%zu,%zu,%s,%.6g,%.6g,%zu,%zu,%zu,%.4f,%.6g,%.6g,%.6g,%.3g,%.4f,%s,%s,%s,%s,%s,%s\n",
              name.c_str(), defect.c_str(), d.triangles, d.self_intersecting_pairs, d.border_edges,
              d.non_manifold_edges, d.non_manifold_vertices, d.shells, r.method.c_str(), r.alpha, r.offset,
              r.mesh.vertices.size(), r.mesh.triangles.size(), r.repaired_shells, r.repair_cpu_seconds, r.hausdorff,
              r.input_to_repaired, r.repaired_to_input, r.hausdorff_error, r.hausdorff_cpu_seconds,
              betti_text(solid.betti).c_str(), axis_betti.c_str(), axis_s.c_str(), axis_samples.c_str(), axis_rounds.c_str(),
              axis_dropped.c_str());
  std::fflush(stdout);
}

int run(int argc, char** argv) {
  experiments::RunOptionSpec spec{{"--axis"}, {"--alpha-ratio", "--max-samples", "--defect"}, 1, SIZE_MAX};
  spec.shard = false;
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, spec);
  const bool axis = cmd.flag("--axis");
  const double alpha_ratio = cmd.number("--alpha-ratio", 50);
  const std::size_t max_samples = cmd.count("--max-samples", MeshAxisOptions{}.max_samples);
  const std::vector<std::string> defects = cmd.values("--defect");
  const std::vector<std::string>& meshes = cmd.positional;
  if (!(alpha_ratio > 0)) throw experiments::UsageError("--alpha-ratio must be positive");
  std::printf("mesh,defect,triangles,self_intersecting_pairs,border_edges,non_manifold_edges,non_manifold_vertices,"
              "shells,method,alpha,offset,repaired_vertices,repaired_triangles,repaired_shells,repair_cpu_s,hausdorff,"
              "input_to_repaired,repaired_to_input,hausdorff_error,hausdorff_cpu_s,solid_betti,axis_betti,axis_cpu_s,axis_samples,"
              "axis_rounds,axis_dropped_components\n");
  for (const std::string& path : meshes) {
    const TriangleMesh3 mesh = read_triangle_mesh(path);
    std::array<double, 3> lo = mesh.vertices.front(), hi = lo;
    for (const auto& p : mesh.vertices)
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    for (const auto& [defect, m] : injected(mesh, diagonal)) {
      if (!defects.empty() && std::find(defects.begin(), defects.end(), defect) == defects.end()) continue;
      try {
        study(base_name(path), defect, m, alpha_ratio, diagonal, axis, max_samples);
      } catch (const std::exception& e) {
        std::printf("# %s %s: %s\n", base_name(path).c_str(), defect.c_str(), e.what());
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return experiments::guarded_main(argc, argv, "study_mesh_repair", kUsage, run); }
