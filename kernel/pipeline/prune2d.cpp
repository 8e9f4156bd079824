// prune2d.cpp -- see prune2d.h.
#include "pipeline/prune2d.h"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/medial2_json.h"
#include "support/union_find.h"
#include "shapes/builtin_shapes.h"

namespace grassfire {

namespace {

using Json = nlohmann::ordered_json;

Json value(const Interval& x, double& bound) { return certified_json(x, bound); }

std::string pruned_json(const std::string& shape, const char* axis, const PruningThresholds& t, bool relative,
                        double size, const PrunedAxis& p, double position_error) {
  double b_off = 0, b_r = 0, b_edf = 0, b_et = 0, b_st = 0, b_len = 0;
  Json j;
  j["format"] = "grassfire-pruned2d";
  j["version"] = 1;
  j["shape"] = shape;
  j["axis"] = axis;
  j["thresholds"] = {{"et", nearest_double(t.erosion)}, {"st", nearest_double(t.tubularity)}, {"relative", relative},
                     {"size", size},                       {"topology", t.topology}};
  Json nodes = Json::array();
  for (const PrunedNode& n : p.nodes) {
    Json o{{"x", n.position.x}, {"y", n.position.y}, {"R", value(n.radius, b_r)}, {"edf", value(n.edf, b_edf)},
           {"et", value(n.erosion, b_et)}, {"st", value(n.tubularity, b_st)}};
    if (n.source_node != kCutPoint)
      o["source"] = {{"node", n.source_node}};
    else
      o["source"] = {{"edge", n.source_edge}, {"offset", value(n.offset, b_off)}};
    nodes.push_back(std::move(o));
  }
  j["nodes"] = std::move(nodes);
  Json edges = Json::array();
  for (const PrunedEdge& e : p.edges)
    edges.push_back({{"u", e.u},
                     {"v", e.v},
                     {"length", value(e.length, b_len)},
                     {"kind", to_string(e.kind)},
                     {"source_edge", e.source_edge},
                     {"from", value(e.from, b_off)},
                     {"to", value(e.to, b_off)}});
  j["edges"] = std::move(edges);
  j["error_bound"] = {{"position", position_error}, {"offset", b_off}, {"R", b_r},     {"edf", b_edf},
                      {"et", b_et},                 {"st", b_st},      {"length", b_len}};
  return j.dump(1) + "\n";
}

std::uint64_t component_count(const PrunedAxis& p) {
  UnionFind components(p.nodes.size());
  std::uint64_t count = p.nodes.size();
  for (const PrunedEdge& e : p.edges)
    if (components.find(e.u) != components.find(e.v)) {
      components.unite(e.u, e.v);
      --count;
    }
  return count;
}

}  // namespace

Prune2dRun prune2d(const Shape2& shape, const Prune2dSetup& setup) {
  if (sgn(setup.erosion) < 0 || sgn(setup.tubularity) < 0)
    throw std::invalid_argument("the ET and ST thresholds must be non-negative");
  if (setup.tubularity > 1) throw std::invalid_argument("option --st must be at most 1");
  Prune2dRun run;
  run.thresholds.erosion = setup.erosion;
  run.thresholds.tubularity = setup.tubularity;
  run.thresholds.topology = setup.topology;
  run.size = shape_dimension(shape);
  if (setup.relative) run.thresholds.erosion *= mpq_class(run.size);
  run.edf = compute_edf2d(shape, setup.options);
  run.pruned = prune_axis(*run.edf.graph, *run.edf.burning, run.thresholds);
  double position_error = 0;
  for (const MedialNode& n : run.edf.graph->nodes()) position_error = std::max(position_error, n.position_error);
  run.components = component_count(run.pruned);
  run.json = pruned_json(shape.name, setup.options.axis == AxisMethod::ExactPolygon ? "exact" : "sampled",
                         run.thresholds, setup.relative, run.size, run.pruned, position_error);
  return run;
}

}  // namespace grassfire
