// mesh_repair.cpp -- see mesh_repair.h (the census, the order of the steps, the reports;
// the CGAL calls are in mesh_repair_cgal.cpp).
#include "medial3/mesh/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "medial3/mesh/mesh_checks.h"
#include "medial3/mesh/mesh_embedding.h"
#include "medial3/mesh/mesh_solid.h"
#include "support/number_text.h"
#include "support/cpu_clock.h"
#include "geometry3/mesh_weld.h"

namespace grassfire {

namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

std::size_t count_duplicate_vertices(const TriangleMesh3& mesh) {
  std::vector<std::array<double, 3>> p = mesh.vertices;
  std::sort(p.begin(), p.end());
  std::size_t n = 0;
  for (std::size_t i = 1; i < p.size(); ++i) n += p[i] == p[i - 1];
  return n;
}

// Edges by their triangles: border, non-manifold, inconsistent; and shells, joining the
// triangles on each edge.
void count_edges_and_shells(const TriangleMesh3& mesh, MeshDefects& d) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;  // (min, max) -> signed uses
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(2 * t + (a < b));
    }
  UnionFind shells(mesh.triangles.size());
  std::size_t components = mesh.triangles.size();
  for (const auto& [e, uses] : edges) {
    if (uses.size() == 1) ++d.border_edges;
    if (uses.size() > 2) ++d.non_manifold_edges;
    if (uses.size() == 2 && (uses[0] & 1) == (uses[1] & 1)) ++d.inconsistent_edges;
    for (std::size_t i = 1; i < uses.size(); ++i) components -= shells.unite(uses[0] / 2, uses[i] / 2);
  }
  d.shells = components;
}

