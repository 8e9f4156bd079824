// check_curves3d.cpp -- 5.1.2: the medial curves (curves3/medial_curves.h) have the b0 and b1
// of the medial axis, on synthetic, generated and real complexes.
//
// Independent reference: the Betti numbers of the axis by GF(2) simplicial homology of its
// triangles, segments and vertices (complex3/simplicial_homology.h), against the curve
// graph's, recounted from its edge list by another construction than the engine's
// (recount_graph_betti: breadth-first search and the GF(2) cycle space, where the engine
// uses a union-find and Euler's formula); the engine's stored count must equal the recount.
// Tolerance: exact (integers). Mutants: "curves-drop-edge": the engine's curve graph loses
// one of its joining edges (a "join", else any edge) before the comparison; removing an
// edge of a graph always changes b0 or b1, so every row with an edge must fail under it.
// "curves-betti-euler-only": the engine's count of b1 leaves out b0 (b1 = E - V), off by b0
// >= 1 on every instance.
#include <algorithm>
#include <cmath>
#include <dirent.h>
#include <queue>
#include <random>

#include "burn3/discrete/discrete_burning_field.h"
#include "curves3/medial_curves.h"
#include "check_registry.h"
#include "medial3/convex/convex_polyhedron_axis.h"
#include "pipeline/medial_axis_input.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"
#include "complex3/simplicial_homology.h"

