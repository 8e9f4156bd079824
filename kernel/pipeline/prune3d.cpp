// prune3d.cpp -- see prune3d.h.
#include "pipeline/prune3d.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "io/curves_export.h"
#include "io/json_numbers.h"
#include "support/progress.h"

namespace grassfire {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

AxisValues3 axis_values(const FieldRun& run) {
  const MedialComplex& mc = *run.complex;
  AxisValues3 v;
  // BT >= 0 (every ignition time is >= 0): a midpoint of an enclosure below 0 is raised to
  // 0, which stays within its error bound and keeps a border igniting at 0 exactly at 0.
  auto at_least_zero = [](double bt) { return bt < 0 ? 0.0 : bt; };
  for (std::uint32_t i = 0; i < mc.vertex_count(); ++i)
    v.vertex_bt.push_back(at_least_zero(run.field->vertex_burn_time(i)));
  // Inside one sheet (interior and border vertices) BT is continuous (Prop. 4), so t's side
  // time at a corner is the point time, which is used there: the two are the same number,
  // though the exact engine encloses them separately. At singular vertices they differ.
  for (std::uint32_t t = 0; t < mc.triangle_count(); ++t) {
    std::array<double, 3> corner{};
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t c = mc.triangle(t).v[i];
      const VertexKind kind = mc.vertex(c).kind;
      corner[i] = kind == VertexKind::Interior || kind == VertexKind::Border
                      ? v.vertex_bt[c]
                      : at_least_zero(run.field->sample_in_triangle(t, mc.vertex(c).approx).bt);
    }
    v.corner_bt.push_back(corner);
  }
  v.vertex_bt_error = run.vertex_bt_error;
  return v;
}

nlohmann::json betti_json(const BettiNumbers& b) { return {b.b0, b.b1, b.b2}; }

const char* on_name(PrunedVertex3::On on) {
  return on == PrunedVertex3::On::Vertex ? "vertex" : on == PrunedVertex3::On::Edge ? "edge" : "triangle";
}

nlohmann::json report(const Prune3dSetup& setup, const Prune3dRun& run, double max_r, double burning_seconds) {
  const MedialComplex& mc = *run.field.complex;
  const PrunedAxis3& p = run.pruned;
  const Pruning3Stats& s = p.stats;
  const MedialComplex& out = *run.pruned_complex;
  nlohmann::json j;
  j["format"] = "grassfire-pruned3d";
  j["version"] = 1;
  j["input"] = setup.field.input;
  j["method"] = setup.field.method;
  j["spacing"] = run.field.spacing;
  j["thresholds"] = {{"et", run.thresholds.erosion ? nlohmann::json(run.thresholds.erosion->get_d()) : nlohmann::json()},
                     {"st", run.thresholds.tubularity ? nlohmann::json(run.thresholds.tubularity->get_d()) : nlohmann::json()},
                     {"relative", setup.relative},
                     {"max_R", max_r}};
  j["axis"] = {{"vertices", mc.vertex_count()},
               {"edges", mc.edge_count()},
               {"triangles", mc.triangle_count()},
               {"segments", mc.count(EdgeStratum::Dangling)},
               {"betti", betti_json(p.betti_axis)}};
  j["refined"] = {{"vertices", s.refined_vertices},         {"edges", s.refined_edges},
                  {"triangles", s.refined_triangles},       {"cut_points", s.cut_points},
                  {"failing_vertices", s.failing_vertices}, {"failing_edges", s.failing_edges},
                  {"failing_triangles", s.failing_triangles}};
  j["removed"] = {{"vertices", s.removed_vertices}, {"edges", s.removed_edges}, {"triangles", s.removed_triangles}};
  j["pruned"] = {{"vertices", out.vertex_count()},
                 {"edges", out.edge_count()},
                 {"triangles", out.triangle_count()},
                 {"segments", out.count(EdgeStratum::Dangling)},
                 {"betti", betti_json(p.betti_pruned)},
                 {"kept_failing",
                  {{"vertices", s.kept_failing_vertices}, {"edges", s.kept_failing_edges}, {"triangles", s.kept_failing_triangles}}}};
  j["uncertified"] = run.field.vertex_bt_error.empty() ? nlohmann::json() : nlohmann::json(s.uncertified);
  j["seconds"] = {{"burning", burning_seconds}, {"pruning", s.seconds}};
  nlohmann::json x = nlohmann::json::array(), y = x, z = x, r = x, bt = x, et = x, on = x, cell = x;
  for (std::uint32_t v = 0; v < out.vertex_count(); ++v) {
    const Vec3d& a = out.vertex(v).approx;
    const PrunedVertex3& pv = p.vertices[v];
    x.push_back(a[0]), y.push_back(a[1]), z.push_back(a[2]), r.push_back(pv.radius);
    bt.push_back(finite_or_null(pv.bt)), et.push_back(finite_or_null(pv.bt - pv.radius));
    on.push_back(on_name(pv.on)), cell.push_back(pv.cell);
  }
  j["vertex_values"] = {{"x", x}, {"y", y}, {"z", z}, {"R", r}, {"BT", bt}, {"ET", et}, {"on", on}, {"cell", cell}};
  j["triangles"] = p.complex.triangles;
  j["segments"] = p.complex.segments;
  return j;
}

}  // namespace

Prune3dSetup default_prune3d_setup() {
  Prune3dSetup s;
  s.field.method = "exact";
  s.field.command = "prune3d";
  return s;
}

Prune3dRun prune3d(const Prune3dSetup& setup) {
  if (!setup.erosion && !setup.tubularity) throw std::invalid_argument("give an ET threshold (--et), an ST threshold (--st) or both");
  if (setup.erosion && sgn(*setup.erosion) < 0) throw std::invalid_argument("the ET threshold must be >= 0");
  if (setup.tubularity && (sgn(*setup.tubularity) < 0 || *setup.tubularity > 1))
    throw std::invalid_argument("the ST threshold must be in [0, 1]");
  const auto start = std::chrono::steady_clock::now();
  Prune3dRun run;
  run.field = load_burning_field(setup.field);
  const AxisValues3 values = axis_values(run.field);
  const double burning_seconds = seconds_since(start);
  const MedialComplex& mc = *run.field.complex;
  double max_r = 0;
  for (const ComplexVertex& v : mc.vertices()) max_r = std::max(max_r, v.radius);
  Progress progress("prune3d " + setup.field.input, 0);
  progress.stage("pruning");
  run.thresholds.tubularity = setup.tubularity;
  if (setup.erosion) run.thresholds.erosion = setup.relative ? *setup.erosion * mpq_class(max_r) : *setup.erosion;
  run.pruned = prune_axis3(mc, values, run.thresholds);
  run.pruned_complex = std::make_unique<MedialComplex>(run.pruned.complex);
  run.pruned_complex->validate();
  run.report = report(setup, run, max_r, burning_seconds);
  return run;
}

}  // namespace grassfire