// A vertex is non-manifold when the link edges (b, c) of its triangles (v, b, c), taken
// undirected, form more than one connected graph.
std::size_t count_non_manifold_vertices(const TriangleMesh3& mesh) {
  std::vector<std::vector<std::array<std::uint32_t, 2>>> link(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  std::size_t n = 0;
  for (const auto& edges : link) {
    if (edges.empty()) continue;
    std::map<std::uint32_t, std::uint32_t> index;
    for (const auto& e : edges)
      for (std::uint32_t u : e) index.emplace(u, static_cast<std::uint32_t>(index.size()));
    UnionFind uf(index.size());
    std::size_t components = index.size();
    for (const auto& e : edges) components -= uf.unite(index[e[0]], index[e[1]]);
    n += components > 1;
  }
  return n;
}

std::string count_text(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}


double bounding_diagonal(const TriangleMesh3& mesh) {
  std::array<double, 3> lo = mesh.vertices.front(), hi = lo;
  for (const auto& p : mesh.vertices)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

std::string closed_manifold_refusal(const TriangleMesh3& mesh) {
  try {
    require_closed_manifold(mesh);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Step 1: the readers' weld (geometry3/mesh_weld.h) on a copy with its own numbering kept.
TriangleMesh3 welded(const TriangleMesh3& mesh) {
  TriangleMesh3 w = mesh;
  if (w.triangle_origin.empty()) {
    w.triangle_origin.resize(w.triangles.size());
    std::iota(w.triangle_origin.begin(), w.triangle_origin.end(), 0u);
  }
  weld_and_drop(w);
  return w;
}

// The outer shells of a closed mesh (depth 0, mesh_solid.h) with their vertices renumbered;
// `dropped` counts the others. The alpha wrap is the boundary of the region flooded from
// infinity, which has no cavity; CGAL 5.5's manifold fix (relabelling cells around
// non-manifold vertices) can leave a tiny enclosed shell (4 triangles on joint.off with a
// shifted copy), which this removes: filling it only adds volume, so the wrap still
// contains the input.
TriangleMesh3 outer_shells(const TriangleMesh3& mesh, std::size_t& dropped) {
  const SolidTopology solid = solid_topology(mesh);
  TriangleMesh3 out;
  out.source = mesh.source;
  std::vector<std::uint32_t> index(mesh.vertices.size(), static_cast<std::uint32_t>(-1));
  dropped = 0;
  for (const MeshShell& shell : solid.shells) {
    if (shell.depth != 0) {
      ++dropped;
      continue;
    }
    for (std::uint32_t t : shell.triangles) {
      std::array<std::uint32_t, 3> tri;
      for (int k = 0; k < 3; ++k) {
        std::uint32_t& v = index[mesh.triangles[t][k]];
        if (v == static_cast<std::uint32_t>(-1)) {
          v = static_cast<std::uint32_t>(out.vertices.size());
          out.vertices.push_back(mesh.vertices[mesh.triangles[t][k]]);
        }
        tri[k] = v;
      }
      out.triangles.push_back(tri);
    }
  }
  return out;
}

}  // namespace

MeshDefects mesh_defects(const TriangleMesh3& mesh) {
  MeshDefects d;
  d.vertices = mesh.vertices.size();
  d.triangles = mesh.triangles.size();
  d.duplicate_vertices = count_duplicate_vertices(mesh);
  std::vector<bool> positive(mesh.triangles.size(), true);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (has_zero_area(mesh, t)) positive[t] = false, ++d.zero_area_triangles;
  count_edges_and_shells(mesh, d);
  d.non_manifold_vertices = count_non_manifold_vertices(mesh);
  d.self_intersecting_pairs = count_crossings(mesh, positive);
  d.refusal = closed_manifold_refusal(mesh);
  return d;
}

std::string describe_defects(const MeshDefects& d) {
  std::string s;
  const auto add = [&](std::size_t n, const std::string& one, const std::string& many) {
    if (n) s += (s.empty() ? "" : ", ") + count_text(n, one, many);
  };
  add(d.duplicate_vertices, "duplicate vertex", "duplicate vertices");
  add(d.zero_area_triangles, "zero-area triangle", "zero-area triangles");
  add(d.border_edges, "border edge", "border edges");
  add(d.non_manifold_edges, "non-manifold edge", "non-manifold edges");
  add(d.inconsistent_edges, "inconsistently oriented edge", "inconsistently oriented edges");
  add(d.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices");
  add(d.self_intersecting_pairs, "self-intersecting pair", "self-intersecting pairs");
  if (d.shells > 1) add(d.shells, "shell", "shells");
  return s.empty() ? "none" : s;
}

void require_solid(const TriangleMesh3& mesh) {
  if (closed_manifold_refusal(mesh).empty()) return;
  const MeshDefects d = mesh_defects(mesh);
  throw std::invalid_argument(d.refusal + " [found: " + describe_defects(d) +
                              "]; --repair builds the axis of a closed embedded solid made from it (holes filled, "
                              "or an alpha wrap) and reports the Hausdorff distance to it");
}

MeshRepairOptions mesh_repair_options(bool repair, std::optional<double> alpha, std::optional<double> offset) {
  if ((alpha || offset) && !repair) throw std::invalid_argument("--repair-alpha and --repair-offset need --repair");
  if (alpha && !(*alpha > 0 && std::isfinite(*alpha))) throw std::invalid_argument("--repair-alpha must be a positive number");
  if (offset && !(*offset > 0 && std::isfinite(*offset)))
    throw std::invalid_argument("--repair-offset must be a positive number");
  MeshRepairOptions r;
  r.enabled = repair;
  r.alpha = alpha.value_or(0);
  r.offset = offset.value_or(0);
  return r;
}

MeshRepair repair_mesh(const TriangleMesh3& mesh, const MeshRepairOptions& options) {
  const double start = cpu_seconds();
  if (mesh.vertices.empty() || mesh.triangles.empty()) throw std::invalid_argument(mesh.source + ": the mesh is empty");
  MeshRepair r;
  r.defects = mesh_defects(mesh);
  r.mesh = mesh;
  r.diagonal = bounding_diagonal(mesh);
  if (r.defects.any()) {
    const TriangleMesh3 w = welded(mesh);
    const bool weld_changed = w.vertices.size() != mesh.vertices.size() || w.triangles.size() != mesh.triangles.size();
    const MeshDefects wd = weld_changed ? mesh_defects(w) : r.defects;
    TriangleMesh3 filled;
    if (weld_changed && !wd.any()) {
      r.method = "weld", r.mesh = w;
    } else if (options.allow_fill && wd.self_intersecting_pairs == 0 && wd.non_manifold_edges == 0 &&
               wd.non_manifold_vertices == 0 && wd.zero_area_triangles == 0 && wd.duplicate_vertices == 0 &&
               fill_holes(w, filled, r.filled_holes) && closed_manifold_refusal(filled).empty()) {
      r.method = "fill", r.mesh = std::move(filled);
      r.added_triangles = r.mesh.triangles.size() - w.triangles.size();
    } else {
      r.alpha = options.alpha > 0 ? options.alpha : r.diagonal / 50;
      r.offset = options.offset > 0 ? options.offset : r.diagonal / 300;
      r.method = "alpha_wrap", r.mesh = alpha_wrap(w, r.alpha, r.offset);
      if (const std::string why = closed_manifold_refusal(r.mesh); !why.empty())
        throw std::invalid_argument(mesh.source + ": the alpha wrap is not a closed embedded manifold (" + why + ")");
      r.mesh = outer_shells(r.mesh, r.dropped_cavities);
    }
  }
  MeshDefects repaired;
  count_edges_and_shells(r.mesh, repaired);
  r.repaired_shells = repaired.shells;
  r.repair_cpu_seconds = cpu_seconds() - start;
  if (r.method != "none") {
    const double h = cpu_seconds();
    r.hausdorff_error = options.hausdorff_error > 0 ? options.hausdorff_error : r.diagonal * 1e-4;
    r.input_to_repaired = hausdorff_distance(mesh, r.mesh, r.hausdorff_error);
    r.repaired_to_input = hausdorff_distance(r.mesh, mesh, r.hausdorff_error);
    r.hausdorff = std::max(r.input_to_repaired, r.repaired_to_input);
    r.hausdorff_cpu_seconds = cpu_seconds() - h;
  }
  return r;
}

nlohmann::json mesh_repair_json(const MeshRepair& r) {
  const MeshDefects& d = r.defects;
  return {{"method", r.method},
          {"defects",
           {{"vertices", d.vertices},
            {"triangles", d.triangles},
            {"duplicate_vertices", d.duplicate_vertices},
            {"zero_area_triangles", d.zero_area_triangles},
            {"border_edges", d.border_edges},
            {"non_manifold_edges", d.non_manifold_edges},
            {"inconsistent_edges", d.inconsistent_edges},
            {"non_manifold_vertices", d.non_manifold_vertices},
            {"self_intersecting_pairs", d.self_intersecting_pairs},
            {"shells", d.shells},
            {"first_problem", d.refusal}}},
          {"diagonal", r.diagonal},
          {"alpha", r.alpha},
          {"offset", r.offset},
          {"filled_holes", r.filled_holes},
          {"added_triangles", r.added_triangles},
          {"dropped_cavities", r.dropped_cavities},
          {"vertices", r.mesh.vertices.size()},
          {"triangles", r.mesh.triangles.size()},
          {"shells", r.repaired_shells},
          {"hausdorff",
           {{"distance", r.hausdorff},
            {"input_to_repaired", r.input_to_repaired},
            {"repaired_to_input", r.repaired_to_input},
            {"error_bound", r.hausdorff_error},
            {"method", "CGAL PMP bounded_error_Hausdorff_distance, both ways (input triangles, zero-area ones left out, and the repaired surface)"}}},
          {"repair_cpu_seconds", r.repair_cpu_seconds},
          {"hausdorff_cpu_seconds", r.hausdorff_cpu_seconds}};
}

std::string describe_repair(const MeshRepair& r) {
  if (r.method == "none") return "nothing to repair (the mesh bounds a solid)";
  std::string s = "repaired by " + r.method;
  if (r.method == "alpha_wrap")
    s += " (alpha " + shortest_double(r.alpha) + ", offset " + shortest_double(r.offset) +
         (r.dropped_cavities ? ", " + count_text(r.dropped_cavities, "spurious cavity", "spurious cavities") + " filled" : "") + ")";
  if (r.method == "fill") s += " (" + count_text(r.filled_holes, "hole", "holes") + ", " + count_text(r.added_triangles, "triangle", "triangles") + " added)";
  return s + " of " + describe_defects(r.defects) + "; " + count_text(r.mesh.vertices.size(), "vertex", "vertices") +
         ", " + count_text(r.mesh.triangles.size(), "triangle", "triangles") + ", " + count_text(r.repaired_shells, "shell", "shells") +
         "; Hausdorff distance " + shortest_double(r.hausdorff) + " (input to repaired " + shortest_double(r.input_to_repaired) +
         ", repaired to input " + shortest_double(r.repaired_to_input) + "; each within " + shortest_double(r.hausdorff_error) + ")";
}

}  // namespace grassfire
