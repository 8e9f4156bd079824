// burn3d_exact.cpp -- `burn3d --method exact`: the exact window-propagation engine
// (kernel/burn3/exact/, docs/exact-engine.md).
//
// The engine burns from the point sources and the border rules (Linear, DistanceToPoint,
// Never; pipeline/burn3d.h turns them off for --no-border-ignition), then reads BT at the
// vertices and at the queries as certified enclosures [lo, hi] of the exact value; each is
// returned as its midpoint with the half-width rounded up as bt_error, so that
// |bt - BT| <= bt_error holds for every finite value; when any decision is uncertified
// every bt_error is +infinity (no bound is claimed). Complexes this part of the engine
// Singular edges follow the junction rule of Definition 9 and singular points the link rule
// (docs/exact-engine.md); --singular-walls asks for the walls semantics instead (fronts stop at every
// singular edge: an upper bound of BT off the curves; the report and the summary say so).
// The report holds the propagation's counters, the events by type, one counter per
// certification stage ("uncertified" counts the wedge decisions no stage certified, each
// taken as collinear and reported, docs/design.md 3), and the kinks, merges and quench points of
// the junction rule (junction_points.h), each a point of a singular edge with BT there:
// {"x","y","z","bt","error"}, |coordinate or bt - exact| <= error (exact parameters are
// enclosed from their closed form), with the count of switch points left unclassified.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "burn3/exact/burn_outputs.h"
#include "burn3/exact/exact_burning.h"
#include "burn3/exact/junction_points.h"
#include "burn3/exact/sources.h"
#include "pipeline/burn3d_methods.h"
#include "support/cpu_clock.h"
#include "support/progress.h"

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
          {"undecided_angles", s.undecided_angles},
          {"junction_passes", s.junction_passes},
          {"uncertified_breaks", s.uncertified_breaks},
          {"uncertified_crossings", s.uncertified_crossings},
          {"uncertified_orders", s.uncertified_orders},
          {"crossing_boxes", s.crossing_boxes}};
}

// Events by type (docs/exact-engine.md): windows reaching a vertex or a singular edge, the switch
// points of the singular edges' (k-1)-th arrival by type (kinks, merges, quenches, tangent
// handovers, unclassified; junction_points.h), vertices burned by the link rule (singular points and
// curve vertices included), ends of burned stretches; then the engine's own counters:
// edge-point sources made at switches, pieces continued across a burned curve, arrivals
// that realise no piece.
nlohmann::json event_report(const PropagationStats& s, const JunctionPoints& j) {
  return {{"vertex_reached", s.vertex_events},
          {"edge_reached", s.junction_records},
          {"kinks", j.kinks.size()},
          {"merges", j.merges.size()},
          {"quenches", j.quenches.size()},
          {"tangents", j.tangents.size()},
          {"unclassified_switches", j.unclassified},
          {"link_rule_burns", s.vertex_burns},
          {"stretch_ends", s.stretch_ends},
          {"switch_sources", s.kinks},
          {"continued_pieces", s.merges},
          {"quenched_arrivals", s.quenched}};
}

// Points of singular edges with BT there: {"x","y","z","bt","error"}, |coordinate or bt -
// exact| <= error (exact parameters and times are enclosed from their closed forms).
nlohmann::json point_report(const std::vector<JunctionPoint>& points) {
  nlohmann::json r = nlohmann::json::array();
  for (const JunctionPoint& p : points)
    r.push_back({{"x", p.x[0]}, {"y", p.x[1]}, {"z", p.x[2]}, {"bt", p.bt}, {"error", p.error}});
  return r;
}

nlohmann::json certification_report(const CertificationCounts& c) {
  return {{"filter", c.filter},
          {"exact", c.exact},
          {"arb", c.arb},
          {"exact_equal", c.exact_equal},
          {"structural_equal", c.structural_equal},
          {"kept_undecided", c.kept_undecided},
          {"memo", c.memo},
          {"uncertified", c.uncertified},
          {"negligible_ties", c.negligible_ties},
          {"max_bits", c.max_bits}};
}

}  // namespace

std::function<void(double, std::uint64_t, std::uint64_t)> exact_sweep_reporter(
    const MedialComplex& mc, double largest_source_time, std::function<void(double, const std::string&)> report) {
  if (!progress_enabled()) return {};  // no lines are drawn: no events counted
  double ignition = largest_source_time, largest_r = 0;
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
    if (const std::optional<ExactSum> f = exact_vertex_ignition(mc, v)) ignition = std::max(ignition, f->to_double());
    if (std::isfinite(mc.vertex(v).radius)) largest_r = std::max(largest_r, mc.vertex(v).radius);
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], mc.vertex(v).approx[i]), hi[i] = std::max(hi[i], mc.vertex(v).approx[i]);
  }
  // On a medial axis BT >= R, and the fire from the border reaches the thickest part last;
  // otherwise a front from the last ignition crosses the complex (its bounding box diagonal).
  const double estimate =
      largest_r > ignition ? largest_r : ignition + std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return [=](double t, std::uint64_t events, std::uint64_t windows) {
    if ((events & 255) != 0) return;
    char line[160];
    std::snprintf(line, sizeof line, "t = %.4g (largest ignition %.4g, final ~%.4g), %llu events, %llu windows", t,
                  ignition, estimate, static_cast<unsigned long long>(events), static_cast<unsigned long long>(windows));
    report(estimate > 0 ? std::min(t / estimate, 0.99) : 0.0, line);
  };
}

