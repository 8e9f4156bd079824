// burn3d.cpp -- see burn3d.h.
#include "pipeline/burn3d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "burn3/point_sources.h"
#include "complex3/point_location.h"
#include "io/complex_text.h"
#include "io/json_numbers.h"
#include "support/progress.h"
#include "pipeline/complex_input.h"

namespace grassfire {

namespace {

std::string point_text(const ExactPoint3& p) {
  return "(" + decimal_or_nearest(p.x) + ", " + decimal_or_nearest(p.y) + ", " + decimal_or_nearest(p.z) + ")";
}

std::vector<CsvPoint> rows_of(const BurnPoints& points, bool with_t0) {
  return points.file ? read_point_csv(*points.file, with_t0) : points.rows;
}

// The rounding of a point's coordinates to doubles, squared: 3 (2^-52 M)^2 for the largest
// magnitude M among them and those of its nearest point (one rounding on either side).
mpq_class rounding_squared(const ExactPoint3& a, const ExactPoint3& b) {
  mpq_class m = 0;
  for (const ExactPoint3* p : {&a, &b})
    for (const mpq_class* c : {&p->x, &p->y, &p->z}) m = std::max(m, mpq_class(abs(*c)));
  const mpq_class ulp = m / mpq_class(mpz_class(1) << 52);
  return 3 * ulp * ulp;
}

// A source on the complex is located exactly; one within the rounding of its coordinates
// (a point of a mesh written as doubles elsewhere) at its nearest point, with a note of the
// distance; any other is an error naming the line and the distance.
std::vector<PointSource> locate_sources(const ComplexLocator& locator, const BurnPoints& points,
                                        std::size_t* rounded) {
  const std::string& name = points.file ? *points.file : points.name;
  std::vector<PointSource> sources;
  for (const CsvPoint& row : rows_of(points, true)) {
    ComplexPoint x = locator.locate(row.point);
    if (sgn(x.snap_squared) != 0) {
      if (x.snap_squared > rounding_squared(row.point, x.point))
        format_error(name, row.line, "source " + point_text(row.point) + " does not lie on the complex (its nearest "
                                     "point is at distance " + shortest_double(x.snap()) + ")");
      note(name + ":" + std::to_string(row.line) + ": source " + point_text(row.point) +
           " located at its nearest point of the complex, at distance " + shortest_double(x.snap()) +
           " (within the rounding of its coordinates)");
      ++*rounded;
    }
    sources.push_back({std::move(x), row.t0});
  }
  return sources;
}

nlohmann::json report(const Burn3dSetup& setup, const Burn3dRun& run) {
  const MedialComplex& mc = *run.mc;
  const std::vector<double>& bt = run.outcome.vertex_bt;
  nlohmann::json j;
  j["input"] = setup.input;
  j["method"] = setup.method;
  if (setup.method == "discrete") j["spacing"] = run.spacing;
  j["complex"] = {{"vertices", mc.vertex_count()},
                  {"edges", mc.edge_count()},
                  {"triangles", mc.triangle_count()},
                  {"segments", mc.count(EdgeStratum::Dangling)},
                  {"border_edges", mc.count(EdgeStratum::Border)},
                  {"singular_edges", mc.count(EdgeStratum::Singular)},
                  {"singular_points", mc.count(VertexKind::SingularPoint)},
                  {"sheets", mc.sheets().size()}};
  j["sources"] = run.sources.size();
  j["sources_within_rounding"] = run.rounded_sources;
  j["queries"] = run.queries.size();
  j["stats"] = run.outcome.report;
  std::size_t unburned = 0;
  double max_bt = 0, max_et = 0;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    if (!std::isfinite(bt[v])) {
      ++unburned;
      continue;
    }
    max_bt = std::max(max_bt, bt[v]);
    max_et = std::max(max_et, run.et[v]);
  }
  j["summary"] = {{"burned_vertices", mc.vertex_count() - unburned},
                  {"unburned_vertices", unburned},
                  {"max_bt", max_bt},
                  {"max_et", max_et}};
  std::vector<double> x, y, z, r;
  for (const ComplexVertex& v : mc.vertices())
    x.push_back(v.approx[0]), y.push_back(v.approx[1]), z.push_back(v.approx[2]), r.push_back(v.radius);
  j["vertex_values"] = {{"x", x}, {"y", y}, {"z", z}, {"R", r}, {"BT", finite_or_null(bt)},
                        {"ET", finite_or_null(run.et)}};
  if (!run.outcome.vertex_bt_error.empty()) j["vertex_values"]["BT_error"] = finite_or_null(run.outcome.vertex_bt_error);
  return j;
}

}  // namespace

double default_burn_spacing(const MedialComplex& mc) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  const double h = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 100;
  return h > 0 ? h : 1.0;
}

Burn3dRun burn3d(const Burn3dSetup& setup) {
  const BurnMethod method = burn_method(setup.method);
  Progress progress("burn3d", 0);
  RawComplex raw = load_complex(setup.input, setup.mesh_is_complex, "burn3d", setup.repair);
  if (setup.no_border_ignition) raw = without_border_ignition(std::move(raw));
  Burn3dRun run;
  run.mc = std::make_unique<MedialComplex>(raw);
  const MedialComplex& mc = *run.mc;
  mc.validate();
  run.spacing = setup.spacing ? *setup.spacing : default_burn_spacing(mc);
  if (!(run.spacing > 0) || !std::isfinite(run.spacing))
    throw std::invalid_argument("--spacing must be a positive number");
  const bool has_queries = setup.queries.file || !setup.queries.rows.empty();
  if (setup.sources.file || !setup.sources.rows.empty() || has_queries) {
    const ComplexLocator locator(mc);
    run.sources = locate_sources(locator, setup.sources, &run.rounded_sources);
    run.query_rows = rows_of(setup.queries, false);
    for (std::size_t i = 0; i < run.query_rows.size(); ++i) {
      run.queries.push_back(locator.locate(run.query_rows[i].point));
      if ((i & 1023) == 1023) progress.fraction("locating queries", static_cast<double>(i + 1) / run.query_rows.size());
    }
  }
  BurnRequest request{mc, std::move(run.sources), std::move(run.queries), run.spacing, setup.max_points,
                      [&](const std::string& stage, double done, const std::string& detail) { progress.fraction(stage, done, detail); }, setup.input,
                      setup.singular_walls};
  run.outcome = method(request);
  progress.done();
  run.sources = std::move(request.sources);
  run.queries = std::move(request.queries);
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
    run.et.push_back(run.outcome.vertex_bt[v] - mc.vertex(v).radius);
  run.report = report(setup, run);
  return run;
}

}  // namespace grassfire
