// burn3d_exact.cpp -- `burn3d --method exact`: the exact window-propagation engine
// (kernel/burn3/exact/, issue 8).
//
// The engine burns from the point sources and the border rules (Linear, DistanceToPoint,
// Never; pipeline/burn3d.h turns them off for --no-border-ignition), then reads BT at the
// vertices and at the queries as certified enclosures [lo, hi] of the exact value; each is
// returned as its midpoint with the half-width rounded up as bt_error, so that
// |bt - BT| <= bt_error holds for every finite value. Complexes this part of the engine
// cannot burn by Definition 9 (singular edges, singular points without segments) are
// refused with a message naming the input's count (exact_engine_unsupported), before any
// burning, unless the request asks for singular walls (part 1's semantics: fronts stop at
// every singular edge; the report and the summary say that this is not Definition 9). The report holds the propagation's counters and one counter per certification
// stage; "uncertified" counts the wedge decisions no stage certified (each taken as
// collinear and reported, DESIGN.md 3).
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "burn3/exact/burn_outputs.h"
#include "burn3/exact/exact_burning.h"
#include "pipeline/burn3d_methods.h"

namespace grassfire {

namespace {

nlohmann::json propagation_report(const PropagationStats& s) {
  return {{"windows", s.windows},
          {"processed", s.processed},
          {"filtered", s.filtered},
          {"split_pruned", s.split_pruned},
          {"evicted", s.evicted},
          {"pseudo_sources", s.pseudo_sources},
          {"ties_absorbed", s.ties_absorbed},
          {"vertex_events", s.vertex_events},
          {"wall_arrivals", s.wall_arrivals},
          {"vertex_burns", s.vertex_burns},
          {"segment_arrivals", s.segment_arrivals},
          {"border_arrivals", s.border_arrivals},
          {"undecided_angles", s.undecided_angles}};
}

nlohmann::json certification_report(const CertificationCounts& c) {
  return {{"filter", c.filter},
          {"exact", c.exact},
          {"arb", c.arb},
          {"exact_equal", c.exact_equal},
          {"structural_equal", c.structural_equal},
          {"kept_undecided", c.kept_undecided},
          {"uncertified", c.uncertified},
          {"max_bits", c.max_bits}};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

BurnOutcome burn_by_exact(const BurnRequest& request) {
  const MedialComplex& mc = request.mc;
  const std::optional<std::string> why = exact_engine_unsupported(mc);
  if (why && !request.singular_walls)
    throw std::runtime_error(request.input + ": method 'exact' cannot burn this complex yet: it has " + *why +
                             "; use --method discrete, or --singular-walls for fronts that stop at singular edges");
  const auto start = std::chrono::steady_clock::now();
  ExactBurning eb(mc);
  for (std::size_t i = 0; i < request.sources.size(); ++i) {
    try {
      eb.add_point_source(request.sources[i].location, request.sources[i].t0);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(request.input + ": source " + std::to_string(i + 1) + ": " + e.what());
    }
  }
  eb.add_border_ignition();
  if (request.progress) request.progress("exact propagation", 0.0);
  eb.run();
  const double propagation_seconds = eb.propagation().stats().seconds;
  BurnOutcome out;
  const VertexBurnValues values = vertex_values(eb);
  for (const CertifiedValue& v : values.bt) {
    out.vertex_bt.push_back(v.value);
    out.vertex_bt_error.push_back(std::isfinite(v.value) ? v.error : std::numeric_limits<double>::infinity());
  }
  for (std::size_t i = 0; i < request.queries.size(); ++i) {
    const CertifiedValue v = certified_value(eb.burn_time(request.queries[i]));
    out.query_values.push_back({v.value, std::isfinite(v.value) ? v.error : std::numeric_limits<double>::infinity()});
    if (request.progress && (i & 1023) == 1023)
      request.progress("queries", static_cast<double>(i + 1) / static_cast<double>(request.queries.size()));
  }
  double max_error = 0.0;
  for (double e : out.vertex_bt_error)
    if (std::isfinite(e)) max_error = std::max(max_error, e);
  const CertificationCounts& c = eb.certification();
  const QueryCounts& q = eb.query_counts();
  out.report = {{"seconds", seconds_since(start)},
                {"propagation_seconds", propagation_seconds},
                {"propagation", propagation_report(eb.propagation().stats())},
                {"certification", certification_report(c)},
                {"uncertified", c.uncertified},
                {"query_candidates", q.candidates},
                {"query_widened", q.widened},
                {"max_vertex_bt_error", max_error},
                {"singular_edges", why ? "walls (not Definition 9: fronts stop at singular edges)" : "none"}};
  std::ostringstream s;
  s << "exact: " << eb.propagation().stats().windows << " windows, " << c.uncertified << " uncertified decisions, "
    << "max vertex error " << max_error << ", " << out.report["seconds"].get<double>() << " s";
  if (why) s << "; singular edges burned as walls, not Definition 9";
  out.summary = s.str();
  return out;
}

}  // namespace grassfire