BurnOutcome burn_by_exact(const BurnRequest& request) {
  const MedialComplex& mc = request.mc;
  const std::optional<std::string> why = exact_engine_unsupported(mc);
  if (why)
    throw std::runtime_error(request.input + ": method 'exact' cannot burn this complex: it has " + *why +
                             "; use --method discrete");
  const bool walls = request.singular_walls && mc.count(EdgeStratum::Singular) > 0;
  const auto start = std::chrono::steady_clock::now();
  ExactBurningOptions options;
  options.singular_walls = request.singular_walls;
  if (request.progress) {
    double largest_source_time = 0;
    for (const PointSource& s : request.sources) largest_source_time = std::max(largest_source_time, s.t0.get_d());
    options.on_event = exact_sweep_reporter(mc, largest_source_time, [&](double done, const std::string& detail) {
      request.progress("exact propagation", done, detail);
    });
  }
  ExactBurning eb(mc, options);
  for (std::size_t i = 0; i < request.sources.size(); ++i) {
    try {
      eb.add_point_source(request.sources[i].location, request.sources[i].t0);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(request.input + ": source " + std::to_string(i + 1) + ": " + e.what());
    }
  }
  eb.add_border_ignition();
  if (request.progress) request.progress("exact propagation", 0.0, "");
  eb.run();
  const double propagation_seconds = eb.propagation().stats().seconds;
  BurnOutcome out;
  // Every error includes the run's decision error (burn_outputs.h: decision_error): +infinity
  // after an uncertified decision, which may move BT anywhere downstream.
  const VertexBurnValues values = vertex_values(eb);
  const double decisions = decision_error(eb);
  for (const CertifiedValue& v : values.bt) {
    out.vertex_bt.push_back(v.value);
    out.vertex_bt_error.push_back(std::isfinite(v.value) ? v.error : std::numeric_limits<double>::infinity());
  }
  for (std::size_t i = 0; i < request.queries.size(); ++i) {
    const CertifiedValue v = certified_value(eb.burn_time(request.queries[i]));
    out.query_values.push_back(
        {v.value, std::isfinite(v.value) ? v.error + decisions : std::numeric_limits<double>::infinity()});
    if (request.progress && (i & 1023) == 1023)
      request.progress("queries", static_cast<double>(i + 1) / static_cast<double>(request.queries.size()), "");
  }
  double max_error = 0.0;  // over the vertices that burn (+infinity after an uncertified decision)
  for (std::size_t v = 0; v < out.vertex_bt.size(); ++v)
    if (std::isfinite(out.vertex_bt[v])) max_error = std::max(max_error, out.vertex_bt_error[v]);
  const JunctionPoints junction = junction_points(eb);
  const CertificationCounts& c = eb.certification();
  const QueryCounts& q = eb.query_counts();
  out.report = {{"seconds", wall_seconds_since(start)},
                {"propagation_seconds", propagation_seconds},
                {"propagation", propagation_report(eb.propagation().stats())},
                {"certification", certification_report(c)},
                {"uncertified", c.uncertified},
                {"query_candidates", q.candidates},
                {"query_widened", q.widened},
                {"max_vertex_bt_error", std::isfinite(max_error) ? nlohmann::json(max_error) : nlohmann::json("inf")},
                {"events", event_report(eb.propagation().stats(), junction)},
                {"kinks", point_report(junction.kinks)},
                {"merges", point_report(junction.merges)},
                {"quenches", point_report(junction.quenches)},
                {"tangents", point_report(junction.tangents)},
                {"unclassified_switches", junction.unclassified},
                {"singular_edges", walls ? "walls (not Definition 9: fronts stop at singular edges)"
                                         : mc.count(EdgeStratum::Singular) > 0 ? "junction rule (Definition 9)" : "none"}};
  std::ostringstream s;
  s << "exact: " << eb.propagation().stats().windows << " windows, " << c.uncertified << " uncertified decisions, "
    << "max vertex error " << max_error << ", " << out.report["seconds"].get<double>() << " s";
  if (walls) s << "; singular edges burned as walls, not Definition 9";
  out.summary = s.str();
  return out;
}

}  // namespace grassfire