namespace grassfire::checks {
namespace {

struct Named {
  std::string name;
  RawComplex raw;
};

// The curve graph's Betti numbers by another construction than the engine's (which unites
// the ends of every edge in a union-find, counts the roots as b0 and takes b1 = E - V + b0
// by the Euler characteristic): b0 by breadth-first search over adjacency lists, b1 as the
// dimension of the cycle space, the columns of the GF(2) boundary matrix d1 (an edge's
// column holds its two ends; a loop's is zero) that the pivot reduction of
// complex3/simplicial_homology.h takes to zero. Neither Euler's formula nor a union-find.
BettiNumbers recount_graph_betti(std::size_t nodes, const std::vector<CurveEdge>& edges) {
  std::vector<std::vector<std::uint32_t>> adjacent(nodes), columns;
  for (const CurveEdge& e : edges) {
    adjacent[e.u].push_back(e.v);
    adjacent[e.v].push_back(e.u);
    if (e.u == e.v) columns.emplace_back();
    else columns.push_back({std::min(e.u, e.v), std::max(e.u, e.v)});
  }
  BettiNumbers b;
  std::vector<bool> seen(nodes, false);
  for (std::uint32_t start = 0; start < nodes; ++start) {
    if (seen[start]) continue;
    ++b.b0;
    std::queue<std::uint32_t> todo;
    todo.push(start);
    seen[start] = true;
    while (!todo.empty()) {
      const std::uint32_t v = todo.front();
      todo.pop();
      for (const std::uint32_t w : adjacent[v])
        if (!seen[w]) seen[w] = true, todo.push(w);
    }
  }
  b.b1 = static_cast<long>(gf2_zero_columns(std::move(columns)).size());
  return b;
}

std::vector<std::pair<std::string, std::vector<Named>>> corpora(const CheckContext& ctx) {
  std::vector<Named> syn, gen, real;
  for (const char* n : {"board-fin", "y-junction", "book:3", "tetrahedron", "tetrahedron-flap", "double-cone", "tube",
                        "annulus", "torus", "box:4:3:1"})
    syn.push_back({n, synthetic_complex(n)});
  if (ctx.tiny()) return {{"synthetic", std::move(syn)}};
  if (!ctx.quick())
    for (const char* n : {"board-cylinder", "book:2", "book:4", "book:5", "octahedron"}) syn.push_back({n, synthetic_complex(n)});
  std::mt19937 rng(512);
  for (int i = 0; i < (ctx.quick() ? 2 : 8); ++i) {
    std::uniform_int_distribution<int> pages(2, 5), width(1, 4), dim(1, 5);
    BookOptions o;
    o.pages = pages(rng);
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(width(rng));
    o.cells_per_unit = 1;
    gen.push_back({"random book " + std::to_string(i), book(o)});
    long d[3] = {dim(rng), dim(rng), dim(rng)};
    std::sort(d, d + 3, std::greater<long>());
    if (d[1] == d[2]) ++d[0], ++d[1];
    gen.push_back({"random box " + std::to_string(i), box_medial_axis(d[0], d[1], d[2], 1)});
  }
  if (DIR* dir = opendir((ctx.data_dir + "/ma").c_str())) {
    std::vector<std::string> files;
    while (dirent* e = readdir(dir)) {
      const std::string f = e->d_name;
      if (f.size() > 3 && f.substr(f.size() - 3) == ".ma") files.push_back(f);
    }
    closedir(dir);
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) real.push_back({f, read_ma(ctx.data_dir + "/ma/" + f)});
  }
  for (const char* mesh : {"cube.off", "tripod.off", "cross.off"})
    real.push_back({mesh, build_medial_axis(ctx.data_dir + "/meshes/" + mesh, MedialInputKind::Auto).complex});
  real.push_back({"caffeine.cin", build_medial_axis(ctx.data_dir + "/balls/caffeine.cin", MedialInputKind::Auto).complex});
  return {{"synthetic", std::move(syn)}, {"generated (seeded)", std::move(gen)}, {"real (data/)", std::move(real)}};
}

double diagonal(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

std::vector<CheckRow> check_curves3d(const CheckContext& ctx) {
  std::vector<CheckRow> rows;
  for (const auto& [corpus, instances] : corpora(ctx)) {
    Tally t;
    std::uint64_t punctures = 0, walls = 0;
    std::string failed;
    for (const Named& in : instances) {
      const MedialComplex mc(in.raw);
      mc.validate();
      const double h = std::max(diagonal(mc), 1.0) / (ctx.quick() ? 24 : 48);
      const DiscreteBurning d = burn_discrete(mc, {h});
      const DiscreteBurningField field(mc, d);
      MedialCurves c = medial_curves(field);
      if (ctx.mutated("curves-betti-euler-only"))  // the engine's count without its components term
        c.curve_betti.b1 = static_cast<long>(c.edges.size()) - static_cast<long>(c.nodes.size());
      if (ctx.mutated("curves-drop-edge") && !c.edges.empty()) {
        const auto join = std::find_if(c.edges.begin(), c.edges.end(), [](const CurveEdge& e) { return !e.raw_end; });
        c.edges.erase(join != c.edges.end() ? join : c.edges.begin());
      }
      const BettiNumbers axis = complex_betti(mc), curves = recount_graph_betti(c.nodes.size(), c.edges);
      ++t.instances;
      t.points += c.nodes.size();
      punctures += c.stats.punctures;
      walls += c.stats.walls_opened;
      // The proposition on the recount, and the engine's own count against the recount.
      const BettiNumbers& stored = c.curve_betti;
      if (c.stats.residual_triangles != 0 || axis.b0 != curves.b0 || axis.b1 != curves.b1 || stored.b0 != curves.b0 ||
          stored.b1 != curves.b1) {
        ++t.violations;
        t.worst = std::max({t.worst, static_cast<double>(std::abs(axis.b0 - curves.b0) + std::abs(axis.b1 - curves.b1)),
                            static_cast<double>(std::abs(stored.b0 - curves.b0) + std::abs(stored.b1 - curves.b1))});
        failed += " " + in.name;
      }
    }
    CheckRow r;
    r.proposition = "5.1.2: medial curves have the axis' b0 and b1";
    r.corpus = corpus;
    r.reference =
        "GF(2) simplicial homology of the axis; the curve graph's (and the engine's stored) Betti numbers against a "
        "recount by breadth-first search (b0) and the GF(2) cycle space of the edges (b1)";
    r.tolerance = "exact (integers)";
    r.instances = t.instances;
    r.points = t.points;
    r.worst_violation = t.worst;
    r.unit = "count";
    r.verdict = verdict_of(t);
    r.note = std::to_string(punctures) + " punctures (axis b2), " + std::to_string(walls) + " walls opened; h = diagonal / " +
             (ctx.quick() ? "24" : "48") + (failed.empty() ? "" : "; failed:" + failed);
    rows.push_back(r);
  }
  return rows;
}

GF_REGISTER_CHECK("curves3d", check_curves3d,
                  (MutantList{{"curves-drop-edge", "one joining edge removed from the engine's curve graph"},
                              {"curves-betti-euler-only", "the engine's graph b1 counted as E - V (its b0 term left out)"}}));

}  // namespace
}  // namespace grassfire::checks
